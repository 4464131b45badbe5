#pragma once
// The range in which each churning form was fitted (or on which its expression is defined),
// and the check of a dipping gear against it: a gear outside is a finding of the case
// (check, stderr, the output's sidecar; docs/config.md "Churning forms and their ranges").
#include <string>
#include <vector>

namespace gearloss::churning {

// One quantity of a form's range: lo <= value <= hi (strictly above lo when lo_open).
struct FittedLimit {
    std::string quantity;  // "helix angle", "h/D", "b/D", "V0/D^3", "Fr"
    double lo = 0, hi = 0;
    bool lo_open = false;
    std::string unit;      // shown after the numbers ("deg"); empty: dimensionless
};

struct FittedRange {
    std::string form;
    std::vector<FittedLimit> limits;
    // Whether the limits are those of the data the form was fitted on ("fitted") or those on
    // which its expression has a value ("defined for").
    bool fitted = true;
};

// The range of a churning form by its name (an empty list: no range is known).
FittedRange fitted_range(const std::string& form);

// The span of one quantity over the case (its smallest and largest value).
struct GivenSpan {
    std::string quantity;
    double lo = 0, hi = 0;
};

// "helix angle 0 deg given, defined for > 0 deg; ..." for every quantity of `given` outside
// the form's range (quantities the range does not name are not checked); empty when inside.
std::string outside_range(const FittedRange& range, const std::vector<GivenSpan>& given);

}  // namespace gearloss::churning
