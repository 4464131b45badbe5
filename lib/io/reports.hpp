#pragma once
// Human-readable and JSON reports for `gearloss point` and `gearloss check`.
#include <string>

#include "io/config.hpp"
#include "solver/operating_point.hpp"

namespace gearloss::io {

std::string point_report(const Case& c, const solver::PointResult& r);
std::string check_report(const Case& c);
std::string check_json(const Case& c);

}  // namespace gearloss::io
