#pragma once
// A compact formula for a remainder no candidate explains (issue 15, unknown forms): sparse
// regression over physically meaningful features of the operating point, with steps and
// thresholds, chosen by cross-validation. Reported as a hypothesis with its uncertainty and
// the nearest physical mechanisms, never as a named finding.
//
// Works on plain vectors (one entry per recorded point), independent of the model.
#include <cstdint>
#include <string>
#include <vector>

namespace gearloss::diagnosis::hypothesis {

// The operating point of each recorded point.
struct Features {
    std::vector<double> speed_rpm;      // input speed
    std::vector<double> torque_Nm;      // input torque
    std::vector<double> oil_temp_C;     // oil temperature (recorded, or the model's)
    std::vector<double> viscosity_cSt;  // kinematic viscosity of the oil at that temperature
    std::vector<double> order;          // run order (row number)
};

// One selected term: coefficient x basis function.
struct Term {
    std::string basis;        // "(n/1000 rpm)^3", "[n > 1050 rpm]", "(T_in/1000 N*m)^2 [n = 1200 rpm]", "exp(-k/12)"
    double coefficient = 0;   // W per unit of the basis
    double uncertainty = 0;   // one standard error, W per unit
};

struct Proposal {
    bool found = false;                  // a formula beats zero by cross-validation
    std::vector<Term> terms;             // residual [W] ~ sum of coefficient x basis
    std::string formula;                 // "dP = 41 W [n > 1050 rpm] + 0.0025 W (T_in/1 N*m)^2 [n = 1200 rpm]"
    double cv_rmse_before = 0;           // W, predicting zero
    double cv_rmse_after = 0;            // W, the formula under K-fold cross-validation
    std::vector<std::string> nearest;    // physical mechanisms the terms resemble, e.g. "windage (n^2.9)"
};

// residual: recorded - model [W] per point; scale: each point's weight scale [W] (the residual
// divided by it has roughly equal noise, e.g. the recorded loss); at most max_terms terms.
// Throws std::invalid_argument when sizes disagree.
Proposal propose(const std::vector<double>& residual, const std::vector<double>& scale, const Features& f,
                 int max_terms = 3, std::uint64_t seed = 20261123);

}  // namespace gearloss::diagnosis::hypothesis
