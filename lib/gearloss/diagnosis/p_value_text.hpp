#pragma once
// How a p-value is printed in the diagnosis texts: one helper for every place that prints one.
#include <fmt/format.h>

#include <string>

namespace gearloss::diagnosis {

// Below this a p-value prints as a bound: the tests take the residuals as near-normal, and so
// far out in the tail the number (down to 4.9e-324, the smallest double) says more about that
// approximation than about the data; "p < 1e-16" says all there is to say.
inline constexpr double kSmallestPrintedP = 1e-16;

// "p = 0.034", "p = 2.1e-05", "p < 1e-16" (two significant digits, as the texts had).
inline std::string p_value_text(double p) {
    if (p < kSmallestPrintedP) return fmt::format("p < {:g}", kSmallestPrintedP);
    return fmt::format("p = {:.2g}", p);
}

}  // namespace gearloss::diagnosis
