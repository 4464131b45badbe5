#pragma once
// `gearloss point --json`: one operating point as JSON (docs/outputs.md "point --json"):
// inputs, status, temperatures, the oil state, every mechanism's loss with its components
// (the quantities of its --detail columns), efficiency, films, and the point's map row
// (the cells `map --detail` writes for it, by column name), with the sidecar's metadata.
#include <nlohmann/json.hpp>

#include "gearloss/case/config.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::map {

// `r` is solved with detail (solver::solve_point(..., true)); `metadata` is the sidecar
// document of the run (output_metadata), stored under "metadata".
nlohmann::ordered_json point_json(const io::Case& c, const solver::PointResult& r, nlohmann::ordered_json metadata);

// The cells of a CSV row by column name: numbers as numbers, empty cells as null, text as text.
nlohmann::ordered_json row_object(const std::string& header_line, const std::string& row_line);

}  // namespace gearloss::map
