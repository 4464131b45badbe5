#pragma once
// Human-readable and JSON reports for `gearloss point` and `gearloss check`.
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "gearloss/case/config.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::io {

std::string point_report(const Case& c, const solver::PointResult& r);
std::string check_report(const Case& c);
// check --json: the derived data as a JSON object (members in a fixed order), and as text.
nlohmann::ordered_json check_json_object(const Case& c);
std::string check_json(const Case& c);
// The assumed values as a JSON array of {key, value, reason, location (null when unknown)}:
// the same in check --json, the sidecars and the report.
nlohmann::ordered_json assumed_json(const std::vector<AssumedValue>& assumed);
// Local thermal-EHL state along the path of contact of mesh `mesh_name` at the
// point's oil temperature (CSV). Throws InputError for an unknown or idle mesh.
std::string mesh_profile_csv(const Case& c, const std::string& mesh_name, double omega_in, double torque_in,
                             double oil_temperature, int positions);

}  // namespace gearloss::io
