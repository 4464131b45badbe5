#pragma once
// Rolling-bearing designations as catalogues print them (ISO 15 / ISO 355 basic designations
// with maker's suffixes): "6307-2RS1", "NJ 309 ECP", "32306 J2/Q", "7308 BECBP", "QJ 308 N2MA",
// "K 38x43x27", "NK 25/20". The key drops spaces, case and the suffixes that do not change the
// boundary dimensions (seals, cage, clearance, E design), and keeps those that do: the contact
// angle letters of an angular contact ball bearing (B = 40 deg, AC = 25 deg, A = 30 deg) and
// B (steep angle) of a 322/323 tapered roller bearing. "NJ 309 E" and "NJ 309 ECP" share a key.
// Accepted forms: letters and number with or without a blank ("NU 2210", "NU2210"); the suffix
// after '-', '.', '/' (tapered "J2/Q"), letters, or a blank ("6307 2Z", "6307 2RS1", "6307 Z":
// a blank after the number ends it, so these are 6307, not 63072); "62/28" (bore after '/' when
// at most three digits precede it; "6307/2Z" is 6307 with the suffix 2Z);
// K Fw x Ew x Bc and NK / NKI Fw / B as their sizes.
#include <optional>
#include <string>

namespace gearloss::bearings {

struct DesignationKey {
    std::string key;      // "NJ309", "6307", "7308B", "32306", "K38X43X27", "NK25/20"
    std::string prefix;   // letters before the number: "NJ", "QJ", "K", "" ...
    std::string number;   // the series and bore digits: "309", "6307"
    std::string suffix;   // what follows, upper case, blanks and a leading '-', '.' or '/' dropped: "2RS1", "BECBP"
};

// nullopt when the text does not look like a designation (no digits after the letters).
std::optional<DesignationKey> designation_key(const std::string& text);

// A suffix that names another kind of bearing than the basic designation: the contact angle
// codes of angular contact ball bearings (A, AC, B, BE..., CD) after a deep groove ball bearing
// ("6307 BE"). Such a designation does not exist and the row it would resolve to is not the one
// meant. nullopt when the suffix does not contradict the basic designation.
std::optional<std::string> suffix_contradiction(const DesignationKey& k);

// What a designation suffix says about integral seals: contact seals rub (SKF 2004 seal moment),
// shields and non-contact seals do not. `token` is the code found ("2RS1", "LLU", "2Z"), `code`
// the seal row of gearloss's `seals:` key it stands for ("RS1", "LS"; "" for no contact).
struct SuffixSeal {
    enum Kind { none, shield, contact } kind = none;
    std::string token, code;
};
SuffixSeal suffix_seal(const std::string& suffix);

// The SKF (2004) series code of a designation for the constants table (skf_constants.hpp):
// "NJ 406" -> "4", "NU 2210 E" -> "22", "6307" -> "63", "32306" -> "323", "7308 BE" -> "73B",
// "QJ 308" -> "QJ"; nullopt when unknown.
std::optional<std::string> skf_series_of_designation(const std::string& text);

// Edit distance of two keys (for "did you mean" suggestions).
int key_distance(const std::string& a, const std::string& b);

}  // namespace gearloss::bearings
