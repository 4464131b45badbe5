#include "gearloss/units/ranges.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "gearloss/units/units.hpp"

namespace gearloss::units {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// One part of a range: its number, the number as written, and the unit after it.
struct Part {
    double value = 0.0;
    std::string_view number;
    std::string_view unit;
};

std::optional<Part> read_part(std::string_view text) {
    const std::string_view s = trim(text);
    std::size_t b = 0;
    if (b < s.size() && s[b] == '+') ++b;
    Part p;
    const auto [ptr, ec] = std::from_chars(s.data() + b, s.data() + s.size(), p.value);
    if (ec != std::errc() || ptr == s.data() + b) return std::nullopt;
    const auto end = static_cast<std::size_t>(ptr - s.data());
    p.number = s.substr(0, end);
    p.unit = trim(s.substr(end));
    return p;
}

std::optional<std::array<Part, 3>> read_parts(std::string_view item) {
    std::array<Part, 3> parts;
    std::size_t start = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t colon = item.find(':', start);
        if ((k < 2) != (colon != std::string_view::npos)) return std::nullopt;  // exactly two ':'
        const auto part = read_part(item.substr(start, k < 2 ? colon - start : std::string_view::npos));
        if (!part) return std::nullopt;
        parts[k] = *part;
        start = colon + 1;
    }
    return parts;
}

// The decimals a number was written with: "12.50" 2, "1.5e-3" 4, "1e3" 0 (at most 17).
int decimals(std::string_view number) {
    const std::size_t e = number.find_first_of("eE");
    const std::string_view mantissa = number.substr(0, e);
    const std::size_t dot = mantissa.find('.');
    int d = dot == std::string_view::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
    if (e != std::string_view::npos) {
        int exponent = 0;
        std::string_view x = number.substr(e + 1);
        if (!x.empty() && x.front() == '+') x.remove_prefix(1);
        std::from_chars(x.data(), x.data() + x.size(), exponent);
        d = exponent > 17 ? 0 : d - exponent;
    }
    return std::clamp(d, 0, 17);
}


bool same_unit(std::string_view a, std::string_view b) {
    if (a == b) return true;
    try {
        const UnitFactor fa = parse_unit(a), fb = parse_unit(b);
        return fa.scale == fb.scale && fa.offset == fb.offset && fa.dim == fb.dim && fa.affine == fb.affine;
    } catch (const UnitError&) {
        return false;  // the unit itself is reported when an item is read
    }
}

}  // namespace

bool is_range(std::string_view item) { return read_parts(item).has_value(); }

std::string range_unit(std::string_view item) {
    const auto parts = read_parts(item);
    return parts ? std::string((*parts)[2].unit) : std::string();
}

std::vector<std::string> expand_range(std::string_view item, std::string_view default_unit, std::size_t max_items) {
    const std::string what = "'" + message_excerpt(trim(item)) + "'";
    const auto parts = read_parts(item);
    if (!parts)
        throw UnitError(what + " is not a range: write START:STOP:STEP, three numbers and a unit, e.g. '300:3000:100rpm'");
    const auto& [start, stop, step] = *parts;
    // The unit on STEP alone (it applies to all three), or the same unit on every part.
    std::string_view unit = step.unit;
    if (!start.unit.empty() || !stop.unit.empty()) {
        if (start.unit.empty() || stop.unit.empty() || step.unit.empty() || !same_unit(start.unit, step.unit) ||
            !same_unit(stop.unit, step.unit))
            throw UnitError(what + ": give one unit, on STEP only ('300:3000:100rpm') or the same on START, STOP and " +
                            "STEP ('300rpm:3000rpm:100rpm')");
    }
    if (unit.empty()) unit = default_unit;
    if (!std::isfinite(start.value) || !std::isfinite(stop.value) || !std::isfinite(step.value))
        throw UnitError(what + ": START, STOP and STEP must be finite numbers");
    if (step.value == 0.0) throw UnitError(what + ": the STEP is zero (the range would never end)");
    if (step.value < 0.0)
        throw UnitError(what + ": the STEP is negative; a range counts up from START to STOP with a positive STEP");
    if (stop.value < start.value)
        throw UnitError(what + ": empty range, STOP " + message_excerpt(stop.number) + " is below START " +
                        message_excerpt(start.number));
    // STOP belongs to the range when a whole number of steps reaches it within 1e-9 of a step
    // ("0:1:0.1" has 11 items although 10 * 0.1 is not exactly 1 in binary).
    const double steps = (stop.value - start.value) / step.value;
    if (!(steps < static_cast<double>(max_items)))
        throw UnitError(what + fmt::format(": {:.3g} items; a list holds at most {}", std::floor(steps + 1e-9) + 1,
                                           max_items));
    const auto count = static_cast<std::size_t>(std::floor(steps + 1e-9)) + 1;
    if (count > max_items) throw UnitError(what + fmt::format(": {} items; a list holds at most {}", count, max_items));
    const int d = std::max({decimals(start.number), decimals(stop.number), decimals(step.number)});
    std::vector<std::string> out;
    out.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        double v = start.value + static_cast<double>(i) * step.value;
        if (i + 1 == count && std::fabs(v - stop.value) <= 1e-9 * step.value) v = stop.value;
        if (v == 0.0) v = 0.0;  // no "-0"
        out.push_back(unit.empty() ? fmt::format("{:.{}f}", v, d) : fmt::format("{:.{}f} {}", v, d, unit));
    }
    return out;
}

}  // namespace gearloss::units
