#pragma once
// Model-form spread (`map --spread`): the same operating grid solved with every combination
// of the mechanisms' alternative forms (friction law, H_V model, film correction, windage
// form, ...), so a user sees how much of a prediction rests on a choice between published
// models rather than on the gearbox and its oil.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "gearloss/case/config.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/model/model.hpp"

namespace gearloss::map {

// One axis of alternative forms of one mechanism ("mesh.friction": schlenk, iso_6336_20, ...).
struct SpreadAxis {
    size_t mechanism = 0;             // index in Model::mechanisms
    std::string mechanism_name;       // "mesh"
    std::string axis;                 // the mechanism's axis name
    std::vector<std::string> forms;   // every form of the axis
    std::string nominal;              // the form the case selects
    std::string label() const;        // "mesh.friction"
};

// Every axis with more than one form, in the mechanisms' order; `only` (labels such as
// "mesh.friction", "windage.form") restricts them. An unknown label is an InputError
// naming `option` and listing the axes.
std::vector<SpreadAxis> spread_axes(const solver::Model& m, const std::vector<std::string>& only,
                                    const std::string& option = "--spread-axes");

// The combinations of a set of axes: their count, and the model of combination i (forms
// chosen in mixed radix, the first axis fastest).
size_t combination_count(const std::vector<SpreadAxis>& axes);
solver::Model combination_model(const solver::Model& nominal, const std::vector<SpreadAxis>& axes, size_t i);
// "mesh.friction=iso_6336_20;windage.form=free_disk": the forms of combination i that differ
// from the case's, or "nominal" when none does.
std::string combination_label(const std::vector<SpreadAxis>& axes, size_t i);

// The spread of the total loss at one point over the combinations that solve it.
struct PointSpread {
    double P_min = 0, P_max = 0;   // W
    size_t at_min = 0, at_max = 0; // combination indices
    size_t solved = 0;             // combinations with values at this point
    size_t unsolved = 0;           // combinations without (no equilibrium, out of range)
};

// A combination whose forms do not apply to this case: validate() reports an issue of it
// that the case's own forms do not have (Ohlendorf's H_V on a mesh with eps_alpha >= 2).
// It is not solved, and counts neither as solved nor as unsolved at any point.
struct NotApplicable {
    size_t combination = 0;
    std::string reason;  // the first such issue's message
};
std::vector<NotApplicable> not_applicable_combinations(const solver::Model& m, const std::vector<SpreadAxis>& axes);
// "72 of 108 form combinations do not apply to this case and are not solved (first:
// mesh.loss_factor=ohlendorf: ...)", or empty when every combination applies.
std::string not_applicable_note(const std::vector<SpreadAxis>& axes, const std::vector<NotApplicable>& skipped);

// The spread of every point of the grid, and the combinations left out.
struct SpreadResult {
    std::vector<PointSpread> points;           // per grid point
    std::vector<NotApplicable> not_applicable; // in combination order
};

// Combinations above this count need `--spread-axes` (the map's cost grows with them);
// require_spread_size throws the InputError (run_spread calls it too).
inline constexpr size_t kMaxSpreadCombinations = 512;
void require_spread_size(const std::vector<SpreadAxis>& axes);

// Solves the grid once per applicable combination (each with its own oil temperature when the
// case is thermally coupled), keeping only each point's running minimum and maximum, so memory
// does not grow with the number of combinations. Stops early after SIGINT like run_map.
SpreadResult run_spread(const solver::Model& m, const io::OperatingGrid& grid, const std::vector<SpreadAxis>& axes,
                        const MapOptions& opt);

// The CSV columns the spread adds after the map's ("P_total_min_W,...") and their cells for
// a point (empty cells when no combination solved it).
std::string spread_csv_header();
std::string spread_csv_cells(const std::vector<SpreadAxis>& axes, const PointSpread& s);

// The JSON summary's "spread" member: the axes, the combination count, the combinations that
// do not apply to the case (count and labels), the points some combination could not solve,
// and the widest spread relative to the nominal loss.
void spread_summary_json(nlohmann::ordered_json& j, const std::vector<SpreadAxis>& axes, const SpreadResult& spread,
                         const std::vector<solver::PointResult>& nominal);

}  // namespace gearloss::map
