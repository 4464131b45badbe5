#pragma once
// One quantity over the operating points of a case as an inline SVG picture: a heat map of
// the speed x torque grid (each computed point at the centre of its cell, marked by its value
// printed in the cell where it fits, else by a dot), contour lines at the colour bar's ticks,
// the colour bar with its unit, axis labels, and a legend for the points without values (no
// equilibrium, out of range) and those above the oil's permissible temperature. A point list
// (no grid) is drawn as coloured dots.
// Colours: a sequential scale for a quantity, a diverging one for a difference, with red
// always meaning worse and blue better (ColourSense).
#include <string>
#include <utility>
#include <vector>

namespace gearloss::report {

// The operating points in display units, in grid order (speed outer, torque inner).
struct MapAxes {
    std::vector<double> speeds_rpm, torques_Nm;    // the grid's axes (is_grid)
    std::vector<std::pair<double, double>> points;  // (rpm, N*m) of every point
    bool is_grid = true;
};

enum class CellState { value, above_oil_limit, no_equilibrium, out_of_range };

// How the colours read: a plain quantity (sequential), or a difference whose positive values
// are worse (more loss, hotter oil: red) or better (more efficiency: blue).
enum class ColourSense { sequential, higher_is_worse, higher_is_better };

struct MapField {
    std::string title;   // above the picture
    std::string unit;    // of the colour bar ("W", "%", "degC")
    ColourSense sense = ColourSense::sequential;
    std::vector<double> values;     // per point; NaN = no value
    std::vector<CellState> states;  // per point
    std::string id;                 // the <svg>'s id (unique in the page)
    int label_digits = 3;           // significant digits of the printed values (map_values.hpp)
};

// The picture (an <svg> element). Titles and units are escaped here. Each cell of a grid
// carries its value as a label when every label fits in its cell (cell_labels_shown);
// otherwise the page prints a table beside the picture (map_values.hpp).
std::string svg_map(const MapAxes& axes, const MapField& field);

// Whether svg_map prints the values in the cells of this picture.
bool cell_labels_shown(const MapAxes& axes, const MapField& field);

// The fill patterns the pictures refer to (no equilibrium, out of range): one hidden <svg>
// to be placed once in the page before the maps.
std::string svg_pattern_defs();

// The colour of a value at position t in [0, 1] of a scale (viridis for sequential; for a
// difference, t = 0.5 is zero: white; red towards worse, blue towards better): "#rrggbb".
std::string scale_colour(ColourSense sense, double t);

// Ticks at "nice" steps (1, 2, 5 x 10^k) inside [lo, hi]; about `count` of them.
std::vector<double> nice_ticks(double lo, double hi, int count);

}  // namespace gearloss::report
