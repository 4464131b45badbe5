#pragma once
// Number formatting shared by every CSV the tool writes: 6 significant digits, no
// "-0", and an empty cell (never "nan") for a value that does not exist.
#include <cmath>
#include <fmt/format.h>
#include <string>

namespace gearloss::io {

inline std::string csv_number(double v) {
    if (!std::isfinite(v)) return {};
    return fmt::format("{:.6g}", v == 0.0 ? 0.0 : v);
}

inline std::string csv_fixed(double v, int decimals) {
    return std::isfinite(v) ? fmt::format("{:.{}f}", v, decimals) : std::string();
}

}  // namespace gearloss::io
