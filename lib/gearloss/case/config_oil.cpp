// Case loader: the oil (`oil:` inline or an oil file) -> lubricant::Oil (docs/config.md).
#include <algorithm>
#include <fmt/format.h>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "gearloss/case/config.hpp"
#include "gearloss/case/config_internal.hpp"
#include "gearloss/case/declared_assumptions.hpp"

namespace gearloss::io {

namespace dim = units::dim;
using lubricant::BaseOil;

namespace {

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

namespace {
// A table over temperature (viscosity points, piezoviscosity): each temperature above the one
// before, as written, so that no two entries share an abscissa; blamed on the later entry.
void require_ascending(const YamlNode& before, double T_before, const YamlNode& at, double T) {
    if (T == T_before)
        at.fail(fmt::format("temperature '{}' is listed twice (also at line {}); each temperature once",
                            excerpt(at.as_string()), before.location().line));
    if (T < T_before)
        at.fail(fmt::format("temperature '{}' is below the one before it ('{}'); list the temperatures in ascending order",
                            excerpt(at.as_string()), excerpt(before.as_string())));
}
}  // namespace

namespace {
// The fitted viscosity law must describe a lubricant from 0 degC to the oil's permissible
// temperature: a law whose Vogel pole lies inside, or that runs past the bounds of
// lubricant::Oil::nu_mm2s (0.5 and 1e7 mm^2/s) there, is blamed on its points, not later on
// the case's ambient or oil temperature.
void check_viscosity_law_range(const lubricant::Oil& oil, const YamlNode& viscosity) {
    // ASTM D341 constants given as such are checked by the model's validation (solver::validate).
    if (!viscosity.has("points")) return;
    const YamlNode at = viscosity.at("points");
    const double T_lo = 273.15, T_hi = oil.max_temperature;
    if (const auto* vg = std::get_if<lubricant::VogelLaw>(&oil.viscosity); vg && 273.15 - vg->c_C >= T_lo)
        at.fail(fmt::format("the fitted Vogel law has its pole at {:.1f} degC, inside the oil's range 0..{:.0f} degC "
                            "(to its max_temperature): check the points",
                            -vg->c_C, T_hi - 273.15));
    constexpr double nu_floor = 0.5, nu_cap = 1e7;  // mm^2/s, the bounds of Oil::nu_mm2s
    for (double T = T_lo; T <= T_hi + 1e-9; T += std::max(1.0, (T_hi - T_lo) / 400)) {
        const double nu = oil.nu_mm2s(T);
        if (nu > nu_floor && nu < nu_cap) continue;
        at.fail(fmt::format("the fitted viscosity law gives {} mm^2/s at {:.1f} degC, inside the oil's range 0..{:.0f} "
                            "degC (to its max_temperature): check the points",
                            nu >= nu_cap ? "1e7 or more" : "0.5 or less", T - 273.15, T_hi - 273.15));
    }
}
}  // namespace

lubricant::Oil load_oil(const YamlNode& n, std::vector<AssumedValue>* assumed) {
    using detail::assume;
    using detail::number_text;
    n.allow_keys({"name", "base", "viscosity", "density", "thermal_expansion", "piezoviscosity", "X_L",
                  "thermal_conductivity", "specific_heat", "bearing_friction", "gear_friction", "traction", "rheology",
                  "max_temperature", "note", "assumed"});
    lubricant::Oil oil;
    oil.name = n.at("name").as_title();
    oil.base = parse_base(n.at("base"));
    oil.max_temperature = lubricant::default_max_temperature(oil.base);
    if (!n.has("max_temperature"))
        assume(assumed, n, "oil.max_temperature", number_text(oil.max_temperature - 273.15) + " degC",
               fmt::format("permissible sump temperature by base oil ({}): mineral 95 degC as rated in ISO/TR 14179-1, "
                           "synthetic and ATF typical datasheet limits (docs/config.md)",
                           lubricant::to_string(oil.base)));
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
        std::optional<YamlNode> previous;
        for (const auto& p : pts) {
            const auto pair = p.items();
            if (pair.size() != 2) p.fail("each point is [temperature, kinematic viscosity], e.g. [40 degC, 112.35 cSt]");
            const double T = pair[0].as_temperature();
            const double nu = pair[1].as_quantity(dim::kinematic_viscosity, "112.35 cSt");
            if (!(nu > 0)) pair[1].fail("viscosity must be positive");
            if (previous) require_ascending(*previous, tv.back().first, pair[0], T);
            if (!tv.empty() && !(nu * 1e6 < tv.back().second))
                pair[1].fail("viscosity must fall as temperature rises (" + excerpt(pair[1].as_string()) +
                             " is not below the point before)");
            tv.emplace_back(T, nu * 1e6);
            previous = pair[0];
        }
        std::string law = tv.size() == 3 ? "vogel" : "astm_d341";
        if (auto l = v.get("law")) law = l->as_enum<std::string>({{"vogel", "vogel"}, {"astm_d341", "astm_d341"}});
        else
            assume(assumed, v, "oil.viscosity.law", law,
                   fmt::format("chosen by the number of points ({}): 3 points select Vogel, else ASTM D341", tv.size()));
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
        if (!d.has("at")) assume(assumed, d, "oil.density.at", "15 degC", "densities are quoted at 15 degC (ISO 12185)");
        oil.rho15 = rho;  // corrected below once the expansion is known
        oil.expansion = 0;
        const double beta = n.has("thermal_expansion")
                                ? n.at("thermal_expansion").as_quantity(dim::per_kelvin, "6.8e-4 1/K")
                                : 6.5e-4;
        if (!n.has("thermal_expansion"))
            assume(assumed, n, "oil.thermal_expansion", "6.5e-4 1/K", "typical of gear oils (lubricant::Oil default)");
        oil.rho15 = rho / (1.0 - beta * (T - 288.15));
        oil.expansion = beta;
    } else {
        oil.rho15 = d.as_quantity(dim::density, "885 kg/m^3");
        if (!(oil.rho15 > 300 && oil.rho15 < 2500)) d.fail("density outside 300..2500 kg/m^3; check the unit");
        if (auto e = n.get("thermal_expansion")) oil.expansion = e->as_quantity(dim::per_kelvin, "6.8e-4 1/K");
        else assume(assumed, n, "oil.thermal_expansion", number_text(oil.expansion) + " 1/K",
                    "typical of gear oils (lubricant::Oil default)");
    }
    if (!(oil.expansion >= 0 && oil.expansion < 5e-3))
        n.at("thermal_expansion").fail("expansion coefficient must be in [0, 5e-3] 1/K (positive: density falls with T)");

    if (!n.has("piezoviscosity"))
        assume(assumed, n, "oil.piezoviscosity", "gold",
               fmt::format("Gold et al. (2001) alpha = s nu^t for base oil {} (Fernandes 2015, Table 2.7)",
                           lubricant::to_string(oil.base)));
    if (auto pz = n.get("piezoviscosity")) {
        if (pz->is_scalar()) {
            if (pz->as_string() != "gold") pz->fail("use 'gold' or a list of [temperature, coefficient] pairs");
        } else {
            std::optional<YamlNode> previous;
            for (const auto& p : pz->items()) {
                const auto pair = p.items();
                if (pair.size() != 2) p.fail("each entry is [temperature, coefficient], e.g. [40 degC, 1.387e-8 1/Pa]");
                const double T = pair[0].as_temperature();
                const double a = pair[1].as_quantity(dim::per_pascal, "1.387e-8 1/Pa");
                if (!(a > 1e-10 && a < 1e-6)) pair[1].fail("pressure-viscosity coefficient outside 1e-10..1e-6 1/Pa");
                // The table is interpolated between neighbours: a temperature listed twice divides by zero.
                if (previous) require_ascending(*previous, oil.piezo_table.back().T_K, pair[0], T);
                oil.piezo_table.push_back({T, a});
                previous = pair[0];
            }
            if (oil.piezo_table.empty()) pz->fail("an empty table; give [temperature, coefficient] pairs or 'gold'");
        }
    }
    if (auto x = n.get("X_L")) {
        oil.X_L = x->as_number();
        if (!(oil.X_L > 0 && oil.X_L < 3)) x->fail("X_L must be in (0, 3)");
    } else if (auto def = lubricant::default_XL(oil.base)) {
        oil.X_L = *def;
        assume(assumed, n, "oil.X_L", number_text(*def),
               fmt::format("ISO/TS 6336-20 lubricant factor for base oil {}", lubricant::to_string(oil.base)));
    } else {
        n.fail(fmt::format("base oil '{}' has no standard X_L (ISO/TS 6336-20); give 'X_L' (e.g. 0.65)",
                           lubricant::to_string(oil.base)));
    }
    if (auto k = n.get("thermal_conductivity")) oil.k_fixed = k->as_quantity(dim::thermal_conductivity, "0.15 W/(m*K)");
    else
        assume(assumed, n, "oil.thermal_conductivity",
               oil.base == BaseOil::mineral || oil.base == BaseOil::transmission_fluid ? "Cragoe"
                                                                                       : "0.158 (1 - 0.00054 T[degC]) W/(m*K)",
               "function of temperature: Cragoe for petroleum oils, typical datasheet values for synthetic base stocks");
    if (auto c = n.get("specific_heat")) oil.cp_fixed = c->as_quantity(dim::specific_heat, "2000 J/(kg*K)");
    else assume(assumed, n, "oil.specific_heat", "Cragoe", "function of temperature and density (Cragoe)");
    oil.traction = lubricant::default_traction(oil.base);
    {
        // Traction properties the case does not give: the defaults by base oil (docs/config.md table).
        const auto tr = n.get("traction");
        const YamlNode& at = tr ? *tr : n;
        const auto& t = oil.traction;
        const std::string why = fmt::format("assumed order-of-magnitude default for base oil {} (docs/config.md)",
                                            lubricant::to_string(oil.base));
        const auto unless_given = [&](const char* key, const std::string& value) {
            if (!tr || !tr->has(key)) assume(assumed, at, std::string("oil.traction.") + key, value, why);
        };
        unless_given("eyring_stress", number_text(t.eyring_stress * 1e-6) + " MPa");
        unless_given("limiting_shear_stress", number_text(t.limiting_shear_0 * 1e-6) + " MPa");
        unless_given("limiting_shear_slope", number_text(t.limiting_shear_slope));
        unless_given("boundary_friction", number_text(t.mu_boundary));
        unless_given("mixed_B", number_text(t.mixed_B));
        unless_given("mixed_m", number_text(t.mixed_m));
        if (!tr || !tr->has("roelands_index"))
            assume(assumed, at, "oil.traction.roelands_index", "from alpha",
                   "Roelands Z = alpha p_r / (ln eta0 + 9.67) from the pressure-viscosity coefficient");
    }
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
    {
        // Shear modulus of the viscoelastic traction (read by the mesh form ehl_maxwell):
        // G = (G0 + G_p p) exp(-beta_G (T - T_ref)).
        const auto rh = n.get("rheology");
        const YamlNode& at = rh ? *rh : n;
        auto& t = oil.traction;
        const auto unless_given = [&](const char* key, const std::string& value, const char* why) {
            if (!rh || !rh->has(key)) assume(assumed, at, std::string("oil.rheology.") + key, value, why);
        };
        unless_given("shear_modulus", number_text(t.shear_modulus_0 * 1e-9) + " GPa",
                     "shear modulus of the viscoelastic traction (ehl_maxwell): the order of magnitude of limiting "
                     "elastic moduli of EHL films (docs/config.md)");
        unless_given("shear_modulus_pressure_slope", number_text(t.shear_modulus_slope),
                     "shear modulus of ehl_maxwell independent of pressure (no data)");
        unless_given("shear_modulus_temperature_coefficient", number_text(t.shear_modulus_beta) + " 1/K",
                     "shear modulus of ehl_maxwell independent of temperature (no data)");
        if (rh) {
            rh->allow_keys({"shear_modulus", "shear_modulus_pressure_slope", "shear_modulus_temperature_coefficient",
                            "reference_temperature"});
            if (auto v = rh->get("shear_modulus")) {
                t.shear_modulus_0 = v->as_quantity(dim::pressure, "1 GPa");
                if (!(t.shear_modulus_0 > 0 && t.shear_modulus_0 < 1e12)) v->fail("shear modulus must be in (0, 1000 GPa)");
            }
            if (auto v = rh->get("shear_modulus_pressure_slope")) {
                t.shear_modulus_slope = v->as_number();
                if (!(t.shear_modulus_slope >= 0 && t.shear_modulus_slope < 100))
                    v->fail("shear modulus pressure slope dG/dp must be in [0, 100)");
            }
            if (auto v = rh->get("shear_modulus_temperature_coefficient")) {
                t.shear_modulus_beta = v->as_quantity(dim::per_kelvin, "0.01 1/K");
                if (!(t.shear_modulus_beta >= 0 && t.shear_modulus_beta < 1))
                    v->fail("shear modulus temperature coefficient must be in [0, 1) 1/K");
            }
            if (auto v = rh->get("reference_temperature")) t.shear_modulus_T_ref = v->as_temperature();
            else if (t.shear_modulus_beta > 0)
                rh->fail("'shear_modulus_temperature_coefficient' needs the 'reference_temperature' of 'shear_modulus'");
        }
    }
    // The mixed-film pair of the mesh (Fernandes et al. 2015), measured per oil.
    if (auto gf = n.get("gear_friction")) {
        const auto pair = parse_pair(*gf);
        if (gf->has("mu_bl")) oil.gear_mu_bl = pair.mu_bl;
        oil.gear_mu_ehl = pair.mu_ehl;
        if (oil.gear_mu_bl && oil.gear_mu_ehl && !(*oil.gear_mu_ehl < *oil.gear_mu_bl))
            gf->fail(fmt::format("need 0 <= mu_ehl < mu_bl < 1 (mu_bl {:g}, mu_ehl {:g}, both from the oil)", *oil.gear_mu_bl,
                                 *oil.gear_mu_ehl));
    }
    const auto bf = n.get("bearing_friction");
    if (bf) {
        bf->allow_keys({"ball", "roller"});
        if (auto b = bf->get("ball")) oil.bearing_ball = parse_pair(*b);
        if (auto r = bf->get("roller")) oil.bearing_roller = parse_pair(*r);
    }
    // mu_ehl left out is assumed per bearing (type and base oil), where the bearings are read.
    for (const char* family : {"ball", "roller"}) {
        const auto f = bf ? bf->get(family) : std::nullopt;
        if (!f || !f->has("mu_bl"))
            assume(assumed, f ? *f : bf ? *bf : n, fmt::format("oil.bearing_friction.{}.mu_bl", family),
                   number_text(lubricant::BearingFrictionPair{}.mu_bl), "SKF (2004) boundary friction coefficient");
    }
    check_viscosity_law_range(oil, n.at("viscosity"));
    // Values the oil file gives but declares assumed (an oil written by `gearloss import`).
    if (assumed) read_declared_assumptions(n, *assumed, "oil.");
    return oil;
}

lubricant::Oil load_oil_file(const std::string& file, std::vector<AssumedValue>* assumed) {
    const YamlNode root = YamlNode::load_file(file);
    return load_oil(root.has("oil") ? root.at("oil") : root, assumed);
}

}  // namespace gearloss::io
