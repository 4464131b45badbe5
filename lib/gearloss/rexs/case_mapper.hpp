#pragma once
// A REXS model (gearloss/rexs/model.hpp) as a gearloss case (docs/config.md), as YAML text:
// cylindrical gear stages (spur and helical, external and internal gears, any number of stages
// and shafts, idlers), planetary stages (sun, identical planets, ring, carrier), the shafts and the positions of the gears and bearings on them (REXS u
// coordinates), the bearings (by catalogue designation when the shipped catalogue has it, else
// assumed bearings of the bore the model gives), the lubricant as an oil file, the operating
// points of the load spectrum, and assumed values with their reasons for what REXS does not carry
// (oil level, oil volume, housing surface). Every imported value's line carries a comment naming
// the REXS component id and attribute it came from. docs/rexs.md lists what is mapped, assumed and
// refused.
//
// Refused (InputError naming the component id, type and name): worm, bevel, hypoid and
// crossed-axis stages, planetary stages gearloss's planetary set cannot hold (stepped or double
// planets, unequal planets, a stage without its carrier), shafts whose axes are not parallel, a
// stage whose shafts are not its centre distance apart, a bearing outside its shaft, teeth whose
// left and right flanks differ.
#include <string>
#include <vector>

#include "gearloss/rexs/model.hpp"

namespace gearloss::rexs {

struct ImportOptions {
    // What the case's `oil:` key names: a path relative to the case file.
    std::string oil_reference;
    // True: the model's lubricant is written as the oil file (ImportResult::oil_yaml). False: the
    // case refers to an oil file given by the user (the model's lubricant is not used).
    bool write_oil = true;
};

struct ImportResult {
    std::string case_yaml;
    std::string oil_yaml;               // empty when ImportOptions::write_oil is false
    std::vector<std::string> warnings;  // "component 33 (...): ..." for what was mapped with a caveat
};

ImportResult map_to_case(const Model& m, const ImportOptions& options);

}  // namespace gearloss::rexs
