// Suffix codes of rolling-bearing designations (designation_suffix.hpp).
#include "gearloss/bearings/designation_suffix.hpp"

#include <cctype>
#include <limits>

namespace gearloss::bearings {
namespace {

struct Known {
    const char* code;
    SuffixCode::Kind kind;
    const char* meaning;
    bool digits;  // digits that follow belong to the code (C3, TN9, J2, MT33, W33)
};

using K = SuffixCode;
// SKF (2018) designation system; Schaeffler (2005); NTN (2002) for LLU/LLB/ZZ/DDU.
const Known kCodes[] = {
    // Seals and shields (the same codes as suffix_seal, designation.cpp).
    {"2RS1", K::contact_seal, "contact seals on both sides", false},
    {"2RSH", K::contact_seal, "contact seals on both sides", false},
    {"2RSR", K::contact_seal, "contact seals on both sides (Schaeffler)", false},
    {"2RS", K::contact_seal, "contact seals on both sides", false},
    {"RS1", K::contact_seal, "a contact seal on one side", false},
    {"RSH", K::contact_seal, "a contact seal on one side", false},
    {"RS", K::contact_seal, "a contact seal on one side", false},
    {"LLU", K::contact_seal, "contact seals on both sides (NTN)", false},
    {"DDU", K::contact_seal, "contact seals on both sides (NSK)", false},
    {"2LS", K::contact_seal, "contact seals on both sides (cylindrical roller bearing)", false},
    {"2RSL", K::shield, "low-friction non-contact seals on both sides", false},
    {"RSL", K::shield, "a low-friction non-contact seal on one side", false},
    {"2RZ", K::shield, "non-contact seals on both sides", false},
    {"RZ", K::shield, "a non-contact seal on one side", false},
    {"LLB", K::shield, "non-contact seals on both sides (NTN)", false},
    {"2ZR", K::shield, "shields on both sides (Schaeffler)", false},
    {"2Z", K::shield, "shields on both sides", false},
    {"ZZ", K::shield, "shields on both sides", false},
    {"ZR", K::shield, "a shield on one side (Schaeffler)", false},
    {"Z", K::shield, "a shield on one side", false},
    // Cages.
    {"J", K::cage, "pressed steel cage", true},
    {"JN", K::cage, "sheet steel cage (Schaeffler)", false},
    {"M", K::cage, "machined brass cage", false},
    {"MA", K::cage, "machined brass cage, outer ring centred", false},
    {"MB", K::cage, "machined brass cage, inner ring centred", false},
    {"ML", K::cage, "one-piece machined brass window cage", false},
    {"MP", K::cage, "machined brass window cage", false},
    {"P", K::cage, "glass fibre reinforced polyamide 66 cage", false},
    {"PH", K::cage, "PEEK cage", false},
    {"PHA", K::cage, "PEEK cage, outer ring centred", false},
    {"TN", K::cage, "polyamide 66 cage", true},
    {"TNH", K::cage, "glass fibre reinforced PEEK cage", false},
    {"TVP", K::cage, "glass fibre reinforced polyamide 66 cage (Schaeffler)", true},
    {"TVH", K::cage, "glass fibre reinforced polyamide 66 cage (Schaeffler)", false},
    {"Y", K::cage, "pressed brass cage", false},
    {"F", K::cage, "machined steel cage", false},
    {"V", K::cage, "full complement (no cage)", false},
    // Internal clearance.
    {"C2", K::clearance, "radial internal clearance smaller than Normal", false},
    {"CN", K::clearance, "Normal radial internal clearance", false},
    {"C3", K::clearance, "radial internal clearance larger than Normal", false},
    {"C4", K::clearance, "radial internal clearance larger than C3", false},
    {"C5", K::clearance, "radial internal clearance larger than C4", false},
    // Internal design (same boundary dimensions).
    {"E", K::design, "optimised internal design (more or larger rolling elements)", false},
    {"EC", K::design, "optimised internal design with a modified roller end and flange contact", false},
    {"X", K::design, "boundary dimensions or internal design changed to the ISO standard", false},
    {"XL", K::design, "X-life (Schaeffler): higher rating from material and finish", false},
    {"Q", K::design, "optimised contact geometry and surface finish (tapered roller bearing)", false},
    {"A", K::design, "a modified internal design", false},
    // Matching for paired mounting.
    {"CA", K::matching, "universally matchable, small axial clearance", false},
    {"CB", K::matching, "universally matchable, Normal axial clearance", false},
    {"CC", K::matching, "universally matchable, large axial clearance", false},
    {"GA", K::matching, "universally matchable, light preload", false},
    {"GB", K::matching, "universally matchable, moderate preload", false},
    {"DB", K::matching, "a matched pair back-to-back: imported as one bearing", false},
    {"DF", K::matching, "a matched pair face-to-face: imported as one bearing", false},
    {"DT", K::matching, "a matched pair in tandem: imported as one bearing", false},
    // Tolerance classes.
    {"P6", K::tolerance, "ISO tolerance class 6", false},
    {"P5", K::tolerance, "ISO tolerance class 5", false},
    {"P4", K::tolerance, "ISO tolerance class 4", false},
    {"P2", K::tolerance, "ISO tolerance class 2", false},
    {"PN", K::tolerance, "Normal tolerance class", false},
    {"SP", K::tolerance, "special precision", false},
    {"UP", K::tolerance, "ultra precision", false},
    // Heat stabilisation.
    {"S0", K::stabilised, "rings stabilised for up to 150 degC", false},
    {"S1", K::stabilised, "rings stabilised for up to 200 degC", false},
    {"S2", K::stabilised, "rings stabilised for up to 250 degC", false},
    // Grease fills.
    {"GJN", K::grease, "grease fill (polyurea)", false},
    {"HT", K::grease, "high-temperature grease fill", true},
    {"LT", K::grease, "low-temperature grease fill", true},
    {"MT", K::grease, "grease fill", true},
    {"WT", K::grease, "wide-temperature grease fill", false},
    {"GWB", K::grease, "grease fill", false},
    // Rings.
    {"N", K::rings, "snap ring groove in the outer ring", false},
    {"NR", K::rings, "snap ring groove with its snap ring", false},
    {"K", K::rings, "tapered bore 1:12", false},
    {"K30", K::rings, "tapered bore 1:30", false},
    {"W", K::rings, "lubrication groove and holes in the outer ring", true},
    // Rolling elements.
    {"HC", K::hybrid, "ceramic rolling elements (hybrid bearing)", true},
};

struct Match {
    size_t length = 0;
    const Known* known = nullptr;
};

// Every code that starts `s` at `pos` (with the digits it takes).
std::vector<Match> matches_at(const std::string& s, size_t pos) {
    std::vector<Match> out;
    for (const Known& k : kCodes) {
        const std::string c = k.code;
        if (s.compare(pos, c.size(), c) != 0) continue;
        size_t len = c.size();
        if (k.digits)
            while (pos + len < s.size() && std::isdigit(static_cast<unsigned char>(s[pos + len]))) ++len;
        out.push_back({len, &k});
    }
    return out;
}

// One part (no separator): the reading with the fewest characters not understood, then the
// fewest codes (dynamic programming over the positions).
void decode_part(const std::string& s, std::vector<SuffixCode>& out) {
    const size_t n = s.size();
    constexpr long inf = std::numeric_limits<long>::max() / 4;
    std::vector<long> cost(n + 1, inf);
    std::vector<Match> step(n + 1);  // how position i is left: a match, or one unknown character
    cost[n] = 0;
    for (size_t i = n; i-- > 0;) {
        cost[i] = 1000 + cost[i + 1];  // one character not understood
        step[i] = {1, nullptr};
        for (const Match& m : matches_at(s, i))
            if (1 + cost[i + m.length] < cost[i]) {
                cost[i] = 1 + cost[i + m.length];
                step[i] = m;
            }
    }
    std::string unknown;
    for (size_t i = 0; i < n;) {
        const Match& m = step[i];
        if (!m.known) {
            unknown += s[i];
        } else {
            if (!unknown.empty()) out.push_back({SuffixCode::unknown, unknown, ""});
            unknown.clear();
            out.push_back({m.known->kind, s.substr(i, m.length), m.known->meaning});
        }
        i += m.length;
    }
    if (!unknown.empty()) out.push_back({SuffixCode::unknown, unknown, ""});
}

}  // namespace

std::vector<SuffixCode> decode_suffix(const DesignationKey& k) {
    std::string s = k.suffix;
    // Letters the key keeps after the number (7308 B, 7308 AC, 32322 B) are the basic designation's.
    const std::string kept = k.key.substr(std::min(k.key.size(), k.prefix.size() + k.number.size()));
    if (!kept.empty() && s.rfind(kept, 0) == 0) s.erase(0, kept.size());
    std::vector<SuffixCode> out;
    std::string part;
    for (size_t i = 0; i <= s.size(); ++i) {
        if (i == s.size() || s[i] == '-' || s[i] == '/' || s[i] == '.') {
            if (!part.empty()) decode_part(part, out);
            part.clear();
        } else {
            part += s[i];
        }
    }
    return out;
}

const char* to_string(SuffixCode::Kind k) {
    switch (k) {
        case SuffixCode::contact_seal: return "contact seal";
        case SuffixCode::shield: return "shield";
        case SuffixCode::cage: return "cage";
        case SuffixCode::clearance: return "clearance";
        case SuffixCode::design: return "internal design";
        case SuffixCode::matching: return "matching";
        case SuffixCode::tolerance: return "tolerance";
        case SuffixCode::stabilised: return "heat stabilisation";
        case SuffixCode::grease: return "grease";
        case SuffixCode::rings: return "rings";
        case SuffixCode::hybrid: return "rolling elements";
        case SuffixCode::unknown: break;
    }
    return "not understood";
}

}  // namespace gearloss::bearings
