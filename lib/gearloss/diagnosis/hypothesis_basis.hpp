#pragma once
// The library of basis columns of the remainder formula (hypothesis.hpp): each a term of
// the operating point with its display, its form and the mechanism it resembles.
#include <Eigen/Dense>

#include <string>
#include <vector>

#include "gearloss/diagnosis/hypothesis.hpp"

namespace gearloss::diagnosis::hypothesis::detail {

struct Column {
    Term term;                 // basis, form and calibration term (coefficient 1 W)
    std::string mechanism;     // what it resembles
    Eigen::VectorXd x;         // its value at each point
};

// Every column the features allow (n points), without constant columns (the intercept
// aside) or duplicates up to a factor.
std::vector<Column> build_library(const Features& f, std::size_t n);

// A number rounded to `sig` significant digits, without an exponent from 1e-4 to 1e6 and
// without trailing zeros ("1150", "0.0025").
std::string num(double v, int sig);
// The same keeping trailing zeros (a coefficient: "41.0").
std::string fmt(double v, int sig = 3);

}  // namespace gearloss::diagnosis::hypothesis::detail
