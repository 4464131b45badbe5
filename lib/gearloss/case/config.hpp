#pragma once
// YAML case description -> solver::Model + operating grid (docs/config.md).
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gearloss/case/bearing_catalogue.hpp"
#include "gearloss/case/yaml_reader.hpp"
#include "gearloss/model/model.hpp"
#include "gearloss/torque_converter/torque_converter.hpp"
#include "gearloss/vehicle/vehicle.hpp"

namespace gearloss::io {

struct OperatingGrid {
    // Either a speeds x torques grid (speed outer, torque inner) or a point list.
    std::vector<double> speeds, torques;             // rad/s, N*m
    std::vector<std::pair<double, double>> points;   // (rad/s, N*m)
    bool is_grid = true;
    size_t size() const { return is_grid ? speeds.size() * torques.size() : points.size(); }
    std::pair<double, double> at(size_t i) const {
        if (!is_grid) return points[i];
        return {speeds[i / torques.size()], torques[i % torques.size()]};
    }
};

// One axis of a design-space sweep (gearloss/case/sweep.hpp).
struct SweepAxis {
    std::string label;               // CSV column name (the first path)
    std::vector<std::string> paths;  // set together (e.g. both gears of a mesh)
    std::vector<std::string> values; // YAML scalars as written ("3.75 mm", "oils/75W140-A.yaml")
};

// A physical value (or a choice) the loader assumed because the case did not give it, so
// that outputs can say what they rest on (the `assumed` list of FILE.meta.json, docs/outputs.md).
struct AssumedValue {
    AssumedValue() = default;
    AssumedValue(std::string key_, std::string value_, std::string reason_, std::string location_, std::string source_ = {})
        : key(std::move(key_)), value(std::move(value_)), reason(std::move(reason_)), location(std::move(location_)),
          source(std::move(source_)) {}
    std::string key;       // key path as a case would write it: "oil.X_L", "bearings.B1.mu_ehl"
    std::string value;     // as a case would write it, with its unit: "0.8", "95 degC", "20 deg"
    std::string reason;    // where the value comes from (the default's source)
    std::string location;  // "file:line:col" of the block that omits the key, or empty
    // Who assumed it: empty for the case loader; the `source` of an entry of the case's own
    // `assumed:` list ("REXS import"), which names values the case gives but its writer assumed.
    std::string source;
};

struct Case {
    std::string file;
    solver::Model model;
    OperatingGrid grid;
    std::optional<vehicle::Vehicle> vehicle;  // for `gearloss cycle`
    std::optional<torque_converter::TorqueConverter> torque_converter;
    std::vector<SweepAxis> sweep;  // `sweep:` axes (map runs every combination; gearloss/case/sweep.hpp)
    // Plausibility findings ("file:line:col: key: warning: ..."), printed by every
    // command on stderr and listed by `check`.
    std::vector<std::string> warnings;
    std::string oil_temperature_key;  // "file:line:col: thermal.oil_temperature" when the case fixes it
    std::string oil_file;  // the oil file the case names (as resolved), empty when the oil is inline
    // Every value assumed because the case (or its oil file) did not give it, in reading order.
    std::vector<AssumedValue> assumed;
    // Per bearing block: its designation, the catalogue row and the source of each value (`check`).
    std::vector<BearingResolution> bearings_resolved;
};

// The `vehicle` block (docs/config.md) into c.vehicle (and c.torque_converter).
void load_vehicle(const YamlNode& n, Case& c);

// Loads a case; `ratio` overrides gearbox.ratio.
Case load_case(const std::string& file, const std::optional<std::string>& ratio = std::nullopt);
// Same from text; `name` appears in messages, relative oil files resolve against `base_dir`.
Case load_case_text(const std::string& text, const std::string& name, const std::string& base_dir,
                    const std::optional<std::string>& ratio = std::nullopt);
// The parsed document of an oil file named by a case (`oil: oils/X.yaml`), given its path
// (already known to be a regular file); a sweep passes one that keeps each file it has read.
using OilFileReader = std::function<YamlNode(const std::string& path)>;
// Same from a parsed document (load_case_text parses, then calls this): every check of
// load_case applies and errors point at the lines the nodes carry. `name` is Case::file and
// appears in messages; oil files are read by `read_oil` (YamlNode::load_file when empty).
Case load_case_node(const YamlNode& root, const std::string& name, const std::string& base_dir,
                    const std::optional<std::string>& ratio = std::nullopt, const OilFileReader& read_oil = {});
// Loads an oil from a YAML mapping (inline or a separate file); the values it assumes are
// appended to `assumed` (keys "oil.X_L", ...) when given.
lubricant::Oil load_oil(const YamlNode& node, std::vector<AssumedValue>* assumed = nullptr);
lubricant::Oil load_oil_file(const std::string& file, std::vector<AssumedValue>* assumed = nullptr);
// Where the case wrote `section` (its `item`, `key`): the deepest recorded place, else the case
// file alone (line 0), for an error or a note found after loading.
SourceLocation case_location(const Case& c, const std::string& section, const std::string& item = "",
                             const std::string& key = "");

// Replaces the oil of a loaded case (bearing friction pairs follow the new oil); the
// assumed values of the old oil ("oil.*", bearings' mu_ehl) give way to `assumed_by_oil`.
void replace_oil(Case& c, const lubricant::Oil& oil, const std::vector<AssumedValue>& assumed_by_oil = {});
// --oil FILE: the oil file replaces the case's oil (Case::oil_file names it) with its assumed values.
void replace_oil_file(Case& c, const std::string& file);
// The same on a model: the oil and what derives from it (the bearings' friction pair).
void replace_oil(solver::Model& m, const lubricant::Oil& oil);

// "600,700,800rpm" or "600 rpm, 700 rpm" -> SI values of the expected dimension.
std::vector<double> parse_value_list(const std::string& text, const units::Dimension& d, const char* what,
                                     const char* example);

}  // namespace gearloss::io
