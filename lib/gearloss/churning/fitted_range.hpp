#pragma once
// The range in which each churning form was fitted (or on which its expression is defined),
// and the check of a dipping gear against it: a gear outside is a finding of the case
// (check, stderr, the output's sidecar; docs/config.md "Churning forms and their ranges").
#include <string>
#include <vector>

namespace gearloss::churning {

// One quantity of a form's range: lo <= value <= hi (strictly above lo when lo_open).
struct FittedLimit {
    std::string quantity;  // "helix angle", "h/D", "b/D", "V0/D^3", "Fr", "pitch-line speed"
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
    // What is known of the range and how well (shown by check and with a finding): e.g. "not
    // stated in a verified source" where no limit is checked, or where the limits come from.
    std::string provenance;
};

// The range of a churning form by its name (an empty list: no range is known).
FittedRange fitted_range(const std::string& form);

// The limits as text ("pitch-line speed 0-60 m/s; ..."), "none checked" when there are none.
std::string describe_limits(const FittedRange& range);

// Where a form's coefficients come from, when that is short of the original paper (check says
// it); empty otherwise.
std::string coefficient_provenance(const std::string& form);

// The span of one quantity over the case (its smallest and largest value).
struct GivenSpan {
    std::string quantity;
    double lo = 0, hi = 0;
};

// "helix angle 0 deg given, defined for > 0 deg; ..." for every quantity of `given` outside
// the form's range (quantities the range does not name are not checked); empty when inside.
std::string outside_range(const FittedRange& range, const std::vector<GivenSpan>& given);

}  // namespace gearloss::churning
