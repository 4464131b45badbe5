#pragma once
// One issue found in a case description (gearloss/model/validate.hpp, the case reader, the loss
// mechanisms' own checks): where it comes from (section, item name, key), so that a reader
// of the case can point at its line, and what is wrong.
#include <string>

namespace gearloss {

struct Issue {
    std::string section;  // top-level key of the case description: "thermal", "bearings", "oil", "operating", ...
    std::string item;     // name of the list item ("B1_RMS11"); empty in a mapping section
    std::string key;      // key inside the item or section, dotted ("C0", "ambient", "heat_rejection.housing.area")
    std::string message;
    bool structural = false;   // an index or count that would make the analysis of the train fail (finalise() throws)
    std::string path() const;  // "bearings.B1_RMS11.C0", "thermal.ambient"
    std::string text() const;  // "bearings.B1_RMS11.C0: message"
};

// The name under which the validation (gearloss/model/validate.hpp) and its callers know it.
namespace solver {
using gearloss::Issue;
}

}  // namespace gearloss
