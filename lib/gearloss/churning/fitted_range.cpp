#include "gearloss/churning/fitted_range.hpp"

#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace gearloss::churning {

FittedRange fitted_range(const std::string& form) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (form == "heingartner_mba_2003")
        // R_f / sqrt(tan beta) of the quoted expression (seed 003) has no value for spur teeth.
        return {form, {{"helix angle", 0.0, inf, true, "deg"}}, false};
    // changenet_velex_2007: the test ranges of the 2007 paper (h/D_p, b/D_p, V_0/D_p^3, Fr, Re)
    // could not be verified, so none is checked (docs/config.md). A gear under the oil
    // altogether is a plausibility warning of its own (solver/plausibility.cpp).
    return {form, {}, true};
}

namespace {
std::string number(double v) { return fmt::format("{:.4g}", v); }
std::string span(double lo, double hi) { return lo == hi ? number(lo) : number(lo) + "-" + number(hi); }
}  // namespace

std::string outside_range(const FittedRange& range, const std::vector<GivenSpan>& given) {
    std::string out;
    for (const auto& l : range.limits)
        for (const auto& g : given) {
            if (g.quantity != l.quantity) continue;
            const bool below = l.lo_open ? !(g.lo > l.lo) : !(g.lo >= l.lo);
            const bool above = !(g.hi <= l.hi);
            if (!below && !above) continue;
            const std::string unit = l.unit.empty() ? "" : " " + l.unit;
            const std::string limit = std::isinf(l.hi) ? fmt::format("{} {}", l.lo_open ? ">" : ">=", number(l.lo))
                                                       : span(l.lo, l.hi);
            out += fmt::format("{}{} {}{} given, {} {}{}", out.empty() ? "" : "; ", l.quantity, span(g.lo, g.hi), unit,
                               range.fitted ? "fitted" : "defined for", limit, unit);
        }
    return out;
}

}  // namespace gearloss::churning
