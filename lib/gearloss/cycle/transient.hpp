#pragma once
// The lumped thermal network of a gearbox integrated in time (Boost.Odeint, Dormand-Prince 5(4)
// with step control): node temperatures and the energy of every heat flow, every loss evaluated
// at the current oil temperature while the load of the interval stays fixed. Shared by the
// drive-cycle warm-up (simulate.hpp) and the duty time series (gearloss/duty).
#include <array>
#include <cstddef>
#include <functional>

#include "gearloss/model/model.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "gearloss/thermal/network.hpp"

namespace gearloss::cycle {

// Integrated state: node temperatures, then the energies of each heat flow [J]. The mechanisms'
// energies take kMaxMechanisms slots (unused slots stay zero).
inline constexpr std::size_t kMaxMechanisms = 12;
using TransientState = std::array<double, 3 + kMaxMechanisms + 3>;
enum TransientSlot : std::size_t {
    kOil,
    kHousing,
    kClutch,
    kMech0,
    kExtraHeat = kMech0 + kMaxMechanisms,  // heat of the source outside the gearbox (a torque converter)
    kAmbient,
    kHeater
};

TransientState initial_state(const thermal::NodeTemperatures& start);
thermal::NodeTemperatures nodes(const TransientState& x);

// What stays fixed over one interval (the oil temperature does not).
struct TransientLoad {
    const solver::Model* gearbox = nullptr;  // null: gearbox at rest
    solver::PointState point;                // prepared for `gearbox`
    double heater = 0;                       // W into the oil
    double omega_in = 0;                     // rad/s, for the heat rejection of a turning housing
    double air_speed = 0;                    // under-body air over the housing [m/s]
    // Heat into the oil from outside the gearbox (a torque converter) at the oil's kinematic
    // viscosity [cSt]; empty: none.
    std::function<double(double nu_cSt)> extra_oil_heat;
};

// dx/dt of the state under `load`; `thermal_model` holds the oil, the network and the heat
// rejection.
void transient_rates(const solver::Model& thermal_model, const TransientLoad& load, double ambient,
                     const TransientState& x, TransientState& dx);

// Integrates x from t0 to t1 under `load`. InputError (key "cycle") when the step count runs over
// a bound or a value stops being finite (naming the component when the gearbox is loaded).
void integrate_interval(const solver::Model& thermal_model, const TransientLoad& load, double ambient,
                        TransientState& x, double t0, double t1);

}  // namespace gearloss::cycle
