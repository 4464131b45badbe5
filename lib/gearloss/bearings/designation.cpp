#include "gearloss/bearings/designation.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

namespace gearloss::bearings {

namespace {
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

std::string suffix_text(std::string s) {
    while (!s.empty() && (s.front() == '-' || s.front() == '.' || s.front() == '/')) s.erase(s.begin());
    return s;
}
}  // namespace

std::optional<DesignationKey> designation_key(const std::string& text) {
    std::string s;  // upper case, no blanks; '.' and '-' start a suffix and are kept as marks
    // A blank after the first group that holds a digit ends the number: "6307 2Z" is 6307 with
    // the suffix 2Z (not 63072), while blanks after leading letters join them ("NU 2210").
    size_t number_end = std::string::npos;
    bool seen_digit = false;
    for (char c : text) {
        if (std::isspace(static_cast<unsigned char>(c))) {
            if (seen_digit && number_end == std::string::npos) number_end = s.size();
            continue;
        }
        seen_digit = seen_digit || digit(c);
        s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    size_t i = 0;
    while (i < s.size() && alpha(s[i])) ++i;
    DesignationKey k;
    k.prefix = s.substr(0, i);
    if (i == s.size() || !digit(s[i])) return std::nullopt;
    // Needle roller and cage assembly K Fw x Ew x Bc, drawn/machined NK Fw/B: the numbers are the size.
    if (k.prefix == "K" || k.prefix == "NK") {
        size_t j = i;
        const char sep = k.prefix == "K" ? 'X' : '/';
        int parts = 0;
        while (j < s.size()) {
            size_t start = j;
            while (j < s.size() && (digit(s[j]) || s[j] == '.' || s[j] == ',')) ++j;
            if (j == start) break;
            ++parts;
            if (j < s.size() && s[j] == sep && parts < (k.prefix == "K" ? 3 : 2)) ++j;
            else break;
        }
        k.number = s.substr(i, j - i);
        std::replace(k.number.begin(), k.number.end(), ',', '.');
        k.key = k.prefix + k.number;
        k.suffix = suffix_text(s.substr(j));
        return k;
    }
    const size_t end = std::min(s.size(), number_end);
    size_t j = i;
    while (j < end && digit(s[j])) ++j;
    k.number = s.substr(i, j - i);
    // 62/28, 320/28: the bore in mm after '/' follows a series code of two or three digits; after
    // a full basic number ("6307/2Z") the '/' starts a suffix.
    if (j < end && s[j] == '/' && j - i <= 3 && j + 1 < end && digit(s[j + 1])) {
        size_t e = j + 1;
        while (e < end && digit(s[e])) ++e;
        k.number = s.substr(i, e - i);
        j = e;
    }
    k.key = k.prefix + k.number;
    const std::string suffix = s.substr(j);
    k.suffix = suffix_text(suffix);
    // Angular contact ball bearings 72.., 73..: the contact angle letters are part of the size.
    if (k.prefix.empty() && k.number.size() == 4 && k.number[0] == '7' && (k.number[1] == '2' || k.number[1] == '3')) {
        if (suffix.rfind("AC", 0) == 0) k.key += "AC";
        else if (suffix.rfind("B", 0) == 0) k.key += "B";
        else if (suffix.rfind("A", 0) == 0) k.key += "A";
    }
    // Tapered 322../323.. B: steeper cup angle, other ratings and constants.
    if (k.prefix.empty() && k.number.size() == 5 && (k.number.rfind("322", 0) == 0 || k.number.rfind("323", 0) == 0) &&
        suffix.rfind("B", 0) == 0)
        k.key += "B";
    return k;
}

std::optional<std::string> suffix_contradiction(const DesignationKey& k) {
    const std::string& n = k.number;
    const bool deep_groove = k.prefix.empty() && ((n.size() == 4 && n[0] == '6') || (n.size() == 5 && n.rfind("160", 0) == 0));
    if (!deep_groove) return std::nullopt;
    size_t letters = 0;
    while (letters < k.suffix.size() && alpha(k.suffix[letters])) ++letters;
    const std::string code = k.suffix.substr(0, letters);
    // SKF (2018) designation system: A, AC, B (BE, BEP, BECBM...) and CD give the contact angle of
    // 72../73.. angular contact ball bearings; no deep groove ball bearing carries them.
    const bool angle_code = code == "A" || code == "CD" || code.rfind("AC", 0) == 0 || code.rfind("B", 0) == 0;
    if (!angle_code) return std::nullopt;
    const std::string example = n.size() == 4 ? " (e.g. 73" + n.substr(2) + " " + code + ")" : "";
    return "'" + k.suffix + "' is a contact-angle suffix of angular contact ball bearings (72.., 73..), but " + k.number +
           " is a deep groove ball bearing: no such bearing; write the angular contact designation" + example +
           " or the deep groove one without it";
}

SuffixSeal suffix_seal(const std::string& suffix) {
    // Maker codes, most specific first (2RSL, a low-friction non-contact lip, before RS).
    // SKF (2018): Z/2Z shields, RZ/2RZ and RSL/2RSL non-contact, RS1/RSH/2RS1/2RSH contact;
    // Schaeffler (2005): 2RSR contact, 2Z; NTN (2002): LLU contact, LLB non-contact, ZZ; LS/2LS
    // contact seals of cylindrical roller bearings.
    static const std::vector<std::pair<std::string, SuffixSeal>> codes = {
        {"2RSL", {SuffixSeal::shield, "", ""}},  {"RSL", {SuffixSeal::shield, "", ""}},
        {"2RZ", {SuffixSeal::shield, "", ""}},   {"RZ", {SuffixSeal::shield, "", ""}},
        {"2RS1", {SuffixSeal::contact, "", "RS1"}}, {"2RSH", {SuffixSeal::contact, "", "RS1"}},
        {"2RSR", {SuffixSeal::contact, "", "RS1"}}, {"RS1", {SuffixSeal::contact, "", "RS1"}},
        {"RSH", {SuffixSeal::contact, "", "RS1"}},  {"2RS", {SuffixSeal::contact, "", "RS1"}},
        {"RS", {SuffixSeal::contact, "", "RS1"}},   {"LLU", {SuffixSeal::contact, "", "RS1"}},
        {"DDU", {SuffixSeal::contact, "", "RS1"}},  {"2LS", {SuffixSeal::contact, "", "LS"}},
        {"LLB", {SuffixSeal::shield, "", ""}},   {"2Z", {SuffixSeal::shield, "", ""}},
        {"ZZ", {SuffixSeal::shield, "", ""}},
    };
    for (const auto& [token, kind] : codes)
        if (suffix.find(token) != std::string::npos) {
            SuffixSeal r = kind;
            r.token = token;
            return r;
        }
    // A lone Z (one shield) only as the whole suffix or its start: "ZNR", not the Z of "ECP-Z..." guesses.
    if (suffix == "Z" || suffix.rfind("Z", 0) == 0) return {SuffixSeal::shield, "Z", ""};
    return {};
}

std::optional<std::string> skf_series_of_designation(const std::string& text) {
    const auto k = designation_key(text);
    if (!k) return std::nullopt;
    const std::string& n = k->number;
    if (k->prefix == "K" || k->prefix == "NK" || k->prefix == "NKI" || k->prefix == "NA") return std::string("other");
    if (n.find('/') != std::string::npos) return std::nullopt;
    if (k->prefix == "QJ") return std::string("QJ");
    if (k->prefix == "N" || k->prefix == "NU" || k->prefix == "NJ" || k->prefix == "NUP") {
        if (n.size() == 3) return n.substr(0, 1);  // NJ 406 -> 4
        if (n.size() == 4) return n.substr(0, 2);  // NU 2210 -> 22
        return std::nullopt;
    }
    if (!k->prefix.empty()) return std::nullopt;
    if (n.size() == 4 && n[0] == '7') {
        const std::string angle = k->key.substr(4);
        if (angle.empty()) return std::nullopt;
        return n.substr(0, 2) + angle;
    }
    if (n.size() == 4 && n[0] == '6') return n.substr(0, 2);  // 6307 -> 63
    if (n.size() == 5 && n.rfind("160", 0) == 0) return std::string("160");
    if (n.size() == 5 && n[0] == '3') {
        const std::string s = n.substr(0, 3);
        if (s == "320") return std::string("320X");
        return s + k->key.substr(5);  // 32306 -> 323, 32306 B -> 323B
    }
    return std::nullopt;
}

int key_distance(const std::string& a, const std::string& b) {
    std::vector<int> prev(b.size() + 1), cur(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) prev[j] = static_cast<int>(j);
    for (size_t i = 1; i <= a.size(); ++i) {
        cur[0] = static_cast<int>(i);
        for (size_t j = 1; j <= b.size(); ++j)
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

}  // namespace gearloss::bearings
