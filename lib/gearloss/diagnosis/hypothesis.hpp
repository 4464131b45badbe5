#pragma once
// A compact formula for a remainder no candidate explains (issue 15, unknown forms): sparse
// regression over physically meaningful features of the operating point (powers with a
// fitted exponent, steps and thresholds at the midpoints of the recorded values, windows,
// terms gated by a threshold, the oil where several were recorded), chosen by K-fold
// cross-validation with the one-standard-error rule. Reported as a hypothesis with its
// uncertainty, its cross-validated residual against the noise and the nearest physical
// mechanisms, never as a named finding; its terms are empirical loss terms
// (mechanisms/empirical_mechanism.hpp) that --write-config can write into a calibration.
//
// Works on plain vectors (one entry per recorded point), independent of the model.
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/mechanisms/empirical_mechanism.hpp"

namespace gearloss::diagnosis::hypothesis {

// The operating point of each recorded point (each vector empty or one entry per point).
struct Features {
    std::vector<double> speed_rpm;      // input speed
    std::vector<double> torque_Nm;      // input torque
    std::vector<double> oil_temp_C;     // oil temperature (recorded, or the model's)
    std::vector<double> viscosity_cSt;  // kinematic viscosity of the oil at that temperature
    std::vector<double> order;          // run order (only where the campaign records one)
    // The model's loss at each point [W] (empty: not given): a running-in or a drift changes
    // the losses by a share that fades along the run order, so its order terms are also
    // offered in proportion to the loss.
    std::vector<double> model_loss_W;
    std::vector<std::string> oil;       // the oil of each point (only where several were recorded)
};

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

// A threshold that gates a term: the term holds only above (or at and below) it.
struct Gate {
    std::string variable;  // "speed_rpm", "torque_Nm", "oil_temp_C", "viscosity_cSt"
    double threshold = 0;  // in the variable's unit
    bool above = true;
};

// A window that confines a term to one band of another variable (a power of load at one
// speed level).
struct Window {
    std::string variable;  // "speed_rpm"
    double lower = 0, upper = 0;  // in the variable's unit
};

// One selected term: coefficient x basis function.
struct Term {
    std::string basis;        // "(n/1000 rpm)^2.9", "[n > 1050 rpm]", "(T_in/250 N*m)^2 [n = 1200 rpm]", "exp(-k/12)"
    double coefficient = 0;   // W per unit of the basis (relative: a share of the model's loss)
    double uncertainty = 0;   // one standard error, W per unit
    // The form: shape "power" | "step" | "threshold" | "window" | "constant" | "exp"; variable
    // "speed_rpm" | "torque_Nm" | "oil_temp_C" | "viscosity_cSt" | "order" | "oil".
    std::string shape, variable;
    double exponent = kNone;             // power: the fitted exponent
    // power of one variable: the exponents of the grid whose refit is within 3.84 units of
    // chi-square of the best (a 95 % profile-likelihood interval, to the grid's 0.1)
    double exponent_low = kNone, exponent_high = kNone;
    double threshold = kNone;            // step, threshold: the location, in the variable's unit
    bool above = true;                   // step, threshold: above it (else at and below it)
    double lower = kNone, upper = kNone; // window, in the variable's unit
    // A step or threshold of the viscosity: the oil temperature the campaign's points split
    // at in the same way (thick oil is cold oil; a viscosity above the threshold is a
    // temperature below this), or NaN when they do not split by temperature alone.
    double oil_temp_equivalent = kNone;
    std::optional<Gate> gate;
    std::optional<Window> window;
    std::string oil;                     // the term holds for this oil only (empty: every oil)
    // The basis is multiplied by the model's loss at each point (Features::model_loss_W), so the
    // coefficient is a share of the loss, without a unit.
    bool relative = false;
    // The same term as a calibration term (SI), with the coefficient; nullopt for a term of
    // the run order (no law of the operating point, so nothing a case file could hold).
    std::optional<losses::EmpiricalTerm> empirical;
};

struct Proposal {
    bool found = false;                  // a formula beats zero by cross-validation, significantly
    std::vector<Term> terms;             // residual [W] ~ sum of coefficient x basis
    std::string formula;                 // "dP = 41 W [theta_oil > 80.5 degC] + 2.5 W (n/1000 rpm)^2.9"
    double cv_rmse_before = 0;           // W, predicting zero
    double cv_rmse_after = 0;            // W, the formula under K-fold cross-validation
    // The loss noise (RMS over the campaign, weighted as the CV errors are) in W; 0: not given.
    double noise_W = 0;
    std::vector<std::string> nearest;    // physical mechanisms the terms resemble, e.g. "windage (n^2.9)"
    // The diagnosis: the formula is for the whole mismatch of the case as described (the
    // findings left aside), as it predicts the recordings better than the findings with a
    // formula for what they leave, whose cross-validated loss RMSE [W] is findings_cv_rmse.
    bool on_case = false;
    double findings_cv_rmse = 0;
};

// How an on_case formula compares with the findings, for the report: "better than" when its
// cross-validated residual is lower, else "about as well as, and more simply than," (it
// replaced them as the simpler account).
inline const char* on_case_comparison(const Proposal& p) {
    return p.cv_rmse_after < p.findings_cv_rmse ? "better than" : "about as well as, and more simply than,";
}

struct Settings {
    int max_terms = 3;
    std::uint64_t seed = 20261123;
    // The loss noise as a share of each point's scale (one standard deviation); 0: unknown.
    // Sets Proposal::noise_W.
    double noise_relative = 0;
};

// residual: recorded - model [W] per point; scale: each point's weight scale [W] (the residual
// divided by it has roughly equal noise, e.g. the recorded loss).
// Throws std::invalid_argument when sizes disagree or values are not finite.
Proposal propose(const std::vector<double>& residual, const std::vector<double>& scale, const Features& f,
                 const Settings& s);
inline Proposal propose(const std::vector<double>& residual, const std::vector<double>& scale, const Features& f,
                        int max_terms = 3, std::uint64_t seed = 20261123) {
    Settings s;
    s.max_terms = max_terms;
    s.seed = seed;
    return propose(residual, scale, f, s);
}

}  // namespace gearloss::diagnosis::hypothesis
