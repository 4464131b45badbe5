#include "gearloss/solver/operating_point.hpp"

#include "gearloss/core/message_text.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "gearloss/model/validate.hpp"

namespace gearloss::solver {

const char* to_string(PointStatus s) {
    switch (s) {
        case PointStatus::ok: return "ok";
        case PointStatus::no_equilibrium: return "no_equilibrium";
        case PointStatus::above_oil_limit: return "above_oil_limit";
        case PointStatus::out_of_range: return "out_of_range";
    }
    return "?";
}

std::string status_text(const PointResult& r) {
    std::string s = to_string(r.status);
    if (r.status != PointStatus::out_of_range || r.cause.empty()) return s;
    s += ": ";
    for (char c : r.cause) s += (c == ',' || c == '"' || c == '\n' || c == '\r') ? ' ' : c;
    return s;
}

namespace {
bool finite(double v) { return std::isfinite(v); }
bool finite_non_negative(double v) { return std::isfinite(v) && v >= 0.0; }

// The oil-independent terms of every mechanism at the point, first fault found.
std::string point_fault(const Model& m, const PointState& p) {
    if (!finite(p.omega_in)) return "input speed";
    if (!finite(p.torque_in)) return "input torque";
    if (!finite(p.power_in)) return "input power";
    for (size_t i = 0; i < m.mechanisms.size(); ++i)
        if (auto f = m.mechanisms[i].point_fault(m, *p.data[i]); !f.empty()) return f;
    return {};
}

std::string degC(double T) { return celsius_text(T); }
}  // namespace

PointState::PointState(const PointState& o)
    : omega_in(o.omega_in), torque_in(o.torque_in), power_in(o.power_in), mechanisms_id(o.mechanisms_id), fault(o.fault) {
    data.reserve(o.data.size());
    for (const auto& d : o.data) data.push_back(d ? d->clone() : nullptr);
}

PointState& PointState::operator=(const PointState& o) {
    if (this != &o) {
        PointState copy(o);
        *this = std::move(copy);
    }
    return *this;
}

PointState prepare_point(const Model& m, double omega_in, double torque_in) {
    PointState p;
    prepare_point(m, omega_in, torque_in, p);
    return p;
}

void prepare_point(const Model& m, double omega_in, double torque_in, PointState& p) {
    p.omega_in = omega_in;
    p.torque_in = torque_in;
    p.power_in = omega_in * torque_in;
    const auto& mech = m.mechanisms;
    if (p.mechanisms_id != mech.id() || p.data.size() != mech.size()) {
        // Storage made by another model's mechanisms is replaced.
        p.data.clear();
        for (size_t i = 0; i < mech.size(); ++i) p.data.push_back(mech[i].make_point());
        p.mechanisms_id = mech.id();
    }
    const losses::PointInput in = p.input();
    for (size_t i = 0; i < mech.size(); ++i) mech[i].prepare(m, in, *p.data[i]);
    p.fault = point_fault(m, p);
}

double LossBreakdown::of(const Model& m, std::string_view name) const {
    const size_t i = m.mechanisms.index(name);
    return i < power.size() ? power[i] : 0.0;
}

const losses::MechanismDetail& LossBreakdown::detail_of(const Model& m, std::string_view name) const {
    return detail.at(m.mechanisms.index(name));
}

double LossBreakdown::into_oil(const Model& m) const {
    double t = 0.0;
    for (size_t i = 0; i < power.size(); ++i)
        if (m.mechanisms[i].heats_oil()) t += power[i];
    return t;
}

LossBreakdown evaluate_losses(const Model& m, const PointState& p, const lubricant::OilState& s, bool detail,
                              bool film) {
    const auto& mech = m.mechanisms;
    LossBreakdown r;
    r.power.resize(mech.size());
    if (detail) r.detail.resize(mech.size());
    losses::Evaluation e{s, std::log(s.nu_cSt), film || detail};
    for (size_t i = 0; i < mech.size(); ++i)
        r.power[i] = mech[i].power(m, *p.data[i], e, detail ? &r.detail[i] : nullptr);
    r.lambda_min = e.lambda_min;
    r.has_lambda = e.has_lambda;
    return r;
}

double total_loss(const Model& m, const PointState& p, double T_oil) {
    const lubricant::OilState s = m.oil_state(T_oil);
    const auto& mech = m.mechanisms;
    losses::Evaluation e{s, std::log(s.nu_cSt), false};
    double total = 0.0;
    for (size_t i = 0; i < mech.size(); ++i) total += mech[i].power(m, *p.data[i], e, nullptr);
    return total;
}

std::string loss_fault(const Model& m, const PointState& p, double T, double ambient) {
    if (auto f = oil_temperature_fault(m.oil, T)) return "oil temperature " + *f;
    const lubricant::OilState s = m.oil_state(T);
    const std::string at = " at " + degC(T);
    if (!(s.nu > 0 && finite(s.nu) && finite(s.eta) && s.eta > 0)) return "oil '" + m.oil.name + "' viscosity" + at;
    if (!(s.rho > 0 && finite(s.rho))) return "oil '" + m.oil.name + "' density" + at;
    if (!(finite(s.alpha_p) && finite(s.beta_T) && s.k > 0 && finite(s.k) && finite(s.cp)))
        return "oil '" + m.oil.name + "' properties" + at;
    const LossBreakdown L = evaluate_losses(m, p, s, true, true);
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        const auto& mech = m.mechanisms[i];
        if (auto f = mech.loss_fault(m, *p.data[i], L.detail[i]); !f.empty()) return f + at;
        if (!finite_non_negative(L.power[i])) return std::string(mech.label()) + " loss" + at;
    }
    if (!finite_non_negative(L.total())) return "total loss" + at;
    if (!finite(m.heat_flow(T, ambient, p.omega_in))) return "heat rejection" + at;
    return {};
}

thermal::Equilibrium solve_temperature(const Model& m, const PointState& p, double ambient) {
    auto F = [&](double Toil) { return total_loss(m, p, Toil) - m.heat_flow(Toil, ambient, p.omega_in); };
    // Conductance of the bracketing steps: the housing's secant from ambient plus the cooler's slope.
    auto G = [&](double Toil) {
        const double Tq = std::max(Toil, ambient + 0.5);
        return m.housing_heat_flow(Tq, ambient, p.omega_in) / (Tq - ambient) + m.cooler_conductance(Toil);
    };
    // A cooler colder than the ambient can hold the oil below it: the search starts at the
    // colder of the two (there F >= 0: the housing gains heat and the cooler removes none).
    const double start = std::min(ambient, m.thermal.cooler.cold_side_temperature());
    return thermal::solve_equilibrium(F, G, start, m.thermal.equilibrium);
}

PointResult solve_point(const Model& m, double omega_in, double torque_in, bool detail, double ambient) {
    PointResult r;
    r.speed_in = omega_in;
    r.torque_in = torque_in;
    r.ambient = ambient;
    r.power_in = omega_in * torque_in;
    // Out of range: no numbers, the cause in the status.
    auto out_of_range = [&r](std::string cause) {
        r.status = PointStatus::out_of_range;
        r.cause = std::move(cause);
        r.losses = LossBreakdown{};
        r.oil_temperature = std::numeric_limits<double>::quiet_NaN();
        r.power_out = r.torque_out = r.omega_out = r.efficiency = 0.0;
        r.has_efficiency = false;
        return r;
    };
    if (auto f = speed_fault(omega_in)) return out_of_range(*f);
    if (auto f = torque_fault(torque_in)) return out_of_range(*f);
    const bool fixed = m.thermal.mode == ThermalMode::fixed;
    if (!fixed) {
        if (auto f = ambient_fault(ambient)) return out_of_range(*f);
        if (auto f = oil_temperature_fault(m.oil, ambient)) return out_of_range("ambient " + *f);
    } else if (auto f = oil_temperature_fault(m.oil, m.thermal.oil_temperature)) {
        return out_of_range("fixed oil temperature " + *f);
    }
    // Per-thread storage: a map solves many points per thread without allocating.
    thread_local PointState p;
    prepare_point(m, omega_in, torque_in, p);
    if (!p.fault.empty()) return out_of_range(p.fault);
    r.power_in = p.power_in;
    double T;
    if (fixed) {
        T = m.thermal.oil_temperature;
    } else {
        const thermal::Equilibrium eq = solve_temperature(m, p, ambient);
        r.evaluations = eq.evaluations;
        r.thermal_residual = eq.residual;
        switch (eq.status) {
            case thermal::EquilibriumStatus::ok: break;
            case thermal::EquilibriumStatus::no_equilibrium:
                r.status = PointStatus::no_equilibrium;
                r.oil_temperature = eq.T;
                return r;
            case thermal::EquilibriumStatus::non_finite: {
                const std::string f = loss_fault(m, p, eq.T, ambient);
                return out_of_range(f.empty() ? "thermal equilibrium: a value that is not finite at " + degC(eq.T) : f);
            }
            case thermal::EquilibriumStatus::iteration_limit:
                return out_of_range("thermal equilibrium: no bracket within " +
                                    std::to_string(m.thermal.equilibrium.max_bracket_steps) + " steps (last at " +
                                    degC(eq.T) + ")");
        }
        T = eq.T;
        if (T > m.oil.max_temperature) r.status = PointStatus::above_oil_limit;
    }
    r.oil_temperature = T;
    r.losses = evaluate_losses(m, p, m.oil_state(T), detail, true);
    const double Ploss = r.losses.total();
    // Every component's loss a finite, non-negative number (the film too), else the cause.
    bool finite_losses = finite_non_negative(Ploss) && finite(r.losses.lambda_min);
    for (double P : r.losses.power) finite_losses = finite_losses && finite_non_negative(P);
    if (!finite_losses) {
        const std::string f = loss_fault(m, p, T, ambient);
        return out_of_range(f.empty() ? "losses at " + degC(T) + " are not finite" : f);
    }
    r.power_out = r.power_in - Ploss;
    r.omega_out = m.layout.ratio * omega_in;
    // Output torque in the output's own sense of rotation: positive when power
    // leaves through the output shaft.
    if (r.omega_out != 0.0) {
        r.torque_out = r.power_out / std::abs(r.omega_out);
    } else {
        r.torque_out = torque_in / std::abs(m.layout.ratio);  // standstill: ideal torque ratio
    }
    if (r.power_in > 0.0) {
        // When the losses exceed the input power no power reaches the output
        // (power_out < 0 says by how much); the efficiency is then 0, not negative.
        r.efficiency = std::max(0.0, r.power_out / r.power_in);
        r.has_efficiency = true;
    } else if (r.power_in < 0.0) {
        // Driven from the output: power enters there, |P_in| leaves at the input.
        r.efficiency = -r.power_in / (-r.power_in + Ploss);
        r.has_efficiency = true;
    }
    if (!finite(r.power_out) || !finite(r.torque_out) || !finite(r.omega_out) || !finite(r.efficiency))
        return out_of_range("output power, torque or efficiency is not finite");
    return r;
}

}  // namespace gearloss::solver
