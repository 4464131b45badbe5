// Run-order cells (`run`, `date`, `time`) as numbers that grow with the order of the tests.
#include "gearloss/diagnosis/run_order.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>

namespace gearloss::diagnosis {

namespace {

// Reads `digits` decimal digits at s[pos] (advancing pos); -1 when they are not there.
long read_digits(std::string_view s, std::size_t& pos, std::size_t digits) {
    if (pos + digits > s.size()) return -1;
    long v = 0;
    for (std::size_t k = 0; k < digits; ++k) {
        const char c = s[pos + k];
        if (!std::isdigit(static_cast<unsigned char>(c))) return -1;
        v = 10 * v + (c - '0');
    }
    pos += digits;
    return v;
}

// Days from 1970-01-01 to a proleptic Gregorian date (the civil-from-days inverse of
// H. Hinnant's date algorithms, public domain).
long days_from_civil(long y, long m, long d) {
    y -= m <= 2;
    const long era = (y >= 0 ? y : y - 399) / 400;
    const long yoe = y - era * 400;
    const long doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    const long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468;
}

// hh:mm[:ss[.fff]] from s[pos] to the end, in seconds.
std::optional<double> clock_seconds(std::string_view s, std::size_t pos) {
    const std::size_t start = pos;
    long h = -1;
    // One or two digits for the hour (7:05 and 07:05).
    if (pos + 1 < s.size() && s[pos + 1] == ':') h = read_digits(s, pos, 1);
    else h = read_digits(s, pos, 2);
    if (h < 0 || h > 24 || pos >= s.size() || s[pos] != ':') return std::nullopt;
    ++pos;
    const long m = read_digits(s, pos, 2);
    if (m < 0 || m > 59) return std::nullopt;
    double sec = 0;
    if (pos < s.size() && s[pos] == ':') {
        ++pos;
        const std::string_view rest = s.substr(pos);
        const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), sec);
        if (ec != std::errc() || end != rest.data() + rest.size() || !(sec >= 0 && sec < 61)) return std::nullopt;
        pos = s.size();
    }
    if (pos != s.size() || pos == start) return std::nullopt;
    return 3600.0 * h + 60.0 * m + sec;
}

// YYYY-MM-DD[(T| )clock] in seconds since 1970-01-01.
std::optional<double> date_seconds(std::string_view s) {
    std::size_t pos = 0;
    const long y = read_digits(s, pos, 4);
    if (y < 0 || pos >= s.size() || s[pos++] != '-') return std::nullopt;
    const long m = read_digits(s, pos, 2);
    if (m < 1 || m > 12 || pos >= s.size() || s[pos++] != '-') return std::nullopt;
    const long d = read_digits(s, pos, 2);
    if (d < 1 || d > 31) return std::nullopt;
    const double day = 86400.0 * static_cast<double>(days_from_civil(y, m, d));
    if (pos == s.size()) return day;
    if (s[pos] != 'T' && s[pos] != ' ') return std::nullopt;
    const auto c = clock_seconds(s, pos + 1);
    if (!c) return std::nullopt;
    return day + *c;
}

std::optional<double> plain_number(std::string_view s) {
    double v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

}  // namespace

std::optional<double> run_order_key(const std::string& column, const std::string& cell) {
    std::string_view s = cell;
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    if (s.empty()) return std::nullopt;
    if (column == "run") return plain_number(s);
    if (column == "date") return date_seconds(s);
    if (column == "time") {
        if (s.find('-') != std::string_view::npos && s.size() >= 10 && s[4] == '-') return date_seconds(s);
        if (s.find(':') != std::string_view::npos) return clock_seconds(s, 0);
        return plain_number(s);
    }
    return std::nullopt;
}

}  // namespace gearloss::diagnosis
