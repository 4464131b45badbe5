#pragma once
// Design-space sweeps: `sweep:` in a case lists named parameters (paths into the case
// document: `oil`, `housing.oil_level`, `gears.w1.face_width` with list items picked by
// their `name`) and the values each takes; `map` runs the cartesian product of all
// axes, each variant a full case re-read with its values.
#include <string>
#include <vector>

#include "gearloss/io/config.hpp"

namespace gearloss::io {

// Reads and checks the `sweep` block of a case document (every path must exist). Empty
// when there is none.
std::vector<SweepAxis> read_sweep(const YamlNode& root);

struct SweepVariant {
    std::vector<std::string> values;  // one per axis
    Case c;
};

// Every combination (first axis slowest), each loaded as a case; `ratio` as load_case.
std::vector<SweepVariant> expand_sweep(const std::string& file, const std::optional<std::string>& ratio);

// CSV cell for a value (quoted when it holds a comma or a quote).
std::string csv_cell(const std::string& s);

}  // namespace gearloss::io
