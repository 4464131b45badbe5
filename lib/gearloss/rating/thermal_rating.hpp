#pragma once
// Thermal rating of a case (ISO/TR 14179-1 and -2: the thermal power limit): at one input speed,
// the input torque (and power) at which the stabilised oil reaches the permissible temperature;
// and, at an operating point, the heat a cooler must remove to hold the oil at a target
// temperature (the cooler duty).
#include <string>

#include "gearloss/model/model.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::rating {

struct RatingOptions {
    double oil_limit = 368.15;   // K, the permissible oil temperature
    double ambient = 298.15;     // K
    double max_torque = 1e4;     // N*m, the search goes no higher ("no limit below")
    double start_torque = 100;   // N*m, the first upper guess of the bracket (the case's largest torque)
};

// limit: the oil reaches oil_limit at `torque`; no_limit_below: below oil_limit up to
// max_torque (`torque` = max_torque); above_at_zero_torque: above oil_limit with no load
// (`torque` = 0); out_of_range: a point of the search left the model's range (`cause`).
enum class RatingStatus { limit, no_limit_below, above_at_zero_torque, out_of_range };
const char* to_string(RatingStatus s);

struct RatingPoint {
    double omega = 0;             // rad/s
    RatingStatus status = RatingStatus::limit;
    double torque = 0;            // N*m (see RatingStatus)
    std::string cause;            // out_of_range: what left the range
    solver::PointResult point;    // the stabilised point at `torque` (with the mechanism split)
    double housing_heat = 0;      // W to ambient through the housing at the point
    double cooler_heat = 0;       // W removed by the case's cooler at the point
    int solves = 0;               // stabilised points solved by the search
};

// The thermal power limit at input speed omega (> 0): the torque where the stabilised oil
// temperature T(torque) crosses oil_limit, bracketed by doubling from start_torque and found
// by TOMS 748 (Alefeld, Potra & Shi 1995, Boost.Math). The model must be in stabilised mode.
RatingPoint rate_speed(const solver::Model& m, double omega, const RatingOptions& o);

struct CoolerDutyPoint {
    double omega = 0, torque = 0;  // rad/s, N*m
    solver::PointResult point;     // the losses with the oil held at the target temperature
    double housing_heat = 0;       // W the housing rejects at the target temperature
    double duty = 0;               // W a cooler must remove: losses - housing heat, at least 0
};

// The cooler duty at (omega, torque) for the oil held at T_target (the case's own cooler left
// out): the heat balance P_loss(T_target) = Q_housing(T_target) + Q_cooler solved for Q_cooler
// (ISO/TR 14179-2: the external cooling term closes the balance).
CoolerDutyPoint cooler_duty(const solver::Model& m, double omega, double torque, double T_target, double ambient);

}  // namespace gearloss::rating
