#pragma once
// Numbers in messages and reports: never "nan" or "inf" printed as a number (a value that is
// not finite is spelt out) and never hundreds of digits (a typo of 1e300 stays a dozen
// characters).
#include <cmath>
#include <fmt/format.h>
#include <string>

namespace gearloss {

// `significant` digits ({:g} style); "not a number", "+infinity", "-infinity" otherwise.
inline std::string number_text(double v, int significant = 6) {
    if (std::isnan(v)) return "not a number";
    if (std::isinf(v)) return v > 0 ? "+infinity" : "-infinity";
    return fmt::format("{:.{}g}", v, significant);
}

// The same with "(not finite)" for any value that is not finite (reports, where no word of a
// value may read as a number).
inline std::string finite_number_text(double v, int significant = 6) {
    return std::isfinite(v) ? number_text(v, significant) : "(not finite)";
}

// A temperature given in K, in degC: one decimal up to 10^6 degC, four significant digits beyond.
inline std::string celsius_text(double T_K) {
    const double c = T_K - 273.15;
    if (!std::isfinite(c)) return number_text(c) + " degC";
    return std::abs(c) < 1e6 ? fmt::format("{:.1f} degC", c) : fmt::format("{:.4g} degC", c);
}

}  // namespace gearloss
