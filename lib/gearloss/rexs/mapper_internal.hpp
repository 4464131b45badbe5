#pragma once
// Shared between the parts of the REXS case mapper (case_mapper.cpp, mapper_support.cpp).
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

struct Shaft {
    const Component* comp = nullptr;
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
    int shaft = -1;            // index into Mapper::shafts
    int z = 0;
    bool internal = false;
    double mn = 0, beta = 0, alpha_n = 0, b = 0, x = 0, u = 0;
    double tip_radius_estimate() const;  // r of the tip circle, from m_n, z, beta and x (for the housing box)
};

struct Mapper {
    const Model& m;
    ImportOptions options;
    ImportResult result;
    std::vector<Shaft> shafts;
    std::vector<Gear> gears;
    int input = -1, output = -1;
    std::map<std::int64_t, int> shaft_of_id, gear_of_id;

    void warn(const Component& c, const std::string& text);
    int shaft_index_of(std::int64_t id) const;

    void refuse_unsupported();
    void read_shafts();
    void read_gears();
    void choose_input_output();
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
