#pragma once
// Shared between the parts of the REXS case mapper (case_mapper.cpp, planetary.cpp,
// mapper_support.cpp).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/bearings/designation.hpp"
#include "gearloss/bearings/skf_constants.hpp"
#include "gearloss/rexs/case_mapper.hpp"
#include "gearloss/rexs/units.hpp"

namespace gearloss::rexs::detail {

// YAML text with a comment column: each value line names where it came from.
class YamlOut {
public:
    void line(int indent, const std::string& text, const std::string& comment = "");
    void blank() { text_ += "\n"; }
    void comment(int indent, const std::string& text);
    const std::string& str() const { return text_; }
    // A value REXS does not carry: the line with the comment "assumed: <reason>", and `key` (its
    // key path, "housing.oil_level") declared in the case's `assumed:` list (assumed_values.cpp).
    void assumed(int indent, const std::string& text, const std::string& key, const std::string& reason);
    // The `assumed:` list of the values declared so far (docs/config.md), for the case loader.
    void write_assumed_list();

private:
    std::string text_;
    std::vector<std::pair<std::string, std::string>> assumed_;  // key path, reason
};

// A number for YAML: up to 10 significant digits, no trailing zeros (117, 0.231415, 4.5).
std::string num(double v);
// "REXS 15 number_of_teeth" ("REXS <id> <attribute> [<unit>]" when the attribute has a unit).
std::string src(const Component& c, const std::string& attribute);
// A YAML double-quoted scalar of `s` (at most `max` characters, control bytes shown as '?').
std::string quoted(const std::string& s, size_t max = 60);
// A component name safe for a YAML comment (no control bytes, at most 60 characters).
std::string safe_name(const Component& c);

struct ShaftSection {
    double u0 = 0, u1 = 0, d_begin = 0, d_end = 0;
    const Component* comp = nullptr;
};

// Names that differ across the REXS versions read (the data model of each version, 1.0 to 1.6):
// - a rolling bearing's catalogue designation is `name` ("Catalogue name") in REXS 1.0 and
//   `catalogue_designation` from 1.1 on (the same attribute, numeric id 486);
// - a gear's flank component is a `flank_geometry` up to 1.2 and a `cylindrical_gear_flank` from
//   1.3 on: both are read through the `flank` relation, whatever the type of its left and right;
// - `ring_gear` (an internal gear) and `planetary_stage` exist from 1.1 on;
// - gear roughness (`arithmetic_average_roughness_flank`) from 1.2 on, the lubricant's
//   `lubricant_type_iso_6336_2006` and a concept bearing's diameters from 1.3 on (before: not given).
inline const char* designation_attribute(const Model& m) { return m.version == "1.0" ? "name" : "catalogue_designation"; }

// What a REXS shaft is in gearloss's model: a shaft of its own, or the shaft of a planet or a
// planet pin of a planetary stage (planetary.cpp), which gearloss folds into the planet gear on
// its carrier, or a further shaft of a carrier made of several (a two-cheek carrier), which
// turns with the carrier's shaft, or a shaft with no gear and no bearing (a connecting shaft
// between couplings), which has no loss of its own and no speed the gear train fixes.
enum class ShaftRole { plain, planet, pin, carrier_part, unconnected };

struct Shaft {
    const Component* comp = nullptr;
    ShaftRole role = ShaftRole::plain;
    bool held = false;         // a planetary member held by the housing (gearloss `fixed: true`)
    std::string held_reason;   // the YAML comment saying why
    std::string name;
    double x = 0, y = 0;       // axis in the housing frame [m]: REXS gear-unit (y, z), z taken as up
    double u_start = 0;        // gear-unit x of the shaft's u = 0 [m]
    std::vector<ShaftSection> sections;
    double length() const;
    std::optional<double> diameter_at(double u) const;  // outer diameter at u, nullopt outside
    double min_diameter() const;
};

struct Gear {
    const Component* comp = nullptr;
    std::string name;
    int shaft = -1;            // index into Mapper::shafts (a planet: its planet shaft or pin)
    int carrier = -1;          // a planet: the carrier shaft (index into Mapper::shafts)
    int planets = 1;           // a planet: the number of identical, equally spaced planets
    int written_as = -1;       // another planet of the same set: the planet written for all (gear index)
    int z = 0;
    bool internal = false;
    double mn = 0, beta = 0, alpha_n = 0, b = 0, x = 0, u = 0;
    double tip_radius_estimate() const;  // r of the tip circle, from m_n, z, beta and x (for the housing box)
};

// A REXS planetary_stage as a gearloss planetary set: sun and ring on central shafts (either may
// be absent), the identical planets on their planet shafts or pins, the carrier shaft.
struct PlanetarySet {
    const Component* stage = nullptr;
    int carrier = -1;                // shaft index
    int sun = -1, ring = -1;         // gear indices, -1 when the set has none
    std::vector<int> planets;        // gear indices, the first is written for all
    std::vector<int> members;        // shaft indices of the central shafts and the carrier
};

struct Mapper {
    const Model& m;
    ImportOptions options;
    ImportResult result;
    std::vector<Shaft> shafts;
    std::vector<Gear> gears;
    int input = -1, output = -1;
    std::map<std::int64_t, int> shaft_of_id, gear_of_id;
    std::vector<PlanetarySet> sets;
    // Bearings written at another axial position than REXS gives (plan_support_positions): id -> u [m].
    std::map<std::int64_t, double> support_moved;

    void warn(const Component& c, const std::string& text);
    int shaft_index_of(std::int64_t id) const;

    void refuse_unsupported();
    void read_shafts();
    void read_gears();
    void read_planetary();           // planetary.cpp
    // The carrier shaft of a planetary stage among its planet_carrier_shaft relations (several:
    // the others become carrier parts).
    int carrier_of(const Component& stage, const std::vector<int>& carriers);
    void hold_planetary_members();   // planetary.cpp: after choose_input_output
    // A bearing of a planet (between its planet shaft or pin and a pin, side plate or the
    // carrier): the planet gear it runs under (written on the carrier), -2 for a bearing of
    // another planet of the set (written once, for the first), -1 for any other bearing.
    int planet_of_bearing(const Component& bearing, const Relation& side) const;
    // "{name: X, fixed: true}" or "X": how the shaft list names shaft i.
    std::string shaft_entry(size_t i) const;
    void choose_input_output();
    // A shaft on more than two support positions: its inner bearings paired with the nearer
    // outermost one (case_mapper.cpp), filling support_moved.
    void plan_support_positions();
    // Shafts with no gear and no bearing, neither input nor output: ShaftRole::unconnected.
    void set_aside_unconnected_shafts();
    void write_shafts_gears_meshes(YamlOut& y);
    void write_bearings(YamlOut& y);
    // bearing_mapper.cpp: what follows a bearing's name, shaft and position.
    void write_bearing_data(YamlOut& y, const Component& c, const Shaft& s, double u, bool locating, const std::string& name);
    void report_suffix(YamlOut& y, const Component& c, const bearings::DesignationKey& key, bearings::BearingType type,
                       double D, bool designation_written);
    void assumed_line(YamlOut& y, int indent, const std::string& text, const std::string& key, const std::string& reason) {
        y.assumed(indent, text, key, reason);
    }
    void write_seals(YamlOut& y);
    void write_housing_thermal(YamlOut& y);
    void write_operating(YamlOut& y);
    std::string oil_yaml() const;
};

}  // namespace gearloss::rexs::detail
