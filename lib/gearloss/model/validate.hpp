#pragma once
// Validation where a model and its operating points are built (Ceres-style IsValid), not
// only in the YAML reader: every number finite, temperatures within the oil's validity
// (density and conductivity positive, viscosity law valid), speeds, torques and ambient
// within the stated ranges. Each issue names the item of the case description it comes
// from (section, item name, key), so a reader of the case can point at its line
// (map::validate_case does); models built in code call validate() themselves, and
// solve_point checks every point (PointStatus::out_of_range) whatever was validated.
#include <optional>
#include <string>
#include <vector>

#include "gearloss/core/issue.hpp"
#include "gearloss/model/model.hpp"

namespace gearloss::solver {

// Stated ranges of the operating point and the ambient.
inline constexpr double kMaxSpeed_rpm = 1e6;      // |n_in|
inline constexpr double kMaxTorque_Nm = 1e8;      // |T_in|
inline constexpr double kMinAmbient_K = 173.15;   // -100 degC
inline constexpr double kMaxAmbient_K = 573.15;   // +300 degC

// Temperatures [K] within which the oil's description holds (both bounds exclusive): above
// the pole of its Vogel law (or 0 K), below the temperature at which its density, or the
// estimate of its thermal conductivity, reaches zero.
struct OilValidity {
    double T_min = 0, T_max = 0;
    const char* min_reason = "absolute zero";  // "pole of its Vogel viscosity law"
    const char* max_reason = "";               // "its density reaches zero", ...
    bool contains(double T) const { return T > T_min && T < T_max; }
};
OilValidity oil_validity(const lubricant::Oil& oil);
// Why the oil's description does not hold at T (nullopt when it does).
std::optional<std::string> oil_temperature_fault(const lubricant::Oil& oil, double T_K);

// Why a value is out of the stated range (nullopt when it is within): finite, |n| <= 1e6 rpm,
// |T| <= 1e8 N m, ambient -100..300 degC.
std::optional<std::string> speed_fault(double omega_in);
std::optional<std::string> torque_fault(double torque_in);
std::optional<std::string> ambient_fault(double T_K);

// Every issue of the model (empty: valid). Checks the description (finite numbers, ranges,
// indices) and, once finalise() has run, the derived layout (finite ratios and loads).
std::vector<Issue> validate(const Model& m);
// The first issue's message, followed by the paths of up to three more: "... (2 more: a.b; c)".
std::string summarise(const std::vector<Issue>& issues);
inline bool is_valid(const Model& m) { return validate(m).empty(); }

// An operating point at the input (section "operating", keys "speeds" / "torques").
std::vector<Issue> validate_operating_point(double omega_in, double torque_in);

}  // namespace gearloss::solver
