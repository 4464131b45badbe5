#include "io/config.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <fmt/format.h>
#include <map>
#include <numbers>
#include <set>

#include "bearings/skf_constants.hpp"
#include "io/case_plausibility.hpp"
#include "io/issue_location.hpp"
#include "io/mechanism_config.hpp"
#include "io/sweep.hpp"
#include "solver/validate.hpp"

namespace gearloss::io {

namespace fs = std::filesystem;
namespace dim = units::dim;
using lubricant::BaseOil;

namespace {

constexpr double deg = std::numbers::pi / 180.0;

BaseOil parse_base(const YamlNode& n) {
    return n.as_enum<BaseOil>({{"mineral", BaseOil::mineral},
                               {"PAO", BaseOil::pao},
                               {"pao", BaseOil::pao},
                               {"ester", BaseOil::ester},
                               {"PAG", BaseOil::pag},
                               {"pag", BaseOil::pag},
                               {"PAG_water_soluble", BaseOil::pag_water_soluble},
                               {"phosphate_ester", BaseOil::phosphate_ester},
                               {"traction_fluid", BaseOil::traction_fluid},
                               {"transmission_fluid", BaseOil::transmission_fluid}});
}

lubricant::BearingFrictionPair parse_pair(const YamlNode& n) {
    n.allow_keys({"mu_bl", "mu_ehl"});
    lubricant::BearingFrictionPair p;
    if (auto v = n.get("mu_bl")) {
        p.mu_bl = v->as_number();
        if (!(p.mu_bl >= 0 && p.mu_bl < 1)) v->fail("must be in [0, 1)");
    }
    if (auto v = n.get("mu_ehl")) {
        p.mu_ehl = v->as_number();
        if (!(*p.mu_ehl >= 0 && *p.mu_ehl < 1)) v->fail("must be in [0, 1)");
    }
    return p;
}

}  // namespace

lubricant::Oil load_oil(const YamlNode& n) {
    n.allow_keys({"name", "base", "viscosity", "density", "thermal_expansion", "piezoviscosity", "X_L",
                  "thermal_conductivity", "specific_heat", "bearing_friction", "gear_friction", "traction",
                  "max_temperature", "note"});
    lubricant::Oil oil;
    oil.name = n.at("name").as_title();
    oil.base = parse_base(n.at("base"));
    oil.max_temperature = lubricant::default_max_temperature(oil.base);
    if (auto t = n.get("max_temperature")) {
        oil.max_temperature = t->as_temperature();
        if (!(oil.max_temperature > 273.15 && oil.max_temperature < 273.15 + 400))
            t->fail("permissible oil temperature outside 0..400 degC");
    }

    const YamlNode v = n.at("viscosity");
    v.allow_keys({"law", "points", "astm_d341"});
    if (auto c = v.get("astm_d341")) {
        c->allow_keys({"A", "B"});
        lubricant::WaltherLaw w;
        w.A = c->at("A").as_number();
        w.B = c->at("B").as_number();
        if (!(w.B > 0)) c->at("B").fail("must be positive (viscosity falls with temperature)");
        oil.viscosity = w;
        if (v.has("points")) v.at("points").fail("give either 'points' or 'astm_d341', not both");
    } else {
        const auto pts = v.at("points").items();
        std::vector<std::pair<double, double>> tv;
        for (const auto& p : pts) {
            const auto pair = p.items();
            if (pair.size() != 2) p.fail("each point is [temperature, kinematic viscosity], e.g. [40 degC, 112.35 cSt]");
            const double T = pair[0].as_temperature();
            const double nu = pair[1].as_quantity(dim::kinematic_viscosity, "112.35 cSt");
            if (!(nu > 0)) pair[1].fail("viscosity must be positive");
            tv.emplace_back(T, nu * 1e6);
        }
        std::sort(tv.begin(), tv.end());
        for (size_t i = 1; i < tv.size(); ++i) {
            if (tv[i].first == tv[i - 1].first) v.at("points").fail("two points at the same temperature");
            if (tv[i].second >= tv[i - 1].second)
                v.at("points").fail("viscosity must fall as temperature rises");
        }
        std::string law = tv.size() == 3 ? "vogel" : "astm_d341";
        if (auto l = v.get("law")) law = l->as_enum<std::string>({{"vogel", "vogel"}, {"astm_d341", "astm_d341"}});
        try {
            if (law == "vogel") {
                if (tv.size() != 3) v.at("points").fail("the Vogel law needs exactly 3 points");
                const double T[3] = {tv[0].first - 273.15, tv[1].first - 273.15, tv[2].first - 273.15};
                const double nu[3] = {tv[0].second, tv[1].second, tv[2].second};
                oil.viscosity = lubricant::VogelLaw::fit(T, nu);
            } else {
                if (tv.size() < 2) v.at("points").fail("ASTM D341 needs 2 points (3 points select the Vogel law)");
                oil.viscosity = lubricant::WaltherLaw::fit(tv.front().first, tv.front().second, tv.back().first,
                                                           tv.back().second);
            }
        } catch (const InputError& e) {
            if (e.where().known()) throw;  // already at its line
            v.at("points").fail(e.message);  // a fit that cannot hold these points
        }
    }

    const YamlNode d = n.at("density");
    if (d.is_map()) {
        d.allow_keys({"value", "at"});
        const double rho = d.positive_quantity("value", dim::density, "885 kg/m^3");
        const double T = d.has("at") ? d.at("at").as_temperature() : 288.15;
        oil.rho15 = rho;  // corrected below once the expansion is known
        oil.expansion = 0;
        const double beta = n.has("thermal_expansion")
                                ? n.at("thermal_expansion").as_quantity(dim::per_kelvin, "6.8e-4 1/K")
                                : 6.5e-4;
        oil.rho15 = rho / (1.0 - beta * (T - 288.15));
        oil.expansion = beta;
    } else {
        oil.rho15 = d.as_quantity(dim::density, "885 kg/m^3");
        if (!(oil.rho15 > 300 && oil.rho15 < 2500)) d.fail("density outside 300..2500 kg/m^3; check the unit");
        if (auto e = n.get("thermal_expansion")) oil.expansion = e->as_quantity(dim::per_kelvin, "6.8e-4 1/K");
    }
    if (!(oil.expansion >= 0 && oil.expansion < 5e-3))
        n.at("thermal_expansion").fail("expansion coefficient must be in [0, 5e-3] 1/K (positive: density falls with T)");

    if (auto pz = n.get("piezoviscosity")) {
        if (pz->is_scalar()) {
            if (pz->as_string() != "gold") pz->fail("use 'gold' or a list of [temperature, coefficient] pairs");
        } else {
            for (const auto& p : pz->items()) {
                const auto pair = p.items();
                if (pair.size() != 2) p.fail("each entry is [temperature, coefficient], e.g. [40 degC, 1.387e-8 1/Pa]");
                const double T = pair[0].as_temperature();
                const double a = pair[1].as_quantity(dim::per_pascal, "1.387e-8 1/Pa");
                if (!(a > 1e-10 && a < 1e-6)) pair[1].fail("pressure-viscosity coefficient outside 1e-10..1e-6 1/Pa");
                oil.piezo_table.push_back({T, a});
            }
            std::sort(oil.piezo_table.begin(), oil.piezo_table.end(),
                      [](const auto& a, const auto& b) { return a.T_K < b.T_K; });
        }
    }
    if (auto x = n.get("X_L")) {
        oil.X_L = x->as_number();
        if (!(oil.X_L > 0 && oil.X_L < 3)) x->fail("X_L must be in (0, 3)");
    } else if (auto def = lubricant::default_XL(oil.base)) {
        oil.X_L = *def;
    } else {
        n.fail(fmt::format("base oil '{}' has no standard X_L (ISO/TS 6336-20); give 'X_L' (e.g. 0.65, Fernandes 2015)",
                           lubricant::to_string(oil.base)));
    }
    if (auto k = n.get("thermal_conductivity")) oil.k_fixed = k->as_quantity(dim::thermal_conductivity, "0.15 W/(m*K)");
    if (auto c = n.get("specific_heat")) oil.cp_fixed = c->as_quantity(dim::specific_heat, "2000 J/(kg*K)");
    oil.traction = lubricant::default_traction(oil.base);
    if (auto tr = n.get("traction")) {
        tr->allow_keys({"eyring_stress", "limiting_shear_stress", "limiting_shear_slope", "boundary_friction", "mixed_B",
                        "mixed_m", "roelands_index"});
        auto& t = oil.traction;
        if (auto v = tr->get("eyring_stress")) t.eyring_stress = v->as_quantity(dim::pressure, "5 MPa");
        if (auto v = tr->get("limiting_shear_stress")) t.limiting_shear_0 = v->as_quantity(dim::pressure, "1 MPa");
        if (auto v = tr->get("limiting_shear_slope")) t.limiting_shear_slope = v->as_number();
        if (auto v = tr->get("boundary_friction")) t.mu_boundary = v->as_number();
        if (auto v = tr->get("mixed_B")) t.mixed_B = v->as_number();
        if (auto v = tr->get("mixed_m")) t.mixed_m = v->as_number();
        if (auto v = tr->get("roelands_index")) {
            t.roelands_Z = v->as_number();
            if (!(t.roelands_Z > 0.1 && t.roelands_Z < 1.5)) v->fail("Roelands index must be in (0.1, 1.5) (typical 0.4-0.8)");
        }
        if (!(t.eyring_stress > 0 && t.limiting_shear_0 >= 0 && t.limiting_shear_slope >= 0 && t.limiting_shear_slope < 1 &&
              t.mu_boundary > 0 && t.mu_boundary < 1 && t.mixed_B > 0 && t.mixed_m > 0))
            tr->fail("traction properties out of range (Eyring stress > 0, 0 <= slope < 1, 0 < boundary friction < 1)");
    }
    if (auto bf = n.get("bearing_friction")) {
        bf->allow_keys({"ball", "roller"});
        if (auto b = bf->get("ball")) oil.bearing_ball = parse_pair(*b);
        if (auto r = bf->get("roller")) oil.bearing_roller = parse_pair(*r);
    }
    return oil;
}

lubricant::Oil load_oil_file(const std::string& file) {
    const YamlNode root = YamlNode::load_file(file);
    return load_oil(root.has("oil") ? root.at("oil") : root);
}

namespace {
// Position where the unit starts in "600rpm" / "1.5e-3 m" (an 'e' followed by a
// digit or sign belongs to the number); npos when there is no unit.
size_t unit_start(const std::string& s) {
    // The unit is whatever follows the number ("700 1/min": "1/min", not "min").
    size_t b = 0;
    while (b < s.size() && s[b] == ' ') ++b;
    if (b < s.size() && s[b] == '+') ++b;
    double v = 0;
    const auto [ptr, ec] = std::from_chars(s.data() + b, s.data() + s.size(), v);
    if (ec != std::errc() && ec != std::errc::result_out_of_range) return std::string::npos;
    size_t u = static_cast<size_t>(ptr - s.data());
    while (u < s.size() && s[u] == ' ') ++u;
    return u < s.size() ? u : std::string::npos;
}
}  // namespace

std::vector<double> parse_value_list(const std::string& text, const units::Dimension& d, const char* what,
                                     const char* example) {
    // Items are comma-separated; a unit on the last item applies to items
    // without one: "600,700,800rpm".
    std::vector<std::string> parts;
    size_t start = 0;
    for (size_t i = 0; i <= text.size(); ++i)
        if (i == text.size() || text[i] == ',') {
            std::string p = text.substr(start, i - start);
            p.erase(0, p.find_first_not_of(' '));
            p.erase(p.find_last_not_of(' ') + 1);
            parts.push_back(p);
            start = i + 1;
        }
    const size_t u = unit_start(parts.back());
    const std::string unit = u == std::string::npos ? "" : parts.back().substr(u);
    std::vector<double> out;
    for (const auto& p : parts) {
        if (p.empty()) throw InputError("", 0, 0, what, "empty item in '" + text + "' (expected e.g. '" + example + "')");
        const std::string q = unit_start(p) == std::string::npos ? p + " " + unit : p;
        units::Quantity v;
        try {
            v = units::parse_quantity(q);
        } catch (const units::UnitError& e) {
            throw InputError("", 0, 0, what, e.message + " (expected e.g. '" + example + "')");
        }
        if (v.dim != d || v.absolute_temperature)
            throw InputError("", 0, 0, what,
                             "'" + p + "' has dimension " + units::to_string(v.dim) + ", expected " + units::to_string(d) +
                                 " (e.g. '" + example + "')");
        try {
            out.push_back(units::as_rotational_speed(v, q));
        } catch (const units::UnitError& e) {
            throw InputError("", 0, 0, what, e.message + " (expected e.g. '" + example + "')");
        }
    }
    return out;
}

namespace {

// SKF sliding friction pair of a bearing from the oil (or the SKF defaults by type and base oil).
void set_bearing_friction(bearings::BearingSpec& s, const lubricant::Oil& oil) {
    const bool synthetic = oil.base != BaseOil::mineral && oil.base != BaseOil::transmission_fluid;
    const auto& pair = bearings::is_roller(s.type) ? oil.bearing_roller : oil.bearing_ball;
    s.mu_bl = pair.mu_bl;
    s.mu_ehl = pair.mu_ehl ? *pair.mu_ehl
                           : bearings::default_mu_ehl(s.type, synthetic, oil.base == BaseOil::transmission_fluid);
}

struct Loader {
    const YamlNode& root;
    solver::Model& model;
    std::map<std::string, int> shaft_index, gear_index;
    std::map<std::string, geometry::Material> materials;

    int shaft_ref(const YamlNode& n) {
        const std::string s = n.as_string();
        auto it = shaft_index.find(s);
        if (it == shaft_index.end()) n.fail("unknown shaft '" + excerpt(s) + "'");
        return it->second;
    }
    int gear_ref(const YamlNode& n) {
        const std::string s = n.as_string();
        auto it = gear_index.find(s);
        if (it == gear_index.end()) n.fail("unknown gear '" + excerpt(s) + "'");
        return it->second;
    }

    geometry::Material material(const YamlNode& n) {
        if (n.is_scalar()) {
            const std::string s = n.as_string();
            auto it = materials.find(s);
            if (it == materials.end()) n.fail("unknown material '" + excerpt(s) + "'; define it under 'materials'");
            return it->second;
        }
        n.allow_keys({"E", "poisson", "density"});
        geometry::Material m;
        m.E = n.positive_quantity("E", dim::pressure, "210 GPa");
        m.poisson = n.at("poisson").as_number();
        if (!(m.poisson > 0 && m.poisson < 0.5)) n.at("poisson").fail("Poisson ratio must be in (0, 0.5)");
        if (n.has("density")) m.density = n.positive_quantity("density", dim::density, "7850 kg/m^3");
        return m;
    }

    void load_materials() {
        materials["steel"] = geometry::Material{};
        if (auto ms = root.get("materials"))
            for (auto& [name, node] : ms->entries()) materials[name] = material(node);
    }

    void load_shafts() {
        const YamlNode s = root.at("shafts");
        for (const auto& item : s.items()) {
            std::string name;
            bool fixed = false;
            if (item.is_scalar()) name = item.as_name();
            else {
                item.allow_keys({"name", "fixed", "note"});
                name = item.at("name").as_name();
                if (auto f = item.get("fixed")) fixed = f->as_bool();
            }
            if (shaft_index.count(name)) item.fail("duplicate shaft name '" + excerpt(name) + "'");
            shaft_index[name] = static_cast<int>(model.gearbox.shafts.size());
            model.gearbox.shafts.push_back({name, fixed});
        }
        if (model.gearbox.shafts.size() < 2) s.fail("a gearbox needs at least two shafts");
    }

    void load_gears() {
        for (const auto& n : root.at("gears").items()) {
            n.allow_keys({"name", "shaft", "position", "teeth", "module", "profile_shift", "face_width", "pressure_angle",
                          "helix_angle", "hand", "material", "Ra", "Rq", "mount", "immersion", "addendum_coefficient",
                          "dedendum_coefficient", "internal", "carrier", "planets", "tip_diameter", "tip_alteration_factor", "note"});
            gearbox::Gear g;
            auto& s = g.spec;
            s.name = n.at("name").as_name();
            if (gear_index.count(s.name)) n.at("name").fail("duplicate gear name '" + s.name + "'");
            if (auto c = n.get("carrier")) {
                // A planet: it turns on pins of the carrier, N identical ones equally spaced.
                g.carrier = shaft_ref(*c);
                g.shaft = g.carrier;
                if (n.has("shaft")) n.at("shaft").fail("a planet gear names its 'carrier', not a 'shaft'");
                if (n.has("mount")) n.at("mount").fail("a planet gear always turns on its own bearings; drop 'mount'");
                g.planets = n.has("planets") ? n.at("planets").as_int() : 1;
                if (g.planets < 1 || g.planets > 12) n.at("planets").fail("number of planets must be 1..12");
            } else {
                if (n.has("planets")) n.at("planets").fail("'planets' needs a 'carrier'");
                g.shaft = shaft_ref(n.at("shaft"));
            }
            if (auto in = n.get("internal")) s.internal = in->as_bool();
            if (s.internal && g.is_planet()) n.at("internal").fail("a planet cannot be an internal gear");
            g.position = n.has("position") ? n.quantity("position", dim::length, "60 mm") : 0.0;
            const YamlNode zt = n.at("teeth");
            s.z = zt.as_int();
            if (s.z < 5) zt.fail(fmt::format("number of teeth must be at least 5, got {}", s.z));
            s.mn = n.positive_quantity("module", dim::length, "3.5 mm");
            s.x = n.has("profile_shift") ? n.at("profile_shift").as_number() : 0.0;
            if (!(s.x > -1.5 && s.x < 2.5)) n.at("profile_shift").fail("profile shift coefficient outside -1.5..2.5");
            s.b = n.positive_quantity("face_width", dim::length, "35 mm");
            s.alpha_n = n.has("pressure_angle") ? n.quantity("pressure_angle", dim::angle, "20 deg") : 20.0 * deg;
            if (!(s.alpha_n > 10 * deg && s.alpha_n < 35 * deg))
                n.at("pressure_angle").fail("pressure angle outside 10..35 deg");
            s.beta = n.has("helix_angle") ? n.quantity("helix_angle", dim::angle, "20 deg") : 0.0;
            if (!(s.beta >= 0 && s.beta < 45 * deg)) n.at("helix_angle").fail("helix angle outside 0..45 deg (give the hand separately)");
            if (s.beta > 0) {
                s.hand = n.at("hand").as_enum<geometry::Hand>({{"right", geometry::Hand::right}, {"left", geometry::Hand::left}});
            } else {
                s.hand = geometry::Hand::spur;
            }
            if (n.has("addendum_coefficient")) s.ha_star = n.at("addendum_coefficient").as_number();
            if (n.has("dedendum_coefficient")) s.hf_star = n.at("dedendum_coefficient").as_number();
            if (n.has("tip_diameter") && n.has("tip_alteration_factor"))
                n.at("tip_alteration_factor").fail("give either 'tip_diameter' or 'tip_alteration_factor', not both");
            if (n.has("tip_diameter")) s.tip_diameter = n.positive_quantity("tip_diameter", dim::length, "82.46 mm");
            if (auto k = n.get("tip_alteration_factor")) {
                s.tip_alteration_factor = k->as_number();
                if (!(*s.tip_alteration_factor > -1.0 && *s.tip_alteration_factor <= 0.5))
                    k->fail("tip alteration factor k outside -1..0.5 (ISO 21771 sign: k <= 0 shortens the tip)");
            }
            s.material = n.has("material") ? material(n.at("material")) : materials["steel"];
            if (n.has("Ra")) s.Ra = n.positive_quantity("Ra", dim::length, "0.5 um");
            if (n.has("Rq")) s.Rq = n.positive_quantity("Rq", dim::length, "0.6 um");
            if (s.Ra > 50e-6) n.at("Ra").fail("roughness above 50 um; check the unit");
            if (auto m = n.get("mount"))
                g.free = m->as_enum<bool>({{"fixed", false}, {"free", true}});
            if (auto im = n.get("immersion")) {
                g.immersion = im->as_quantity(dim::length, "10 mm");
                if (*g.immersion < 0) im->fail("immersion depth cannot be negative");
            }
            gear_index[s.name] = static_cast<int>(model.gearbox.gears.size());
            model.gearbox.gears.push_back(g);
        }
        if (model.gearbox.gears.size() < 2) root.at("gears").fail("a gearbox needs at least two gears");
    }

    void load_meshes() {
        std::set<int> used;
        std::set<std::string> names;
        for (const auto& n : root.at("meshes").items()) {
            n.allow_keys({"name", "gears", "angle", "centre_distance", "note"});
            gearbox::Mesh m;
            const auto g = n.at("gears").items();
            if (g.size() != 2) n.at("gears").fail("a mesh names exactly two gears");
            m.gear[0] = gear_ref(g[0]);
            m.gear[1] = gear_ref(g[1]);
            if (m.gear[0] == m.gear[1]) n.at("gears").fail("a gear cannot mesh with itself");
            m.name = n.has("name") ? n.at("name").as_name()
                                   : model.gearbox.gears[m.gear[0]].spec.name + "-" + model.gearbox.gears[m.gear[1]].spec.name;
            if (!names.insert(m.name).second)
                (n.has("name") ? n.at("name") : n.at("gears"))
                    .fail("duplicate mesh name '" + m.name + "'" +
                          (n.has("name") ? "" : " (the default name, from its gears; give the mesh a 'name')"));
            m.angle = n.has("angle") ? n.quantity("angle", dim::angle, "30 deg") : 0.0;
            m.centre_distance = n.opt_quantity("centre_distance", dim::length, "95 mm");
            if (m.centre_distance && *m.centre_distance <= 0) n.at("centre_distance").fail("must be positive");
            try {
                (void)geometry::pair_geometry(model.gearbox.gears[m.gear[0]].spec, model.gearbox.gears[m.gear[1]].spec,
                                              m.centre_distance);
            } catch (const geometry::GeometryError& e) {
                n.fail(e.message);
            }
            model.gearbox.meshes.push_back(m);
        }
    }

    void load_bearings() {
        if (!root.has("bearings")) return;
        std::set<std::string> names;
        for (const auto& n : root.at("bearings").items()) {
            n.allow_keys({"name", "type", "series", "designation", "d", "D", "B", "C0", "Y", "shaft", "position",
                          "under_gear", "locating", "lubrication", "seals", "seal_counterface", "constants", "oil_bath",
                          "note", "count"});
            gearbox::Bearing b;
            b.name = n.at("name").as_name();
            if (!names.insert(b.name).second) n.at("name").fail("duplicate bearing name '" + b.name + "'");
            auto& s = b.spec;
            const YamlNode tn = n.at("type");
            const auto t = bearings::bearing_type_from_string(tn.as_string());
            if (!t) {
                std::string all;
                for (const auto& x : bearings::bearing_type_names()) all += (all.empty() ? "" : ", ") + x;
                tn.fail("unknown bearing type '" + excerpt(tn.as_string()) + "'; known: " + all);
            }
            s.type = *t;
            s.d = n.positive_quantity("d", dim::length, "35 mm") * 1e3;
            s.D = n.positive_quantity("D", dim::length, "80 mm") * 1e3;
            if (s.d >= s.D) n.at("D").fail(fmt::format("outer diameter D = {} mm must exceed bore d = {} mm", s.D, s.d));
            s.B = n.has("B") ? n.positive_quantity("B", dim::length, "21 mm") * 1e3 : 0.25 * (s.D - s.d) * 1.0 + 0.0;
            if (!n.has("B") && bearings::is_roller(s.type) && n.has("oil_bath"))
                n.fail("give the width 'B' for roller bearings in an oil bath (drag depends on it)");
            if (n.has("C0")) s.C0 = n.positive_quantity("C0", dim::force, "18.3 kN");
            if (n.has("Y")) {
                s.Y = n.at("Y").as_number();
                if (!(s.Y > 0 && s.Y < 5)) n.at("Y").fail("axial load factor Y outside (0, 5)");
            }
            const std::string series = n.has("series") ? n.at("series").as_string() : "";
            auto k = bearings::skf_constants(s.type, series);
            if (!k && !n.has("constants")) {
                std::string all;
                for (const auto& x : bearings::series_names(s.type)) all += (all.empty() ? "" : ", ") + x;
                (n.has("series") ? n.at("series") : n)
                    .fail(fmt::format("no SKF constants for a {} bearing of series '{}'; known series: {} (or give "
                                      "'constants')",
                                      bearings::to_string(s.type), excerpt(series), all));
            }
            if (k) s.k = *k;
            if (auto c = n.get("constants")) {
                c->allow_keys({"R1", "R2", "R3", "R4", "S1", "S2", "S3", "S4", "K_Z", "K_L", "rows"});
                auto set = [&](const char* key, double& v) {
                    if (auto x = c->get(key)) v = x->as_number();
                };
                set("R1", s.k.R1); set("R2", s.k.R2); set("R3", s.k.R3); set("R4", s.k.R4);
                set("S1", s.k.S1); set("S2", s.k.S2); set("S3", s.k.S3); set("S4", s.k.S4);
                set("K_Z", s.k.K_Z); set("K_L", s.k.K_L);
                if (auto x = c->get("rows")) s.k.rows = x->as_int();
                if (!(s.k.R1 > 0 && s.k.S1 > 0)) c->fail("R1 and S1 must be positive");
            }
            if (s.type == bearings::BearingType::deep_groove_ball && s.C0 <= 0)
                n.fail("deep groove ball bearings need the static load rating 'C0' (for the axial-load terms)");
            if (auto l = n.get("lubrication"))
                s.K_rs = l->as_enum<double>({{"splash", 3e-8}, {"oil_bath_low", 3e-8}, {"oil_jet", 3e-8},
                                            {"oil_bath", 0.0}, {"grease", 6e-8}, {"oil_air", 6e-8}});
            set_bearing_friction(s, model.oil);
            if (auto se = n.get("seals")) {
                const std::string st = se->as_string();
                if (st != "none") {
                    // M_seal = K_S1 d_s^beta + K_S2 (SKF 2004 seal moment, both sides sealed).
                    using BT = bearings::BearingType;
                    if (s.type == BT::deep_groove_ball && st == "RS1") {
                        s.seal_beta = 2.25;
                        if (s.D <= 62) { s.seal_KS1 = 0.023; s.seal_KS2 = 2; }
                        else if (s.D <= 80) { s.seal_KS1 = 0.018; s.seal_KS2 = 20; }
                        else if (s.D <= 100) { s.seal_KS1 = 0.018; s.seal_KS2 = 15; }
                        else { s.seal_KS1 = 0.018; s.seal_KS2 = 0; }
                    } else if ((s.type == BT::angular_contact_ball || s.type == BT::self_aligning_ball) && st == "RS1") {
                        s.seal_beta = 2; s.seal_KS1 = 0.014; s.seal_KS2 = 10;
                    } else if ((s.type == BT::cylindrical_roller || s.type == BT::cylindrical_roller_full) && st == "LS") {
                        s.seal_beta = 2; s.seal_KS1 = 0.032; s.seal_KS2 = 50;
                    } else if (s.type == BT::spherical_roller && (st == "CS" || st == "CS2" || st == "CS5")) {
                        s.seal_beta = 2; s.seal_KS1 = 0.057; s.seal_KS2 = 50;
                    } else if (st == "Z" || st == "RZ" || st == "2Z") {
                        // shields: no contact friction
                    } else {
                        se->fail(fmt::format("no seal constants for '{}' on a {} bearing (known: DGBB RS1, ACBB/SABB RS1, "
                                             "CRB LS, SRB CS/CS2/CS5, shields Z/RZ)",
                                             st, bearings::to_string(s.type)));
                    }
                    s.seal_ds = n.has("seal_counterface")
                                    ? n.positive_quantity("seal_counterface", dim::length, "30 mm") * 1e3
                                    : s.d + 0.2 * (s.D - s.d);  // inner-ring shoulder estimate
                }
            }
            if (auto ob = n.get("oil_bath")) {
                ob->allow_keys({"level", "V_M"});
                const double H = ob->quantity("level", dim::length, "10 mm") * 1e3;
                if (H < 0) ob->at("level").fail("oil level cannot be negative");
                s.bath_H = H;
                s.bath_VM = ob->at("V_M").as_number();
                if (!(s.bath_VM >= 0 && s.bath_VM < 0.01)) ob->at("V_M").fail("drag factor V_M outside 0..0.01 (SKF diagram)");
            }
            b.shaft = shaft_ref(n.at("shaft"));
            if (auto ug = n.get("under_gear")) {
                b.under_gear = gear_ref(*ug);
                const auto& g = model.gearbox.gears[b.under_gear];
                if (!g.free && !g.is_planet())
                    ug->fail("bearing under gear '" + g.spec.name + "', which is neither 'mount: free' nor a planet");
                if (g.shaft != b.shaft)
                    ug->fail("gear '" + g.spec.name + "' is not on shaft '" + n.at("shaft").as_string() + "'" +
                             (g.is_planet() ? " (a planet bearing names the carrier as its shaft)" : ""));
                b.position = g.position;
                if (g.is_planet()) b.multiplicity = g.planets;  // listed once, runs in every planet
            } else {
                b.position = n.quantity("position", dim::length, "20 mm");
            }
            if (auto lc = n.get("locating")) b.locating = lc->as_bool();
            int count = 1;
            if (auto c = n.get("count")) {
                count = c->as_int();
                if (count < 1 || count > 8) c->fail("count must be 1..8 (identical bearings side by side)");
            }
            for (int i = 0; i < count; ++i) {
                gearbox::Bearing bi = b;
                if (count > 1) {
                    bi.name = b.name + "." + std::to_string(i + 1);
                    if (!names.insert(bi.name).second)
                        n.at("count").fail("bearing name '" + bi.name + "' (of 'count' side by side) is already taken");
                }
                model.gearbox.bearings.push_back(bi);
            }
        }
        // A free gear or a planet needs bearings under it (its speed differs from the shaft's).
        for (size_t g = 0; g < model.gearbox.gears.size(); ++g) {
            if (!model.gearbox.gears[g].free && !model.gearbox.gears[g].is_planet()) continue;
            bool any = false;
            for (const auto& b : model.gearbox.bearings) any = any || b.under_gear == static_cast<int>(g);
            if (!any)
                root.at("gears").items()[g].fail("gear '" + model.gearbox.gears[g].spec.name +
                                                 "' turns on its own bearings ('mount: free' or a planet) but no bearing "
                                                 "has 'under_gear' naming it");
        }
    }

    void load_seals() {
        if (!root.has("seals")) return;
        std::set<std::string> names;
        for (const auto& n : root.at("seals").items()) {
            n.allow_keys({"name", "shaft", "diameter", "note"});
            gearbox::Seal s;
            s.name = n.at("name").as_name();
            if (!names.insert(s.name).second) n.at("name").fail("duplicate seal name '" + s.name + "'");
            s.shaft = shaft_ref(n.at("shaft"));
            s.diameter = n.positive_quantity("diameter", dim::length, "40 mm");
            model.gearbox.seals.push_back(s);
        }
    }

    void load_clutches() {
        if (!root.has("clutches")) return;
        std::set<std::string> names;
        for (const auto& n : root.at("clutches").items()) {
            n.allow_keys({"name", "engages", "interfaces", "r_inner", "r_outer", "clearance", "roughness", "oil_supply",
                          "note"});
            gearbox::ClutchPack c;
            c.pack.name = n.at("name").as_name();
            if (!names.insert(c.pack.name).second) n.at("name").fail("duplicate clutch name '" + c.pack.name + "'");
            c.gear = gear_ref(n.at("engages"));
            if (!model.gearbox.gears[c.gear].free)
                n.at("engages").fail("a clutch engages a 'mount: free' gear (it locks that gear to its shaft)");
            c.pack.interfaces = n.at("interfaces").as_int();
            if (c.pack.interfaces < 1 || c.pack.interfaces > 100) n.at("interfaces").fail("must be 1-100");
            c.pack.r_inner = n.positive_quantity("r_inner", dim::length, "55 mm");
            c.pack.r_outer = n.positive_quantity("r_outer", dim::length, "72 mm");
            if (c.pack.r_outer <= c.pack.r_inner) n.at("r_outer").fail("r_outer must exceed r_inner");
            c.pack.clearance = n.positive_quantity("clearance", dim::length, "0.15 mm");
            if (auto r = n.get("roughness")) c.pack.roughness = r->as_quantity(dim::length, "1 um");
            if (c.pack.roughness > 0 && c.pack.clearance / c.pack.roughness < 3)
                n.at("clearance").fail("clearance below 3x the roughness: the open-pack drag model (full film, "
                                       "Patir & Cheng shear factor for H >= 3) does not apply");
            if (auto q = n.get("oil_supply")) {
                c.pack.oil_supply = q->as_quantity(units::make_dim(3, 0, -1, 0), "0.4 L/min");
                if (c.pack.oil_supply < 0) q->fail("must not be negative");
            }
            model.gearbox.clutches.push_back(c);
        }
    }
};

void load_options(const YamlNode& n, solver::LossOptions& o) {
    n.allow_keys({"losses", "gear_loss_factor", "mesh_friction", "film_thermal_correction", "lambda_roughness",
                  "gear_friction"});
    if (auto l = n.get("losses")) {
        l->allow_keys({"mesh", "churning", "bearings", "seals"});
        if (auto v = l->get("mesh")) o.mesh = v->as_bool();
        if (auto v = l->get("churning")) o.churning = v->as_bool();
        if (auto v = l->get("bearings")) o.bearings = v->as_bool();
        if (auto v = l->get("seals")) o.seals = v->as_bool();
    }
    if (auto v = n.get("gear_loss_factor"))
        o.loss_factor = v->as_enum<mesh::LossFactorModel>({{"ohlendorf", mesh::LossFactorModel::ohlendorf},
                                                          {"buckingham", mesh::LossFactorModel::buckingham},
                                                          {"wimmer", mesh::LossFactorModel::wimmer}});
    if (auto v = n.get("mesh_friction"))
        o.friction = v->as_enum<mesh::FrictionModel>({{"schlenk", mesh::FrictionModel::schlenk},
                                                      {"iso_6336_20", mesh::FrictionModel::iso_6336_20},
                                                      {"fernandes_mixed", mesh::FrictionModel::fernandes_mixed},
                                                      {"ehl_local", mesh::FrictionModel::ehl_local}});
    if (auto v = n.get("film_thermal_correction"))
        o.film_correction = v->as_enum<mesh::ThermalFilmCorrection>({{"gupta", mesh::ThermalFilmCorrection::gupta},
                                                                     {"simplified", mesh::ThermalFilmCorrection::simplified},
                                                                     {"none", mesh::ThermalFilmCorrection::none}});
    if (auto v = n.get("lambda_roughness"))
        o.lambda_roughness = v->as_enum<solver::LambdaRoughness>({{"average_Ra", solver::LambdaRoughness::average_Ra},
                                                                  {"composite_Rq", solver::LambdaRoughness::composite_Rq}});
    if (auto gf = n.get("gear_friction")) {
        gf->allow_keys({"mu_bl", "mu_ehl"});
        if (auto v = gf->get("mu_bl")) o.gear_mu_bl = v->as_number();
        if (auto v = gf->get("mu_ehl")) o.gear_mu_ehl = v->as_number();
        if (!(o.gear_mu_bl > 0 && o.gear_mu_bl < 1 && o.gear_mu_ehl >= 0 && o.gear_mu_ehl < o.gear_mu_bl))
            gf->fail("need 0 <= mu_ehl < mu_bl < 1");
    }
}

void load_thermal(const YamlNode& n, solver::ThermalSettings& t) {
    n.allow_keys({"mode", "oil_temperature", "ambient", "heat_rejection", "max_oil_temperature", "heat_capacity",
                  "network"});
    if (auto net = n.get("network")) {
        if (n.has("heat_capacity")) net->fail("give either 'heat_capacity' (one node) or 'network', not both");
        net->allow_keys({"oil", "housing", "oil_to_housing", "clutch_packs", "clutch_to_oil", "note"});
        auto& w = t.network;
        w.C_oil = net->positive_quantity("oil", units::dim::heat_capacity, "2 kJ/K");
        const auto conductance = units::make_dim(2, 1, -3, -1);
        if (net->has("housing")) {
            w.C_housing = net->positive_quantity("housing", units::dim::heat_capacity, "5 kJ/K");
            w.G_oil_housing = net->positive_quantity("oil_to_housing", conductance, "30 W/K");
        } else if (net->has("oil_to_housing")) {
            net->at("oil_to_housing").fail("'oil_to_housing' needs a 'housing' node");
        }
        if (net->has("clutch_packs")) {
            w.C_clutch = net->positive_quantity("clutch_packs", units::dim::heat_capacity, "1 kJ/K");
            w.G_clutch_oil = net->positive_quantity("clutch_to_oil", conductance, "40 W/K");
        } else if (net->has("clutch_to_oil")) {
            net->at("clutch_to_oil").fail("'clutch_to_oil' needs a 'clutch_packs' node");
        }
        t.heat_capacity = w.total_capacity();
    }
    if (auto hc = n.get("heat_capacity")) {
        t.heat_capacity = hc->as_quantity(units::dim::heat_capacity, "25 kJ/K");
        if (!(t.heat_capacity > 0)) hc->fail("heat capacity must be positive");
        t.network = {};
        t.network.C_oil = t.heat_capacity;
    }
    t.ambient = n.at("ambient").as_temperature();
    t.mode = n.has("mode") ? n.at("mode").as_enum<solver::ThermalMode>({{"stabilised", solver::ThermalMode::stabilised},
                                                                        {"stabilized", solver::ThermalMode::stabilised},
                                                                        {"fixed", solver::ThermalMode::fixed}})
                           : solver::ThermalMode::stabilised;
    if (t.mode == solver::ThermalMode::fixed) t.oil_temperature = n.at("oil_temperature").as_temperature();
    else if (n.has("oil_temperature")) t.oil_temperature = n.at("oil_temperature").as_temperature();
    if (auto m = n.get("max_oil_temperature")) {
        t.equilibrium.T_max = m->as_temperature();
        if (t.equilibrium.T_max <= t.ambient + 1) m->fail("must be above the ambient temperature");
    }
    if (t.mode == solver::ThermalMode::stabilised || n.has("heat_rejection")) {
        const YamlNode h = n.at("heat_rejection");
        h.allow_keys({"resistance", "reference_speed", "speed_exponent", "housing"});
        if (h.has("resistance") == h.has("housing"))
            h.fail("give exactly one of 'resistance' (equivalent thermal resistance) or 'housing' (surface model)");
        if (h.has("resistance")) {
            thermal::ThermalResistance r;
            r.R0 = h.positive_quantity("resistance", units::dim::thermal_resistance, "0.12 K/W");
            if (h.has("reference_speed")) {
                r.n_ref = h.positive_quantity("reference_speed", units::dim::angular_speed, "600 rpm");
                r.exponent = h.at("speed_exponent").as_number();
                if (!(r.exponent >= 0 && r.exponent < 2)) h.at("speed_exponent").fail("exponent outside 0..2");
            }
            t.rejection.model = r;
        } else {
            const YamlNode s = h.at("housing");
            s.allow_keys({"area", "emissivity", "height", "length", "air_speed"});
            thermal::HousingSurface hs;
            hs.area = s.positive_quantity("area", units::dim::area, "0.5 m^2");
            if (s.has("emissivity")) {
                hs.emissivity = s.at("emissivity").as_number();
                if (!(hs.emissivity >= 0 && hs.emissivity <= 1)) s.at("emissivity").fail("emissivity must be in [0, 1]");
            }
            if (s.has("height")) hs.height = s.positive_quantity("height", units::dim::length, "0.3 m");
            hs.length = s.has("length") ? s.positive_quantity("length", units::dim::length, "0.3 m") : hs.height;
            if (s.has("air_speed")) {
                hs.air_speed = s.at("air_speed").as_quantity(units::dim::velocity, "2 m/s");
                if (hs.air_speed < 0) s.at("air_speed").fail("air speed cannot be negative");
            }
            t.rejection.model = hs;
        }
    }
}

std::vector<double> load_axis(const YamlNode& n, const units::Dimension& d, const char* example) {
    std::vector<double> v;
    if (n.is_sequence()) {
        for (const auto& it : n.items()) v.push_back(it.as_quantity(d, example));
    } else if (n.is_map()) {
        n.allow_keys({"from", "to", "count"});
        const double a = n.at("from").as_quantity(d, example), b = n.at("to").as_quantity(d, example);
        const int c = n.at("count").as_int();
        if (c < 1 || c > 1000000) n.at("count").fail("count must be 1..1000000");
        for (int i = 0; i < c; ++i) v.push_back(c == 1 ? a : a + (b - a) * i / (c - 1));
    } else {
        n.fail(std::string("expected a list of values or {from, to, count}, e.g. [") + example + "]");
    }
    if (v.empty()) n.fail("empty list");
    return v;
}

}  // namespace

void replace_oil(Case& c, const lubricant::Oil& oil) {
    c.model.oil = oil;
    for (auto& b : c.model.gearbox.bearings) set_bearing_friction(b.spec, oil);
}

Case load_case(const std::string& file, const std::optional<std::string>& ratio_override) {
    const std::string text = read_input_file(file, kMaxYamlFileBytes);  // a regular file, bounded (io/csv_read.hpp)
    return load_case_text(text, file, fs::path(file).parent_path().string(), ratio_override);
}

namespace {
Case load_case_impl(const std::string& text, const std::string& file, const std::string& base_dir,
                    const std::optional<std::string>& ratio_override);
}

Case load_case_text(const std::string& text, const std::string& file, const std::string& base_dir,
                    const std::optional<std::string>& ratio_override) {
    try {
        return load_case_impl(text, file, base_dir, ratio_override);
    } catch (const YAML::Exception& e) {
        // Any structural surprise inside yaml-cpp is still an input error with its position.
        throw InputError(file, e.mark.is_null() ? 0 : e.mark.line + 1, e.mark.is_null() ? 0 : e.mark.column + 1, "",
                         "unexpected YAML structure: " + e.msg);
    }
}

namespace {
Case load_case_impl(const std::string& text, const std::string& file, const std::string& base_dir,
                    const std::optional<std::string>& ratio_override) {
    Case c;
    c.file = file;
    const YamlNode root = YamlNode::load_text(text, file);
    root.allow_keys({"name", "description", "oil", "materials", "shafts", "gears", "meshes", "bearings", "seals",
                     "clutches", "housing", "thermal", "gearbox", "operating", "options", "mechanisms", "calibration", "vehicle",
                     "sweep"});
    c.sweep = read_sweep(root);
    auto& m = c.model;
    m.name = root.has("name") ? root.at("name").as_title() : fs::path(file).stem().string();

    const YamlNode oil = root.at("oil");
    if (oil.is_scalar()) {
        const fs::path p = fs::path(base_dir) / oil.as_string();
        std::error_code ec;  // non-throwing: a malformed name is an input error, not a crash
        if (!fs::is_regular_file(p, ec)) oil.fail("oil file '" + excerpt(p.string(), 200) + "' does not exist or is not a file");
        m.oil = load_oil_file(p.string());
    } else {
        m.oil = load_oil(oil);
    }

    Loader L{root, m, {}, {}, {}};
    L.load_materials();
    L.load_shafts();
    L.load_gears();
    L.load_meshes();
    L.load_bearings();
    L.load_seals();
    L.load_clutches();

    const YamlNode gbn = root.at("gearbox");
    gbn.allow_keys({"input", "output", "ratio", "ratios"});
    m.gearbox.input_shaft = L.shaft_ref(gbn.at("input"));
    m.gearbox.output_shaft = L.shaft_ref(gbn.at("output"));
    if (auto rs = gbn.get("ratios")) {
        std::map<std::string, std::vector<int>> ratios;
        for (auto& [name, rn] : rs->entries()) {
            if (const std::string why = name_problem(name, YamlNode::kMaxNameBytes); !why.empty())
                rn.fail("ratio '" + excerpt(name) + "': " + why);
            rn.allow_keys({"engage", "note"});
            std::vector<int> eng;
            for (const auto& g : rn.at("engage").items()) {
                const int gi = L.gear_ref(g);
                if (!m.gearbox.gears[gi].free) g.fail("gear '" + g.as_string() + "' is fixed to its shaft; only 'mount: free' gears are engaged");
                eng.push_back(gi);
            }
            ratios[name] = eng;
            c.ratio_names.push_back(name);
        }
        std::string sel = ratio_override ? *ratio_override : (gbn.has("ratio") ? gbn.at("ratio").as_string() : "");
        if (sel.empty()) gbn.fail("several ratios are defined; select one with 'ratio' (or --ratio)");
        auto it = ratios.find(sel);
        if (it == ratios.end()) {
            std::string all;
            for (const auto& n : c.ratio_names) all += (all.empty() ? "" : ", ") + n;
            if (ratio_override) throw InputError(file, 0, 0, "--ratio", "unknown ratio '" + sel + "'; defined: " + all);
            gbn.at("ratio").fail("unknown ratio '" + excerpt(sel) + "'; defined: " + all);
        }
        m.gearbox.engaged = it->second;
        c.ratio = sel;
    } else if (ratio_override) {
        throw InputError(file, 0, 0, "--ratio", "the config defines no 'gearbox.ratios'");
    }

    const YamlNode h = root.at("housing");
    h.allow_keys({"oil_volume", "oil_level", "lubrication", "note"});
    const auto lubrication = h.has("lubrication") ? h.at("lubrication").as_enum<solver::Lubrication>(
                                                        {{"dip", solver::Lubrication::dip}, {"injection", solver::Lubrication::injection}})
                                                  : solver::Lubrication::dip;
    m.gearbox.oil_volume = h.positive_quantity("oil_volume", units::dim::volume, "2 L");
    if (auto lv = h.get("oil_level")) m.gearbox.oil_level = lv->as_quantity(units::dim::length, "-60 mm");

    load_thermal(root.at("thermal"), m.thermal);
    if (auto o = root.get("options")) load_options(*o, m.options);
    if (auto mech = root.get("mechanisms")) load_mechanism_settings(*mech, m);
    if (auto cal = root.get("calibration")) load_calibration(*cal, m);

    const YamlNode op = root.at("operating");
    op.allow_keys({"speeds", "torques", "points"});
    if (op.has("points")) {
        if (op.has("speeds") || op.has("torques")) op.fail("give either 'points' or 'speeds' and 'torques'");
        c.grid.is_grid = false;
        for (const auto& p : op.at("points").items()) {
            const auto pr = p.items();
            if (pr.size() != 2) p.fail("each point is [speed, torque], e.g. [800 rpm, 250 N*m]");
            c.grid.points.emplace_back(pr[0].as_quantity(units::dim::angular_speed, "800 rpm"),
                                       pr[1].as_quantity(units::dim::torque, "250 N*m"));
        }
        if (c.grid.points.empty()) op.at("points").fail("empty list");
    } else {
        c.grid.speeds = load_axis(op.at("speeds"), units::dim::angular_speed, "800 rpm");
        c.grid.torques = load_axis(op.at("torques"), units::dim::torque, "250 N*m");
    }

    if (auto v = root.get("vehicle")) {
        load_vehicle(*v, c);
        for (size_t i = 0; i < c.vehicle->gears.size(); ++i)
            if (std::find(c.ratio_names.begin(), c.ratio_names.end(), c.vehicle->gears[i]) == c.ratio_names.end())
                v->at("gears").items()[i].fail("'" + excerpt(c.vehicle->gears[i]) + "' is not one of gearbox.ratios");
    }

    // Errors found once the model is assembled point at the item they come from.
    try {
        m.finalise();
    } catch (const gearbox::TopologyError& e) {
        (e.section.empty() ? gbn : locate_in_case(root, e.section, e.item, e.key)).fail(e.message);
    }
    if (const auto issues = solver::validate(m); !issues.empty()) {
        const auto& first = issues.front();
        locate_in_case(root, first.section, first.item, first.key).fail(solver::summarise(issues));
    }
    // Ohlendorf's closed form (and the single-pair average) assume 1 <= eps_alpha < 2.
    if (m.options.loss_factor != mesh::LossFactorModel::wimmer)
        for (size_t i = 0; i < m.layout.meshes.size(); ++i) {
            const auto& g = m.layout.meshes[i].geom;
            if (g.eps_alpha < 1.0 || g.eps_alpha >= 2.0)
                root.at("options").at("gear_loss_factor").fail(fmt::format(
                    "mesh '{}' has eps_alpha = {:.3f}, outside the 1..2 that this closed form assumes; use 'wimmer' "
                    "(rigid load sharing over the contact lines)",
                    m.gearbox.meshes[i].name, g.eps_alpha));
        }
    check_case_plausibility(root, c, lubrication);
    return c;
}
}  // namespace

}  // namespace gearloss::io
