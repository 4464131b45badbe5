#pragma once
// An empirical loss: the calibration's formula for what the case's physics does not
// describe, as `gearloss diagnose` proposes it for a remainder no mechanism explains
// (diagnosis/hypothesis.hpp) and `--write-config` writes it. A sum of terms, each a
// coefficient in W times a product of factors of the operating point and the oil state:
//
//   P = sum_k c_k prod_j f_kj,   f = 1                          constant
//                                  (x / x_ref)^a                power
//                                  [x > x_t]  ([x <= x_t])      step (below)
//                                  max(0, x - x_t) / x_ref      threshold: a loss growing above x_t
//                                  (max(0, x_t - x) / x_ref)    (or growing below it)
//                                  [x_lo < x <= x_hi]           window
//
// over x = input speed, input torque, oil temperature or kinematic viscosity (SI inside).
// A term may name an oil: it then holds for that oil only (multi-oil campaigns). There is
// no published source: the terms are a fit to recordings, said as such wherever reported.
#include <string>
#include <string_view>
#include <vector>

#include "gearloss/losses/loss_mechanism.hpp"

namespace gearloss::losses {

enum class EmpiricalVariable { speed, torque, oil_temperature, viscosity };
enum class EmpiricalShape { power, step, threshold, window };

// YAML names: speed, torque, oil_temperature, viscosity; power, step, threshold, window.
std::string_view empirical_name(EmpiricalVariable v);
std::string_view empirical_name(EmpiricalShape s);

struct EmpiricalFactor {
    EmpiricalVariable variable = EmpiricalVariable::speed;
    EmpiricalShape shape = EmpiricalShape::power;
    double reference = 1;          // SI (rad/s, N*m, K, m^2/s): power and threshold
    double exponent = 1;           // power
    double threshold = 0;          // SI: step and threshold
    double lower = 0, upper = 0;   // SI: window
    bool below = false;            // step, threshold: at and below the threshold instead of above
    double value(double x) const;  // f(x)
};

struct EmpiricalTerm {
    double coefficient = 0;               // W
    std::vector<EmpiricalFactor> factors; // none: a constant loss while the input turns
    std::string oil;                      // empty: every oil; else the oil's name
    // The basis (the product of the factors) at omega_in [rad/s], torque_in [N*m], oil
    // temperature T [K], kinematic viscosity nu [m^2/s].
    double basis(double omega, double torque, double T, double nu) const;
};

class EmpiricalMechanism final : public LossMechanism {
public:
    std::unique_ptr<LossMechanism> clone() const override { return std::make_unique<EmpiricalMechanism>(*this); }
    std::string_view name() const override { return "empirical"; }
    std::string_view label() const override { return "empirical"; }
    std::string_view column() const override { return "P_empirical_W"; }
    std::unique_ptr<MechanismPoint> make_point() const override;
    void prepare(const solver::Model&, const PointInput&, MechanismPoint& point) const override;
    double power(const solver::Model&, const MechanismPoint&, Evaluation& eval, MechanismDetail* detail) const override;
    // A sum of fitted terms may be negative where the model over-predicts: only a non-finite
    // value is a fault.
    std::string loss_fault(const solver::Model&, const MechanismPoint&, const MechanismDetail&) const override;

    const std::vector<EmpiricalTerm>& terms() const { return terms_; }
    void set_terms(std::vector<EmpiricalTerm> t) { terms_ = std::move(t); }

private:
    std::vector<EmpiricalTerm> terms_;
};

}  // namespace gearloss::losses
