#pragma once
// The case's own `assumed:` list (docs/config.md, "Values the case declares assumed"): values the
// case gives but its writer assumed, e.g. the oil level and housing of a case written by
// `gearloss import` from a REXS model, which carries neither. Each entry names the value by its
// key path and gives the reason and who assumed it; the loader lists it with the values it
// assumes itself (Case::assumed), so `check` and the sidecars show both.
#include <string>
#include <vector>

#include "gearloss/case/config.hpp"
#include "gearloss/case/yaml_reader.hpp"

namespace gearloss::io {

// Reads `root`'s `assumed:` list (when present) into `out`: {key, value (as the case writes it),
// reason, location of the value, source}. A key path that names no value of the case, a missing
// reason or an entry that is not a mapping is an error at the entry.
// Key paths: mapping keys joined by '.', a list item by its `name` ("bearings.bearing_33.D",
// "housing.oil_level", "thermal.heat_rejection.housing.area", "operating.speeds"), relative to
// `root`; `prefix` goes before the key listed ("oil." for an oil file: "oil.density").
void read_declared_assumptions(const YamlNode& root, std::vector<AssumedValue>& out, const std::string& prefix = "");

}  // namespace gearloss::io
