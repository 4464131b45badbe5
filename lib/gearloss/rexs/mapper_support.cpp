// A REXS model as a gearloss case: bearings (placed here; their data in bearing_mapper.cpp),
// seals, housing and thermal data, operating points and the oil file (case_mapper.hpp). What
// REXS does not carry is written as an assumed value with its reason and declared in the case's
// `assumed:` list (assumed_values.cpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/rexs/mapper_internal.hpp"

namespace gearloss::rexs::detail {

void Mapper::write_bearings(YamlOut& y) {
    static const char* const kinds[] = {"rolling_bearing_with_catalog_geometry", "rolling_bearing_with_detailed_geometry",
                                        "concept_bearing"};
    y.line(0, "bearings:");
    int written = 0;
    for (const auto& c : m.components) {
        if (std::find_if(std::begin(kinds), std::end(kinds), [&](const char* k) { return c.type == k; }) == std::end(kinds))
            continue;
        const auto sides = m.relations_with("side", "assembly", c.id);
        if (sides.empty()) {
            warn(c, "no side relation places the bearing on a shaft: not imported");
            continue;
        }
        const Relation& side = *sides.front();
        // A planet's bearing runs under the planet on the carrier (planetary.cpp); the first planet's
        // bearings are written once for all its planets.
        const int planet = planet_of_bearing(c, side);
        if (planet == -2) continue;
        const auto inner = side.ref("inner_part");
        const auto outer = side.ref("outer_part");
        int si = inner ? shaft_index_of(*inner) : -1;
        std::string u_attr = "u_coordinate_on_shaft_inner_side";
        if (si < 0 && outer && shaft_index_of(*outer) >= 0) {
            si = shaft_index_of(*outer);  // outer-ring rotation: the shaft is the outer part
            u_attr = "u_coordinate_on_shaft_outer_side";
        }
        if (si < 0) m.fail(c, "neither side of the bearing is a shaft");
        const Shaft& s = shafts[static_cast<size_t>(si)];
        // A pilot bearing (between two shafts, e.g. the input shaft's end in the output shaft's hub):
        // on its inner shaft with `outer_shaft`, so it runs at the relative speed of the two. A shaft
        // the case does not write as a shaft of its own (a carrier part, an unconnected shaft) has
        // no speed there: the bearing then stays against the housing, with a warning.
        int outer_shaft = -1;
        if (planet < 0 && inner && outer && shaft_index_of(*inner) >= 0 && shaft_index_of(*outer) >= 0) {
            outer_shaft = shaft_index_of(*outer);
            if (shafts[static_cast<size_t>(outer_shaft)].role != ShaftRole::plain || s.role != ShaftRole::plain) {
                warn(c, fmt::format("the bearing runs between shafts {} and {}: it is placed on shaft {} against the housing "
                                    "(its speed is that shaft's, not the difference of the two: shaft {} is not a shaft "
                                    "of the case)",
                                    *inner, *outer, s.comp->id, s.role != ShaftRole::plain ? *inner : *outer));
                outer_shaft = -1;
            }
        }
        const double u = required_quantity(m, c, u_attr, Quantity::length);
        if (!s.sections.empty() && (u < -1e-9 || u > s.length() + 1e-9))
            m.fail(c, fmt::format("{} = {:g} mm lies outside shaft {} (0 to {:g} mm)", u_attr, u * 1e3, s.comp->id,
                                  s.length() * 1e3));
        const auto axial = text(m, c, "axial_force_absorption");
        const bool locating = axial && *axial != "no_direction";
        const std::string name = "bearing_" + std::to_string(c.id);
        y.line(2, "- name: " + name, "REXS " + std::to_string(c.id) + " " + c.type + " '" + safe_name(c) + "'");
        if (planet >= 0) {
            const Gear& g = gears[static_cast<size_t>(planet)];
            y.line(4, "shaft: " + shafts[static_cast<size_t>(g.carrier)].name, "the planet's carrier (REXS side relation " + std::to_string(side.id) + ")");
            y.line(4, "under_gear: " + g.name, fmt::format("REXS side relation {}: a bearing of the planet, one per planet", side.id));
        } else {
            y.line(4, "shaft: " + s.name, "REXS side relation " + std::to_string(side.id));
            if (const auto moved = support_moved.find(c.id); moved != support_moved.end())
                y.line(4, "position: " + num(moved->second * 1e3) + " mm",
                       "assumed: " + src(c, u_attr) + " = " + num(u * 1e3) + " mm; paired with the nearer outer support");
            else
                y.line(4, "position: " + num(u * 1e3) + " mm", src(c, u_attr));
            if (outer_shaft >= 0)
                y.line(4, "outer_shaft: " + shafts[static_cast<size_t>(outer_shaft)].name,
                       fmt::format("REXS side relation {}: outer ring in shaft {} (a pilot bearing, at the relative speed)",
                                   side.id, shafts[static_cast<size_t>(outer_shaft)].comp->id));
            if (outer_shaft >= 0) {
                // Its place along the outer shaft, in that shaft's own u coordinate (the pilot's reaction
                // loads the outer shaft there); without the outer-side coordinate, the same gear-unit x.
                const Shaft& os = shafts[static_cast<size_t>(outer_shaft)];
                if (const auto uo = quantity(m, c, "u_coordinate_on_shaft_outer_side", Quantity::length))
                    y.line(4, "outer_position: " + num(*uo * 1e3) + " mm", src(c, "u_coordinate_on_shaft_outer_side"));
                else
                    y.line(4, "outer_position: " + num((s.u_start + u - os.u_start) * 1e3) + " mm",
                           src(c, u_attr) + fmt::format(" on shaft {}, from shaft {}'s u = 0", s.comp->id, os.comp->id));
            }
        }
        if (locating) y.line(4, "locating: true", src(c, "axial_force_absorption") + " " + io::excerpt(*axial, 30));
        ++written;
        write_bearing_data(y, c, s, u, locating, name);
    }
    if (written == 0) y.line(2, "[]");
    y.blank();
}

void Mapper::write_seals(YamlOut& y) {
    // REXS 1.x describes no shaft seals; a gearbox has a radial lip seal where the input and
    // output shafts leave the casing.
    y.line(0, "seals:", "assumed: REXS carries no seals; one lip seal on the input and one on the output shaft");
    for (int i : {input, output}) {
        const Shaft& s = shafts[static_cast<size_t>(i)];
        const double d = s.min_diameter();
        if (!(d > 0)) continue;
        y.assumed(2, "- {name: seal_" + s.name + ", shaft: " + s.name + ", diameter: " + num(d * 1e3) + " mm}",
                  "seals.seal_" + s.name,
                  fmt::format("REXS carries no seals: a radial lip seal where shaft {} leaves the casing, of its smallest "
                              "diameter",
                              s.comp->id));
    }
    y.blank();
}

void Mapper::write_housing_thermal(YamlOut& y) {
    // The box around the gears and shafts (REXS gear_casing carries no geometry): in the transverse
    // plane each shaft's largest tip circle plus 20 mm clearance, along the shafts their extent.
    const Shaft& in = shafts[static_cast<size_t>(input)];
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9, z0 = 1e9, z1 = -1e9;
    double lowest_y = 1e9, lowest_r = 0, lowest_m = 0;
    for (size_t i = 0; i < shafts.size(); ++i) {
        const Shaft& s = shafts[i];
        double r = 0.5 * s.min_diameter(), mn = 0;
        for (const auto& g : gears)
            if (g.shaft == static_cast<int>(i) && g.tip_radius_estimate() > r) {
                r = g.tip_radius_estimate();
                mn = g.mn;
            }
        x0 = std::min(x0, s.x - in.x - r - 0.02);
        x1 = std::max(x1, s.x - in.x + r + 0.02);
        y0 = std::min(y0, s.y - in.y - r - 0.02);
        y1 = std::max(y1, s.y - in.y + r + 0.02);
        z0 = std::min(z0, s.u_start);
        z1 = std::max(z1, s.u_start + s.length());
        // The dip reference is a gear on a fixed axis: planets orbit (and gearloss does not churn them).
        if (mn > 0 && s.role == ShaftRole::plain && s.y - in.y - r < lowest_y - lowest_r) {
            lowest_y = s.y - in.y;
            lowest_r = r;
            lowest_m = mn;
        }
    }
    const double a = x1 - x0, b = y1 - y0, c = std::max(z1 - z0, 0.05);
    const double area = 2 * (a * b + b * c + c * a);
    // Dip lubrication: the lowest gear dips three normal modules (within the usual 2..5 m_n).
    const double level = lowest_y - lowest_r + 3 * lowest_m;
    const double volume = a * c * std::max(level - y0, 0.0);
    y.line(0, "housing:");
    y.assumed(2, "oil_volume: " + fmt::format("{:.2g}", volume * 1e3) + " L", "housing.oil_volume",
              fmt::format("REXS gives no oil volume: the box {:.0f} x {:.0f} mm (transverse, along the shafts) filled to the "
                          "oil level",
                          a * 1e3, c * 1e3));
    y.assumed(2, "oil_level: " + num(std::round(level * 1e4) / 10) + " mm", "housing.oil_level",
              "REXS gives no oil level: the lowest gear dips 3 m_n (dip lubrication, within the usual 2 to 5 m_n)");
    y.blank();
    // One lubricant temperature in every load case: a temperature-controlled run at that temperature.
    std::set<double> temperatures;
    for (const auto& lc : m.load_cases)
        for (const auto& lcc : lc.components)
            if (lcc.find("temperature_lubricant"))
                temperatures.insert(required_quantity(m, lcc, "temperature_lubricant", Quantity::temperature));
    y.line(0, "thermal:");
    if (temperatures.size() == 1) {
        y.line(2, "mode: fixed", "REXS load cases give one lubricant temperature");
        y.line(2, "oil_temperature: " + num(*temperatures.begin() - 273.15) + " degC", "REXS load cases temperature_lubricant");
    } else {
        y.line(2, "mode: stabilised", temperatures.empty() ? "REXS gives no lubricant temperature"
                                                          : "REXS load cases give several lubricant temperatures");
    }
    y.assumed(2, "ambient: 20 degC", "thermal.ambient", "REXS gives no ambient temperature: room temperature");
    y.line(2, "heat_rejection:");
    y.assumed(4, fmt::format("housing: {{area: {:.2g} m^2, emissivity: 0.9, height: {:.2g} m}}", area, b),
              "thermal.heat_rejection.housing",
              "REXS gives no casing geometry: the surface of the box around the gears, a painted cast housing (heat path "
              "to the ambient air)");
    y.blank();
}

void Mapper::write_operating(YamlOut& y) {
    // Load cases: the input shaft's speed and the torque of the external load that defines it.
    const Shaft& in = shafts[static_cast<size_t>(input)];
    std::vector<std::pair<double, double>> points;
    std::vector<std::string> sources;
    for (const auto& lc : m.load_cases) {
        const Component* s = lc.find(in.comp->id);
        double n = 0, t = 0;  // 0: not given
        if (s)
            if (const auto v = quantity(m, *s, "rotational_speed", Quantity::rotational_speed)) n = std::abs(*v);
        for (const Relation* r : m.relations_with("assembly", "assembly", in.comp->id))
            if (const auto p = r->ref("part"); p && m.at(*p).type == "external_load")
                if (const Component* l = lc.find(*p))
                    if (const auto v = quantity(m, *l, "torque_around_u_axis", Quantity::torque)) t = std::abs(*v);
        if (n > 0 && t > 0) {
            points.emplace_back(n, t);
            sources.push_back(std::to_string(lc.id));
        }
    }
    y.line(0, "operating:");
    if (!points.empty()) {
        std::string list, ids;
        for (const auto& [n, t] : points)
            list += fmt::format("{}[{} rpm, {} N*m]", list.empty() ? "" : ", ", num(n * 60 / (2 * std::numbers::pi)), num(t));
        for (const auto& id : sources) ids += (ids.empty() ? "" : ", ") + id;
        y.line(2, "points: [" + list + "]",
               fmt::format("REXS load cases {} (shaft {} rotational_speed, its external load torque_around_u_axis)", ids,
                           in.comp->id));
    } else {
        y.assumed(2, "speeds: [500 rpm, 1000 rpm, 1500 rpm, 3000 rpm]", "operating.speeds", "REXS gives no load case");
        y.assumed(2, "torques: [50 N*m, 100 N*m, 200 N*m]", "operating.torques", "REXS gives no load case");
    }
}

std::string Mapper::oil_yaml() const {
    const auto list = m.of_type("lubricant");
    if (list.empty())
        m.fail("the model has no lubricant component: give an oil file with --oil");
    const Component& c = *list.front();
    YamlOut y;
    y.comment(0, "The lubricant of the REXS model " + io::excerpt(m.file, 120) + ", imported by gearloss import.");
    y.line(0, "name: " + quoted(c.name), "REXS " + std::to_string(c.id) + " lubricant name");
    // The base oil: the ISO 6336 lubricant type when given, else the basis when it is mineral.
    static const std::pair<const char*, const char*> iso_types[] = {
        {"mineral_oil", "mineral"}, {"polyalfaolefin", "PAO"}, {"non_water_soluble_polyglycol", "PAG"},
        {"water_soluble_polyglycol", "PAG_water_soluble"}, {"phosphate_ester", "phosphate_ester"},
        {"traction_fluid", "traction_fluid"}};
    const auto iso = text(m, c, "lubricant_type_iso_6336_2006");
    const auto basis = text(m, c, "basis");
    const char* base = nullptr;
    for (const auto& [rexs_type, gearloss_base] : iso_types)
        if (iso && *iso == rexs_type) base = gearloss_base;
    if (base) y.line(0, std::string("base: ") + base, src(c, "lubricant_type_iso_6336_2006") + " " + *iso);
    else if (basis && *basis == "mineral") y.line(0, "base: mineral", src(c, "basis"));
    else y.assumed(0, "base: mineral", "base",
                   basis ? "REXS basis '" + io::excerpt(*basis, 30) + "' names no base oil gearloss knows"
                         : "REXS gives no base oil type");
    const double nu40 = required_quantity(m, c, "viscosity_at_40_degree_celsius", Quantity::kinematic_viscosity);
    const double nu100 = required_quantity(m, c, "viscosity_at_100_degree_celsius", Quantity::kinematic_viscosity);
    if (!(nu40 > nu100 && nu100 > 0)) m.fail(c, "the viscosity at 40 degC must exceed the one at 100 degC");
    y.line(0, "viscosity:");
    y.line(2, "law: astm_d341", "two points: the ASTM D341 (Walther) line");
    y.line(2, "points:");
    y.line(4, "- [40 degC, " + num(nu40 * 1e6) + " cSt]", src(c, "viscosity_at_40_degree_celsius"));
    y.line(4, "- [100 degC, " + num(nu100 * 1e6) + " cSt]", src(c, "viscosity_at_100_degree_celsius"));
    if (const auto rho = quantity(m, c, "density_at_15_degree_celsius", Quantity::density))
        y.line(0, "density: {value: " + num(*rho) + " kg/m^3, at: 15 degC}", src(c, "density_at_15_degree_celsius"));
    else y.assumed(0, "density: {value: 880 kg/m^3, at: 15 degC}", "density", "REXS gives no density (a mineral gear oil)");
    y.write_assumed_list();
    return y.str();
}

}  // namespace gearloss::rexs::detail
