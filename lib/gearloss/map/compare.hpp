#pragma once
// The same map for two oils and their differences per point (seed 001 §3.7.3,
// figs. 3.13-3.15 and eq. 3.4: power loss, stabilised temperature and efficiency).
#include <string>
#include <vector>

#include "gearloss/solver/operating_point.hpp"

namespace gearloss::map {

std::string compare_header(const std::string& name_a, const std::string& name_b);
// One row per point: both results and the differences B - A (empty where either
// point has no equilibrium).
std::string compare_row(const solver::PointResult& a, const solver::PointResult& b);

}  // namespace gearloss::map
