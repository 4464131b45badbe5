#include "gearloss/churning/fitted_range.hpp"

#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace gearloss::churning {

FittedRange fitted_range(const std::string& form) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (form == "heingartner_mba_2003")
        // R_f / sqrt(tan beta) of the quoted expression (seed 003) has no value for spur teeth.
        return {form, {{"helix angle", 0.0, inf, true, "deg"}}, false,
                "where the quoted expression has a value; the range of the data it was fitted on is not stated in "
                "a verified source"};
    if (form == "mauz_1987")
        // Pitch-line speeds up to 60 m/s: the range in the title of Mauz's thesis (1987) as cited in
        // secondary sources; the immersion and face-width ranges of its tests are not quoted there.
        return {form, {{"pitch-line speed", 0.0, 60.0, false, "m/s"}}, true,
                "speed range as quoted in secondary sources (Mauz 1987: up to 60 m/s), not checked against the ISO/TR "
                "text; immersion and face-width ranges not stated in a verified source"};
    // changenet_velex_2007: the test ranges of the 2007 paper (h/D_p, b/D_p, V_0/D_p^3, Fr, Re)
    // could not be verified, so none is checked (docs/config.md). A gear under the oil
    // altogether is a plausibility warning of its own (solver/plausibility.cpp).
    return {form, {}, true, "not stated in a verified source (h/D, b/D, V0/D^3, Fr, Re not checked)"};
}

namespace {
std::string number(double v) { return fmt::format("{:.4g}", v); }
std::string span(double lo, double hi) { return lo == hi ? number(lo) : number(lo) + "-" + number(hi); }
}  // namespace

std::string describe_limits(const FittedRange& range) {
    std::string out;
    for (const auto& l : range.limits) {
        const std::string unit = l.unit.empty() ? "" : " " + l.unit;
        const std::string limit = std::isinf(l.hi) ? fmt::format("{} {}", l.lo_open ? ">" : ">=", number(l.lo))
                                                   : span(l.lo, l.hi);
        out += fmt::format("{}{} {}{}", out.empty() ? "" : "; ", l.quantity, limit, unit);
    }
    return out.empty() ? "none checked" : out;
}

std::string coefficient_provenance(const std::string& form) {
    if (form == "mauz_1987")
        return "coefficients as quoted in secondary sources, not checked against the ISO/TR text; the definitions of "
               "h_c and l_h are not verified; no oil property enters the form";
    if (form == "heingartner_mba_2003")
        return "as quoted by Gillot, Picarelli & Dempsey (units and R_f, A_g not stated there)";
    return {};
}

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
