#include "gearloss/bearings/designation.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

namespace gearloss::bearings {

namespace {
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
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
        return k;
    }
    const size_t end = std::min(s.size(), number_end);
    size_t j = i;
    while (j < end && digit(s[j])) ++j;
    k.number = s.substr(i, j - i);
    if (j < end && s[j] == '/' && j + 1 < end && digit(s[j + 1])) {  // 62/28: bore in mm after '/'
        size_t e = j + 1;
        while (e < end && digit(s[e])) ++e;
        k.number = s.substr(i, e - i);
        j = e;
    }
    k.key = k.prefix + k.number;
    const std::string suffix = s.substr(j);
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
