#pragma once
// The codes of a rolling-bearing designation's suffix ("6210-2Z/C3", "NJ 309 ECP", "7308 BECBP",
// "6207-E-XL-TVP2", "32306 J2/Q"), each with what it says and whether the SKF (2004) friction
// model has a term for it. Source of the codes: the SKF (2018) designation system; the maker codes
// of other makers (2RSR, 2ZR, TVP2, XL; LLU, LLB) as in designation.cpp (Schaeffler (2005),
// NTN (2002)).
#include <string>
#include <vector>

#include "gearloss/bearings/designation.hpp"

namespace gearloss::bearings {

struct SuffixCode {
    enum Kind {
        contact_seal,  // rubs: the SKF (2004) seal moment applies (suffix_seal)
        shield,        // shield or non-contact seal: no seal friction
        cage,
        clearance,     // radial internal clearance class
        design,        // internal design (E, EC, X-life, Q): same boundary dimensions
        matching,      // universally matchable / matched set (CB, DB, DF, DT)
        tolerance,     // tolerance class (P6, P5, SP)
        stabilised,    // dimensional stabilisation for high temperature (S0..S4)
        grease,        // grease fill of a sealed bearing
        rings,         // ring features: snap ring groove, tapered bore, lubrication holes
        hybrid,        // ceramic rolling elements
        unknown        // not understood
    } kind = unknown;
    std::string code;     // as written, upper case: "2Z", "C3", "TVP2", "ECP" splits into "EC" and "P"
    std::string meaning;  // what the code says (empty when unknown)
};

// The suffix of `k` (DesignationKey::suffix) as its codes, in order. The contact-angle letters
// the key keeps (7308 B..., 32322 B) are not repeated. Separators '-', '/', '.' split the
// suffix; within a part the reading with the fewest characters not understood (then the
// fewest codes) is taken, so "BECBP" after 7308 B is E, CB, P and "ECP" is EC, P.
std::vector<SuffixCode> decode_suffix(const DesignationKey& k);

// "cage", "clearance", ... for messages.
const char* to_string(SuffixCode::Kind k);

}  // namespace gearloss::bearings
