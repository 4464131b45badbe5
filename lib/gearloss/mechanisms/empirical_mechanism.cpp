// The empirical loss of a calibration (empirical_mechanism.hpp): terms fitted to recordings.
#include "gearloss/mechanisms/empirical_mechanism.hpp"

#include <algorithm>
#include <cmath>

#include "gearloss/losses/registry.hpp"
#include "gearloss/model/model.hpp"

namespace gearloss::losses {

std::string_view empirical_name(EmpiricalVariable v) {
    switch (v) {
        case EmpiricalVariable::speed: return "speed";
        case EmpiricalVariable::torque: return "torque";
        case EmpiricalVariable::oil_temperature: return "oil_temperature";
        case EmpiricalVariable::viscosity: return "viscosity";
    }
    return "";
}

std::string_view empirical_name(EmpiricalShape s) {
    switch (s) {
        case EmpiricalShape::power: return "power";
        case EmpiricalShape::step: return "step";
        case EmpiricalShape::threshold: return "threshold";
        case EmpiricalShape::window: return "window";
    }
    return "";
}

double EmpiricalFactor::value(double x) const {
    switch (shape) {
        case EmpiricalShape::power: return std::pow(std::max(0.0, x / reference), exponent);
        case EmpiricalShape::step: return (below ? x <= threshold : x > threshold) ? 1.0 : 0.0;
        case EmpiricalShape::threshold: return std::max(0.0, below ? threshold - x : x - threshold) / reference;
        case EmpiricalShape::window: return x > lower && x <= upper ? 1.0 : 0.0;
    }
    return 0.0;
}

double EmpiricalTerm::basis(double omega, double torque, double T, double nu) const {
    double b = 1.0;
    for (const auto& f : factors) {
        double x = 0;
        switch (f.variable) {
            case EmpiricalVariable::speed: x = std::abs(omega); break;
            case EmpiricalVariable::torque: x = torque; break;
            case EmpiricalVariable::oil_temperature: x = T; break;
            case EmpiricalVariable::viscosity: x = nu; break;
        }
        b *= f.value(x);
    }
    return b;
}

namespace {
struct EmpiricalPoint : MechanismPointOf<EmpiricalPoint> {
    bool turning = false;
    double omega = 0, torque = 0;
    const std::string* oil = nullptr;  // the model's oil name (the model outlives the point's use)
};
}  // namespace

std::unique_ptr<MechanismPoint> EmpiricalMechanism::make_point() const { return std::make_unique<EmpiricalPoint>(); }

void EmpiricalMechanism::prepare(const solver::Model& m, const PointInput& in, MechanismPoint& out) const {
    auto& p = static_cast<EmpiricalPoint&>(out);
    p.turning = enabled() && !terms_.empty() && in.omega_in != 0.0;
    p.omega = in.omega_in;
    p.torque = in.torque_in;
    p.oil = &m.oil.name;
}

double EmpiricalMechanism::power(const solver::Model& m, const MechanismPoint& pt, Evaluation& eval,
                                 MechanismDetail* d) const {
    if (d) d->reset(0, 1);
    const auto& p = static_cast<const EmpiricalPoint&>(pt);
    if (!p.turning) return 0.0;
    double P = 0;
    for (const auto& t : terms_) {
        if (!t.oil.empty() && t.oil != m.oil.name) continue;
        P += t.coefficient * t.basis(p.omega, p.torque, eval.oil.T, eval.oil.nu);
    }
    return P;
}

std::string EmpiricalMechanism::loss_fault(const solver::Model&, const MechanismPoint&, const MechanismDetail&) const {
    return {};
}

std::unique_ptr<LossMechanism> create_empirical() { return make_mechanism<EmpiricalMechanism>(); }

}  // namespace gearloss::losses
