#pragma once
// The values of a map printed in the page, so that they read without hovering and on paper:
// a label in each cell of the picture when every label fits in its cell (svg_map draws them),
// otherwise a table under the picture. The table of a large grid shows an evenly spread subset
// of its speeds and torques (the first and last kept) so that it stays readable on a printed
// page; it says so, and the embedded data hold every value.
#include <cstddef>
#include <string>
#include <vector>

#include "gearloss/report/svg_map.hpp"

namespace gearloss::report {

// Most speeds (columns) and torques (rows) of a value table, and rows of a point list's table.
inline constexpr size_t kTableSpeeds = 12, kTableTorques = 16, kTableRows = 40;

// A cell's printed value: `digits` significant digits in fixed notation, at most 3 decimals
// ("97.84", "393.7", "1234", "0.012"); empty for a value that is not a finite number.
std::string label_text(double v, int digits);

// Whether every cell of a grid picture has room for its label (a point list never has).
// `cell_w`, `cell_h`: the smallest cell of the picture [px].
bool labels_fit(const MapField& f, double cell_w, double cell_h);

// The table of a field's values (empty when the picture carries its labels).
std::string values_table(const MapAxes& axes, const MapField& f);

// `count` indices spread evenly over 0..n-1, both ends kept (all of them when n <= count).
std::vector<size_t> even_indices(size_t n, size_t count);

}  // namespace gearloss::report
