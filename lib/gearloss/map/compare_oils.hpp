#pragma once
// `gearloss compare` with two or more oils, --detail and --json (docs/outputs.md). The first
// oil is the reference A; every difference is (oil k - oil A): a positive dP means more loss
// than A (worse). Two oils without --detail write compare_header/compare_row's columns
// exactly; N >= 3 oils give, per oil k, P_total_<k>_W, oil_temp_<k>_C, efficiency_<k>,
// status_<k> and, for k != A, dP_loss_<k>_W, dT_oil_<k>_K, d_efficiency_<k>. --detail adds,
// per mechanism column P_x_W, P_x_<k>_W per oil and dP_x_<k>_W for k != A.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "gearloss/solver/operating_point.hpp"

namespace gearloss::map {

// The oils' names as parts of column names: ',' and '"' replaced by '_', and names that
// occur twice told apart by their position (_1, _2, ...; two oils: _A and _B, as before).
std::vector<std::string> oil_column_names(const std::vector<std::string>& oil_names);

std::string compare_oils_header(const solver::Model& m, const std::vector<std::string>& oil_names, bool detail);
// One row: the results of point i for every oil (same order as the names).
std::string compare_oils_row(const solver::Model& m, const std::vector<const solver::PointResult*>& r, bool detail);

// `compare --json`: per oil and per point; `metadata` is stored under "metadata".
// maps[k][i] is point i of oil k.
nlohmann::ordered_json compare_json(const solver::Model& m, const std::vector<std::string>& oil_names,
                                    const std::vector<std::vector<solver::PointResult>>& maps,
                                    nlohmann::ordered_json metadata);

}  // namespace gearloss::map
