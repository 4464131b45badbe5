// Case loader: materials, shafts, gears and meshes (the Loader's gear-train sections, docs/config.md).
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <set>
#include <string>

#include "gearloss/case/config_internal.hpp"
#include "gearloss/io/csv_read.hpp"

namespace gearloss::io::detail {

namespace dim = units::dim;

int Loader::shaft_ref(const YamlNode& n) {
    const std::string s = n.as_string();
    auto it = shaft_index.find(s);
    if (it == shaft_index.end()) n.fail("unknown shaft '" + excerpt(s) + "'");
    return it->second;
}

int Loader::gear_ref(const YamlNode& n) {
    const std::string s = n.as_string();
    auto it = gear_index.find(s);
    if (it == gear_index.end()) n.fail("unknown gear '" + excerpt(s) + "'");
    return it->second;
}

geometry::Material Loader::material(const YamlNode& n) {
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

void Loader::load_materials() {
    materials["steel"] = geometry::Material{};
    if (auto ms = root.get("materials"))
        for (auto& [name, node] : ms->entries()) materials[name] = material(node);
}

void Loader::load_shafts() {
    const YamlNode s = root.at("shafts");
    for (const auto& item : s.items()) {
        gearbox::Shaft shaft;
        if (item.is_scalar()) shaft.name = item.as_name();
        else {
            item.allow_keys({"name", "fixed", "mass", "diameter", "length", "material", "density", "note"});
            shaft.name = item.at("name").as_name();
            if (auto f = item.get("fixed")) shaft.fixed = f->as_bool();
            // Its weight on its bearings (gearbox/weights.cpp): a mass, or a cylinder's size and density.
            if (item.has("mass")) {
                shaft.mass = item.positive_quantity("mass", dim::mass, "12 kg");
                for (const char* k : {"diameter", "length", "material", "density"})
                    if (item.has(k)) item.at(k).fail(std::string("'mass' is given: '") + k + "' would not be read");
            }
            if (item.has("diameter")) shaft.diameter = item.positive_quantity("diameter", dim::length, "40 mm");
            if (item.has("length")) shaft.length = item.positive_quantity("length", dim::length, "200 mm");
            if (item.has("material")) shaft.density = material(item.at("material")).density;
            if (item.has("density")) shaft.density = item.positive_quantity("density", dim::density, "7850 kg/m^3");
        }
        if (shaft_index.count(shaft.name)) item.fail("duplicate shaft name '" + excerpt(shaft.name) + "'");
        shaft_index[shaft.name] = static_cast<int>(model.gearbox.shafts.size());
        model.gearbox.shafts.push_back(shaft);
    }
    if (model.gearbox.shafts.size() < 2) s.fail("a gearbox needs at least two shafts");
}

void Loader::load_gears() {
    for (const auto& n : root.at("gears").items()) {
        n.allow_keys({"name", "shaft", "position", "teeth", "module", "profile_shift", "face_width", "pressure_angle",
                      "helix_angle", "hand", "material", "Ra", "Rq", "mount", "immersion", "addendum_coefficient",
                      "dedendum_coefficient", "internal", "carrier", "planets", "tip_diameter", "tip_alteration_factor", "mass",
                      "bore", "density", "note"});
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
        // Gear modules run from 0.05 mm (fine pitch) to 100 mm; outside that the unit is wrong, and
        // the gear pair would fail later with a message about the train instead of the module.
        if (!(s.mn >= 0.05e-3 && s.mn <= 100e-3))
            n.at("module").fail(fmt::format("module '{}' is outside 0.05..100 mm; check the unit (e.g. '3.5 mm')",
                                            excerpt(n.at("module").as_string())));
        const std::string key = "gears." + s.name + ".";
        const auto unless_given = [&](const char* k, const std::string& value, const char* why) {
            if (!n.has(k)) assume(assumed, n, key + k, value, why);
        };
        s.x = n.has("profile_shift") ? n.at("profile_shift").as_number() : 0.0;
        if (!(s.x > -1.5 && s.x < 2.5)) n.at("profile_shift").fail("profile shift coefficient outside -1.5..2.5");
        s.b = n.positive_quantity("face_width", dim::length, "35 mm");
        s.alpha_n = n.has("pressure_angle") ? n.at("pressure_angle").as_angle("20 deg") : 20.0 * deg;
        if (!(s.alpha_n > 10 * deg && s.alpha_n < 35 * deg))
            n.at("pressure_angle").fail("pressure angle outside 10..35 deg");
        s.beta = n.has("helix_angle") ? n.at("helix_angle").as_angle("20 deg") : 0.0;
        if (!(s.beta >= 0 && s.beta < 45 * deg)) n.at("helix_angle").fail("helix angle outside 0..45 deg (give the hand separately)");
        if (s.beta > 0) {
            s.hand = n.at("hand").as_enum<geometry::Hand>({{"right", geometry::Hand::right}, {"left", geometry::Hand::left}});
        } else {
            s.hand = geometry::Hand::spur;
        }
        // Basic-rack coefficients: ISO 53 has 1.0 and 1.25; short-tooth and high-contact-ratio racks stay
        // within these bounds. Checked here so that a wrong one is blamed, not the profile shift.
        if (n.has("addendum_coefficient")) {
            s.ha_star = n.at("addendum_coefficient").as_number();
            if (!(s.ha_star >= 0.5 && s.ha_star <= 1.6))
                n.at("addendum_coefficient").fail(fmt::format("addendum coefficient {:g} outside 0.5..1.6 (ISO 53: 1.0)", s.ha_star));
        }
        if (n.has("dedendum_coefficient")) {
            s.hf_star = n.at("dedendum_coefficient").as_number();
            if (!(s.hf_star >= 0.8 && s.hf_star <= 2.0))
                n.at("dedendum_coefficient").fail(fmt::format("dedendum coefficient {:g} outside 0.8..2.0 (ISO 53: 1.25)", s.hf_star));
        }
        if (n.has("tip_diameter") && n.has("tip_alteration_factor"))
            n.at("tip_alteration_factor").fail("give either 'tip_diameter' or 'tip_alteration_factor', not both");
        if (n.has("tip_diameter")) s.tip_diameter = n.positive_quantity("tip_diameter", dim::length, "82.46 mm");
        if (auto k = n.get("tip_alteration_factor")) {
            s.tip_alteration_factor = k->as_number();
            if (!(*s.tip_alteration_factor > -1.0 && *s.tip_alteration_factor <= 0.5))
                k->fail("tip alteration factor k outside -1..0.5 (ISO 21771 sign: k <= 0 shortens the tip)");
        }
        s.material = n.has("material") ? material(n.at("material")) : materials["steel"];
        if (n.has("density")) s.material.density = n.positive_quantity("density", dim::density, "7850 kg/m^3");
        // Its weight on the bearings (gearbox/weights.cpp): a mass, else a disc less its bore.
        if (n.has("mass")) {
            g.mass = n.positive_quantity("mass", dim::mass, "2.5 kg");
            for (const char* k : {"bore", "density"})
                if (n.has(k)) n.at(k).fail(std::string("'mass' is given: '") + k + "' would not be read");
        }
        if (n.has("bore")) {
            g.bore = n.quantity("bore", dim::length, "40 mm");
            if (!(*g.bore >= 0)) n.at("bore").fail("bore diameter cannot be negative");
        }
        if (n.has("Ra")) s.Ra = n.positive_quantity("Ra", dim::length, "0.5 um");
        unless_given("profile_shift", "0", "no profile shift");
        unless_given("pressure_angle", "20 deg", "ISO 53 basic rack");
        unless_given("helix_angle", "0 deg", "spur gear");
        unless_given("addendum_coefficient", number_text(s.ha_star), "ISO 53 basic rack");
        unless_given("dedendum_coefficient", number_text(s.hf_star), "ISO 53 basic rack");
        unless_given("material", "steel", "E = 210 GPa, Poisson 0.3, 7850 kg/m^3");
        unless_given("Ra", number_text(s.Ra * 1e6) + " um", "ground flanks (geometry::GearSpec default)");
        if (!n.has("Rq"))
            assume(assumed, n, key + "Rq", "1.25 Ra", "Gaussian surface: Rq = 1.25 Ra");
        if (n.has("Rq")) s.Rq = n.positive_quantity("Rq", dim::length, "0.6 um");
        if (s.Ra > 50e-6) n.at("Ra").fail("roughness above 50 um; check the unit");
        // The lambda ratio divides by the roughness: below the finest superfinished flanks (Ra of a few
        // hundredths of a micrometre) it would call any film a full film, 1e-300 um a lambda of 1e299.
        for (const char* k : {"Ra", "Rq"})
            if (n.has(k) && (k[1] == 'a' ? s.Ra : s.Rq.value_or(s.Ra)) < 1e-9)
                n.at(k).fail(fmt::format("roughness '{}' is below 0.001 um (1 nm), smoother than any gear flank; check "
                                         "the unit (e.g. '0.5 um')",
                                         excerpt(n.at(k).as_string())));
        if (s.Rq && *s.Rq > 60e-6) n.at("Rq").fail("roughness above 60 um; check the unit");
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

void Loader::load_meshes() {
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
        m.angle = n.has("angle") ? n.at("angle").as_angle("30 deg") : 0.0;
        m.centre_distance = n.opt_quantity("centre_distance", dim::length, "95 mm");
        if (m.centre_distance && *m.centre_distance <= 0) n.at("centre_distance").fail("must be positive");
        try {
            (void)geometry::pair_geometry(model.gearbox.gears[m.gear[0]].spec, model.gearbox.gears[m.gear[1]].spec,
                                          m.centre_distance);
        } catch (const geometry::GeometryError& e) {
            // At the mesh's own key when the error names one (a centre distance the shifts do not give).
            (!e.key.empty() && n.has(e.key) ? n.at(e.key) : n).fail(e.message);
        }
        model.gearbox.meshes.push_back(m);
    }
}

}  // namespace gearloss::io::detail

namespace gearloss::io::detail {

Eigen::Vector3d load_gravity(const YamlNode& n) {
    Eigen::Vector3d g;
    if (n.is_sequence()) {
        const auto c = n.items();
        if (c.size() != 3) n.fail("gravity as a direction [x, y, z] needs three numbers, e.g. [0, -1, 0]");
        for (int i = 0; i < 3; ++i) g[i] = c[static_cast<size_t>(i)].as_number();
        if (!g.allFinite() || g.norm() < 1e-9) n.fail("the direction of gravity cannot be a zero vector");
        return g.normalized();
    }
    // An angle in the plane of the mesh angles (0 deg along +x, 90 deg up): -90 deg is straight down.
    const double a = n.as_angle("-90 deg");
    if (!std::isfinite(a)) n.fail("the direction of gravity must be a finite angle");
    return {std::cos(a), std::sin(a), 0.0};
}

void note_weights(Case& c) {
    std::erase_if(c.assumed, [](const AssumedValue& a) {
        return (a.key.starts_with("gears.") || a.key.starts_with("shafts.")) && a.key.ends_with(".mass");
    });
    const auto& gb = c.model.gearbox;
    const auto& L = c.model.layout;
    if (L.gear_mass.size() != gb.gears.size() || L.shaft_mass.size() != gb.shafts.size()) return;
    const auto carried = [&](int shaft, int gear) {
        return std::ranges::any_of(gb.bearings, [&](const auto& b) { return b.shaft == shaft || b.under_gear == gear; });
    };
    for (size_t g = 0; g < gb.gears.size(); ++g) {
        const auto& gear = gb.gears[g];
        if (gear.mass || !carried(gear.shaft, static_cast<int>(g))) continue;  // given, or its weight reaches no bearing
        std::string hollow;
        if (gear.spec.internal) hollow = "; an internal gear: its teeth and a rim of 3 m_n outside its root circle (assumed)";
        else if (gear.bore) hollow = ", less the given bore";
        else if (gear.free || gear.is_planet()) hollow = ", less the outer diameter of the bearings under it (its bore)";
        else hollow = ", less its shaft's diameter when inside its root circle (the shaft is counted with the shaft), else solid";
        c.assumed.push_back({"gears." + gear.spec.name + ".mass", fmt::format("{:.4g} kg", L.gear_mass[g]),
                             fmt::format("disc of diameter sqrt((d_a^2 + d_f^2)/2) (teeth half metal) over the face width{}, "
                                         "{:g} kg/m^3",
                                         hollow, gear.spec.material.density),
                             located_at(case_location(c, "gears", gear.spec.name))});
    }
    for (size_t s = 0; s < gb.shafts.size(); ++s) {
        const auto& shaft = gb.shafts[s];
        const bool supported = std::ranges::any_of(
            gb.bearings, [&](const auto& b) { return b.shaft == static_cast<int>(s) && b.under_gear < 0; });
        if (shaft.mass || !supported) continue;
        c.assumed.push_back(
            {"shafts." + shaft.name + ".mass", fmt::format("{:.4g} kg", L.shaft_mass[s]),
             fmt::format("cylinder of {} over {}, {:g} kg/m^3, centred between its bearings (gears, hubs and carrier plates "
                         "not included)",
                         shaft.diameter ? "the given diameter" : "its largest bearing bore (its diameter is not given)",
                         shaft.length ? "the given length" : "its bearing span (its length is not given)", shaft.density),
             located_at(case_location(c, "shafts", shaft.name))});
    }
}

}  // namespace gearloss::io::detail
