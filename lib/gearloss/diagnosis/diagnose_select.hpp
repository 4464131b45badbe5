#pragma once
// diagnose: the selection of effects (diagnose_select.cpp).
#include <string>
#include <vector>

#include "gearloss/diagnosis/diagnose_internal.hpp"

namespace gearloss::diagnosis::detail {

struct Selection {
    Hypothesis h;                        // the case with every accepted effect, jointly refitted
    std::vector<Finding> findings;       // in the order they were added
    std::vector<Candidate> candidates;   // the first round's screening, best first
    std::vector<std::string> warnings;
    double cv_rmse_after = 0;
    int fitted = 0;                      // parameters in h beyond the case
};

Selection select_effects(const Engine& E, const std::vector<Effect>& candidates, const Hypothesis& neutral,
                         const DiagnoseOptions& opt);

}  // namespace gearloss::diagnosis::detail
