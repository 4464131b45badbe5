#include "gearloss/cycle/transient.hpp"

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <fmt/format.h>
#include <string>

#include "gearloss/core/errors.hpp"

namespace gearloss::cycle {

namespace odeint = boost::numeric::odeint;

TransientState initial_state(const thermal::NodeTemperatures& start) {
    TransientState x{};
    x[kOil] = start[0];
    x[kHousing] = start[1];
    x[kClutch] = start[2];
    return x;
}

thermal::NodeTemperatures nodes(const TransientState& x) { return {x[kOil], x[kHousing], x[kClutch]}; }

void transient_rates(const solver::Model& tm, const TransientLoad& load, double ambient, const TransientState& x,
                     TransientState& dx) {
    const auto& net = tm.thermal.network;
    const thermal::NodeTemperatures T = nodes(x);
    const lubricant::OilState os = tm.oil_state(T[0]);
    solver::LossBreakdown L;
    if (load.gearbox) L = solver::evaluate_losses(*load.gearbox, load.point, os, false);
    const double P_extra = load.extra_oil_heat ? load.extra_oil_heat(os.nu_cSt) : 0.0;
    // Heat of the mechanisms that do not heat the oil goes to the clutch-pack node.
    const double P_other = load.gearbox ? L.total() - L.into_oil(*load.gearbox) : 0.0;
    // The external cooler draws from the oil node, as in the stabilised balance (Model::heat_flow).
    const double Q_cooler = tm.thermal.cooler.present() ? tm.thermal.cooler.heat_flow(T[0], os.rho * os.cp) : 0.0;
    const double P_oil = L.total() - P_other + P_extra + load.heater - Q_cooler;
    const double Q = tm.surface_heat_flow(thermal::surface_temperature(net, T), ambient, load.omega_in, load.air_speed);
    const auto d = thermal::node_rates(net, T, P_oil, P_other, Q);
    dx.fill(0.0);
    dx[kOil] = d[0];
    dx[kHousing] = d[1];
    dx[kClutch] = d[2];
    for (size_t i = 0; i < L.power.size(); ++i) dx[kMech0 + i] = L.power[i];
    dx[kExtraHeat] = P_extra;
    dx[kAmbient] = Q + Q_cooler;  // heat that left the transmission
    dx[kHeater] = load.heater;
}

namespace {

// One interval between samples takes at most kMaxSteps accepted steps of the integrator (a 1-s
// interval takes a handful).
constexpr size_t kMaxSteps = 100000;

[[noreturn]] void fail(const std::string& message) { throw InputError("", 0, 0, "cycle", message); }

// Called by the integrator once per accepted step: bounds the steps and stops at the first
// value that is not finite, naming the component when the gearbox is loaded.
struct StepGuard {
    const TransientLoad& load;
    double ambient;
    size_t* steps;
    void operator()(const TransientState& x, double t) const {
        if (++*steps > kMaxSteps)
            fail(fmt::format("the integration of the interval at t = {:g} s did not finish within {} steps", t, kMaxSteps));
        for (double v : x)
            if (!std::isfinite(v)) {
                std::string cause;
                if (load.gearbox && std::isfinite(x[kOil]))
                    cause = solver::loss_fault(*load.gearbox, load.point, x[kOil], ambient);
                fail(fmt::format("at t = {:g} s a temperature or energy is not a finite number (out_of_range: {})", t,
                                 cause.empty() ? "thermal network" : cause));
            }
    }
};

struct Rates {
    const solver::Model& tm;
    const TransientLoad& load;
    double ambient;
    void operator()(const TransientState& x, TransientState& dx, double /*t*/) const {
        transient_rates(tm, load, ambient, x, dx);
    }
};

}  // namespace

void integrate_interval(const solver::Model& tm, const TransientLoad& load, double ambient, TransientState& x,
                        double t0, double t1) {
    // Tolerances: 1e-4 K on temperatures (the energies are large numbers: relative 1e-7).
    auto stepper = odeint::make_controlled(1e-4, 1e-7, odeint::runge_kutta_dopri5<TransientState>());
    size_t steps = 0;
    try {
        // First trial step at most 1 s: a cycle sampled every 100 s would otherwise start with a
        // trial of 100 s, whose stages leave the range where the oil's description holds.
        odeint::integrate_adaptive(stepper, Rates{tm, load, ambient}, x, t0, t1, std::min(t1 - t0, 1.0),
                                   StepGuard{load, ambient, &steps});
    } catch (const odeint::step_adjustment_error& e) {
        fail(fmt::format("the integration from t = {:g} s failed: {}", t0, e.what()));
    }
}

}  // namespace gearloss::cycle
