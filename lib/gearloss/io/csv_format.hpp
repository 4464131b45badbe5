#pragma once
// Number formatting shared by every CSV the tool writes: 6 significant digits, no
// "-0", and an empty cell (never "nan") for a value that does not exist. std::to_chars
// with a precision is printf's %.6g / %.Nf digit for digit (the standard defines it so),
// at half the cost of a formatting library: a large map spends a fifth of its time here.
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <string>

namespace gearloss::io {

// Appends csv_number(v) to `out`, without a temporary string.
inline void append_csv_number(std::string& out, double v) {
    if (!std::isfinite(v)) return;
    char buf[32];  // "-1.23457e-308": 13 characters at most
    const auto r = std::to_chars(buf, buf + sizeof buf, v == 0.0 ? 0.0 : v, std::chars_format::general, 6);
    out.append(buf, r.ptr);
}

inline std::string csv_number(double v) {
    std::string s;
    append_csv_number(s, v);
    return s;
}

// Appends csv_fixed(v, decimals) to `out`.
inline void append_csv_fixed(std::string& out, double v, int decimals) {
    if (!std::isfinite(v)) return;
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
    if (r.ec == std::errc()) out.append(buf, r.ptr);
    else out += fmt::format("{:.{}f}", v, decimals);  // a value too large for the buffer (|v| > 1e40)
}

inline std::string csv_fixed(double v, int decimals) {
    std::string s;
    append_csv_fixed(s, v, decimals);
    return s;
}

}  // namespace gearloss::io
