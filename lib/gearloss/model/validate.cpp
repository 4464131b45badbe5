#include "gearloss/model/validate.hpp"

#include "gearloss/losses/loss_mechanism.hpp"

#include "gearloss/core/message_text.hpp"

#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>
#include <variant>

namespace gearloss::solver {

namespace {
constexpr double kRpm = 30.0 / std::numbers::pi;
constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

bool finite(double v) { return std::isfinite(v); }
// A value as written in a message (gearloss/core/message_text.hpp).
std::string show(double v) { return number_text(v); }
std::string degC(double T_K) { return celsius_text(T_K); }

// Collects issues of one section/item.
struct Collector {
    std::vector<Issue>& out;
    std::string section, item;
    void add(const std::string& key, std::string message) { out.push_back({section, item, key, std::move(message)}); }
    void structural(const std::string& key, std::string message) {
        out.push_back({section, item, key, std::move(message), true});
    }
    // finite and within [lo, hi] (open ends where `open_lo` / `open_hi`)
    void range(const std::string& key, double v, double lo, double hi, const char* what, bool open_lo = false,
               bool open_hi = false) {
        if (!finite(v)) return add(key, fmt::format("{} is {}", what, show(v)));
        const bool below = open_lo ? !(v > lo) : !(v >= lo), above = open_hi ? !(v < hi) : !(v <= hi);
        if (below || above)
            add(key, fmt::format("{} = {:g} outside {}{:g}, {:g}{}", what, v, open_lo ? "(" : "[", lo, hi, open_hi ? ")" : "]"));
    }
    void positive(const std::string& key, double v, const char* what) { range(key, v, 0.0, kInf, what, true, true); }
    void non_negative(const std::string& key, double v, const char* what) { range(key, v, 0.0, kInf, what, false, true); }
    void is_finite(const std::string& key, double v, const char* what) {
        if (!finite(v)) add(key, fmt::format("{} is {}", what, show(v)));
    }
};

template <class V>
bool index_ok(int i, const V& v) {
    return i >= 0 && static_cast<size_t>(i) < v.size();
}

void validate_oil(const lubricant::Oil& oil, std::vector<Issue>& out) {
    Collector c{out, "oil", ""};
    if (const auto* v = std::get_if<lubricant::VogelLaw>(&oil.viscosity)) {
        c.positive("viscosity", v->k_mm2s, "Vogel factor k");
        c.positive("viscosity", v->b_C, "Vogel exponent b");
        c.is_finite("viscosity", v->c_C, "Vogel offset c");
    } else {
        const auto& w = std::get<lubricant::WaltherLaw>(oil.viscosity);
        c.is_finite("viscosity", w.A, "ASTM D341 constant A");
        c.positive("viscosity", w.B, "ASTM D341 constant B");
        // Constants that are finite but describe no oil (nu(40 degC) of 10^300 mm^2/s, or a
        // slope that makes nu(T) rise): the datasheet range of a lubricant, checked at 40 and 100 degC.
        if (finite(w.A) && finite(w.B) && w.B > 0)
            for (double T_C : {40.0, 100.0}) {
                const double nu = w.nu_mm2s(T_C + 273.15), dln = w.dlnnu_dT(T_C + 273.15);
                if (!(nu >= 0.5 && nu <= 1e7 && finite(dln) && dln < 0)) {
                    c.add("viscosity", fmt::format("the ASTM D341 constants give nu({:g} degC) = {} mm^2/s (d ln nu/dT = {}): "
                                                   "not an oil (0.5..1e7 mm^2/s, falling with temperature)",
                                                   T_C, show(nu), show(dln)));
                    break;
                }
            }
    }
    c.range("density", oil.rho15, 300.0, 2500.0, "density at 15 degC [kg/m^3]");
    c.range("thermal_expansion", oil.expansion, 0.0, 5e-3, "thermal expansion coefficient [1/K]");
    c.range("X_L", oil.X_L, 0.0, 3.0, "lubricant factor X_L", true, true);
    c.positive("max_temperature", oil.max_temperature, "permissible temperature [K]");
    if (oil.k_fixed) c.positive("thermal_conductivity", *oil.k_fixed, "thermal conductivity");
    if (oil.cp_fixed) c.positive("specific_heat", *oil.cp_fixed, "specific heat");
    for (const auto& p : oil.piezo_table) {
        c.positive("piezoviscosity", p.T_K, "temperature of a pressure-viscosity point [K]");
        c.range("piezoviscosity", p.alpha, 1e-10, 1e-6, "pressure-viscosity coefficient [1/Pa]");
    }
    const auto& t = oil.traction;
    c.positive("traction", t.eyring_stress, "Eyring stress");
    c.non_negative("traction", t.limiting_shear_0, "limiting shear stress");
    c.range("traction", t.limiting_shear_slope, 0.0, 1.0, "limiting shear slope", false, true);
    c.range("traction", t.mu_boundary, 0.0, 1.0, "boundary friction", true, true);
    c.positive("traction", t.mixed_B, "mixed_B");
    c.positive("traction", t.mixed_m, "mixed_m");
    c.non_negative("traction", t.roelands_Z, "Roelands index");
    c.positive("rheology", t.shear_modulus_0, "shear modulus");
    c.non_negative("rheology", t.shear_modulus_slope, "shear modulus pressure slope");
    c.non_negative("rheology", t.shear_modulus_beta, "shear modulus temperature coefficient");
    for (const auto* pair : {&oil.bearing_ball, &oil.bearing_roller}) {
        c.range("bearing_friction", pair->mu_bl, 0.0, 1.0, "bearing mu_bl", false, true);
        if (pair->mu_ehl) c.range("bearing_friction", *pair->mu_ehl, 0.0, 1.0, "bearing mu_ehl", false, true);
    }
}

void validate_thermal(const Model& m, std::vector<Issue>& out) {
    const auto& th = m.thermal;
    Collector c{out, "thermal", ""};
    if (auto f = ambient_fault(th.ambient)) c.add("ambient", *f);
    const bool stabilised = th.mode == ThermalMode::stabilised;
    if (th.mode == ThermalMode::fixed) {
        if (auto f = oil_temperature_fault(m.oil, th.oil_temperature))
            c.add("oil_temperature", "fixed oil temperature " + *f);
    }
    if (stabilised) {
        // The oil starts at the ambient and is searched up to max_oil_temperature.
        if (finite(th.ambient) && !ambient_fault(th.ambient))
            if (auto f = oil_temperature_fault(m.oil, th.ambient)) c.add("ambient", "ambient " + *f);
        const auto& eq = th.equilibrium;
        if (!finite(eq.T_max)) {
            c.add("max_oil_temperature", "is " + show(eq.T_max));
        } else if (finite(th.ambient) && !(eq.T_max > th.ambient)) {
            c.add("max_oil_temperature", fmt::format("{} is not above the ambient {}: no oil temperature to search",
                                                     degC(eq.T_max), degC(th.ambient)));
        } else if (const OilValidity v = oil_validity(m.oil); !(eq.T_max < v.T_max)) {
            c.add("max_oil_temperature",
                  fmt::format("{} is beyond the validity of oil '{}' ({} at {}); lower 'max_oil_temperature'",
                              degC(eq.T_max), m.oil.name, v.max_reason, degC(v.T_max)));
        }
        c.positive("max_oil_temperature", eq.tol_K, "equilibrium tolerance [K]");
        c.positive("max_oil_temperature", eq.max_step, "equilibrium bracketing step [K]");
        if (eq.max_bracket_steps < 1) c.add("max_oil_temperature", "equilibrium step bound must be at least 1");
    }
    if (const auto* r = std::get_if<thermal::ThermalResistance>(&th.rejection.model)) {
        c.positive("heat_rejection.resistance", r->R0, "thermal resistance [K/W]");
        c.non_negative("heat_rejection.reference_speed", r->n_ref, "reference speed [rad/s]");
        c.range("heat_rejection.speed_exponent", r->exponent, 0.0, 2.0, "speed exponent", false, true);
    } else {
        const auto& h = std::get<thermal::HousingSurface>(th.rejection.model);
        c.positive("heat_rejection.housing.area", h.area, "housing area [m^2]");
        c.range("heat_rejection.housing.emissivity", h.emissivity, 0.0, 1.0, "emissivity");
        c.positive("heat_rejection.housing.height", h.height, "housing height [m]");
        c.positive("heat_rejection.housing.length", h.length, "housing length [m]");
        c.range("heat_rejection.housing.air_speed", h.air_speed, 0.0, 1000.0, "air speed [m/s]");
    }
    const auto& n = th.network;
    c.non_negative("heat_capacity", th.heat_capacity, "heat capacity [J/K]");
    c.non_negative("network.oil", n.C_oil, "oil node heat capacity [J/K]");
    c.non_negative("network.housing", n.C_housing, "housing node heat capacity [J/K]");
    c.non_negative("network.oil_to_housing", n.G_oil_housing, "oil-to-housing conductance [W/K]");
    c.non_negative("network.clutch_packs", n.C_clutch, "clutch node heat capacity [J/K]");
    c.non_negative("network.clutch_to_oil", n.G_clutch_oil, "clutch-to-oil conductance [W/K]");
    if (n.has_housing() && !(n.G_oil_housing > 0)) c.add("network.oil_to_housing", "a housing node needs a positive conductance");
    if (n.has_clutch() && !(n.G_clutch_oil > 0)) c.add("network.clutch_to_oil", "a clutch node needs a positive conductance");
}

void validate_calibration(const Calibration& k, std::vector<Issue>& out) {
    Collector c{out, "calibration", ""};
    c.range("viscosity_factor", k.viscosity_factor, 0.05, 20.0, "viscosity factor");
    c.range("heat_rejection_factor", k.heat_rejection_factor, 0.05, 20.0, "heat rejection factor");
    c.range("cooling_per_1000rpm", k.cooling_per_1000rpm, -0.95, 50.0, "cooling per 1000 rpm");
    c.range("cooling_speed_exponent", k.cooling_speed_exponent, 0.2, 2.0, "power of speed in the forced cooling");
    c.range("heat_rejection_rise_slope", k.heat_rejection_rise_slope, -0.2, 0.2,
            "change of the heat flow per 50 K of oil rise over ambient");
}

void validate_gearbox(const Model& m, std::vector<Issue>& out) {
    const auto& gb = m.gearbox;
    {
        Collector c{out, "gearbox", ""};
        if (!index_ok(gb.input_shaft, gb.shafts)) c.structural("input", "the input shaft is not one of the shafts");
        if (!index_ok(gb.output_shaft, gb.shafts)) c.structural("output", "the output shaft is not one of the shafts");
        for (int g : gb.engaged)
            if (!index_ok(g, gb.gears)) c.structural("ratios", "an engaged gear is not one of the gears");
    }
    {
        Collector c{out, "housing", ""};
        c.positive("oil_volume", gb.oil_volume, "oil volume [m^3]");
        if (gb.oil_level) c.is_finite("oil_level", *gb.oil_level, "oil level");
    }
    for (const auto& g : gb.gears) {
        const auto& s = g.spec;
        Collector c{out, "gears", s.name};
        if (!index_ok(g.shaft, gb.shafts)) c.structural("shaft", "not one of the shafts");
        if (g.carrier >= 0 && !index_ok(g.carrier, gb.shafts)) c.structural("carrier", "not one of the shafts");
        if (g.planets < 1 || g.planets > 12) c.structural("planets", fmt::format("number of planets {} outside 1..12", g.planets));
        if (s.z < 5 || s.z > 100000) c.add("teeth", fmt::format("number of teeth {} outside 5..100000", s.z));
        c.range("module", s.mn, 1e-5, 1.0, "module [m]");  // 0.01 mm .. 1 m
        c.range("profile_shift", s.x, -1.5, 2.5, "profile shift coefficient", true, true);
        c.range("face_width", s.b, 1e-5, 10.0, "face width [m]");
        c.range("pressure_angle", s.alpha_n * kDeg, 10.0, 35.0, "pressure angle [deg]", true, true);
        c.range("helix_angle", s.beta * kDeg, 0.0, 45.0, "helix angle [deg]", false, true);
        c.range("addendum_coefficient", s.ha_star, 0.0, 5.0, "addendum coefficient", true);
        c.range("dedendum_coefficient", s.hf_star, 0.0, 5.0, "dedendum coefficient", true);
        c.range("Ra", s.Ra, 0.0, 50e-6, "roughness Ra [m]");
        if (s.Rq) c.range("Rq", *s.Rq, 0.0, 50e-6, "roughness Rq [m]");
        c.positive("material", s.material.E, "Young's modulus [Pa]");
        c.range("material", s.material.poisson, 0.0, 0.5, "Poisson ratio", true, true);
        c.positive("material", s.material.density, "material density [kg/m^3]");
        c.is_finite("position", g.position, "position");
        if (g.immersion) c.non_negative("immersion", *g.immersion, "immersion depth [m]");
        if (s.tip_diameter) c.positive("tip_diameter", *s.tip_diameter, "tip diameter [m]");
        if (s.tip_alteration_factor) c.range("tip_alteration_factor", *s.tip_alteration_factor, -1.0, 0.5, "tip alteration factor", true);
    }
    for (const auto& me : gb.meshes) {
        Collector c{out, "meshes", me.name};
        if (!index_ok(me.gear[0], gb.gears) || !index_ok(me.gear[1], gb.gears) || me.gear[0] == me.gear[1])
            c.structural("gears", "a mesh names two different gears of the gearbox");
        c.is_finite("angle", me.angle, "angle");
        if (me.centre_distance) c.positive("centre_distance", *me.centre_distance, "centre distance [m]");
    }
    for (const auto& b : gb.bearings) {
        const auto& s = b.spec;
        Collector c{out, "bearings", b.name};
        if (!index_ok(b.shaft, gb.shafts)) c.structural("shaft", "not one of the shafts");
        if (b.under_gear >= 0 && !index_ok(b.under_gear, gb.gears)) c.structural("under_gear", "not one of the gears");
        if (b.outer_shaft >= 0 && (!index_ok(b.outer_shaft, gb.shafts) || b.outer_shaft == b.shaft || b.under_gear >= 0))
            c.structural("outer_shaft", "not one of the other shafts, or given with under_gear");
        c.range("d", s.d, 0.5e-3, 100.0, "bore d [m]");  // the smallest catalogue bearings: 0.6 mm
        c.range("D", s.D, 1e-3, 100.0, "outer diameter D [m]");
        if (finite(s.d) && finite(s.D) && !(s.D > s.d)) c.add("D", fmt::format("outer diameter {:g} m must exceed the bore {:g} m", s.D, s.d));
        c.range("B", s.B, 0.0, 100.0, "width B [m]", true);
        c.non_negative("C0", s.C0, "static load rating C0 [N]");
        if (s.type == bearings::BearingType::deep_groove_ball && !(s.C0 > 0))
            c.add("C0", "deep groove ball bearings need a positive static load rating C0");
        c.range("Y", s.Y, 0.0, 5.0, "axial load factor Y", true, true);
        for (double k : {s.k.R1, s.k.R2, s.k.R3, s.k.R4, s.k.S1, s.k.S2, s.k.S3, s.k.S4, s.k.K_Z, s.k.K_L})
            c.is_finite("constants", k, "an SKF constant");
        if (b.multiplicity < 1) c.structural("count", "multiplicity must be at least 1");
        c.is_finite("position", b.position, "position");
        c.non_negative("lubrication", s.K_rs, "replenishment constant K_rs");
        c.range("lubrication", s.mu_bl, 0.0, 1.0, "mu_bl", false, true);
        c.range("lubrication", s.mu_ehl, 0.0, 1.0, "mu_ehl", false, true);
        for (double v : {s.seal_KS1, s.seal_KS2, s.seal_beta}) c.non_negative("seals", v, "a seal constant");
        if (s.seal_ds) c.non_negative("seals", *s.seal_ds, "seal counterface diameter [m]");
        if (s.bath_H) c.non_negative("oil_bath", *s.bath_H, "oil bath level [m]");
        c.range("oil_bath", s.bath_VM, 0.0, 0.01, "drag factor V_M");
    }
    for (const auto& se : gb.seals) {
        Collector c{out, "seals", se.name};
        if (!index_ok(se.shaft, gb.shafts)) c.structural("shaft", "not one of the shafts");
        c.range("diameter", se.diameter, 0.0, 10.0, "diameter [m]", true);
    }
    for (const auto& cl : gb.clutches) {
        const auto& p = cl.pack;
        Collector c{out, "clutches", p.name};
        if (!index_ok(cl.gear, gb.gears)) c.structural("engages", "not one of the gears");
        if (p.interfaces < 1 || p.interfaces > 100) c.add("interfaces", fmt::format("{} interfaces outside 1..100", p.interfaces));
        c.positive("r_inner", p.r_inner, "r_inner [m]");
        c.range("r_outer", p.r_outer, 0.0, 10.0, "r_outer [m]", true);
        if (finite(p.r_inner) && finite(p.r_outer) && !(p.r_outer > p.r_inner)) c.add("r_outer", "r_outer must exceed r_inner");
        c.positive("clearance", p.clearance, "clearance [m]");
        c.non_negative("roughness", p.roughness, "roughness [m]");
        c.non_negative("oil_supply", p.oil_supply, "oil supply [m^3/s]");
    }
}

// The H_V model the mesh mechanism selects. (mechanisms/, which holds its typed accessor, sits
// above this folder: asked by the form's name, which is mesh::to_string's.)
mesh::LossFactorModel selected_loss_factor(const Model& m) {
    const auto* mech = m.mechanisms.find("mesh");
    const std::string name = mech ? mech->form(m, "loss_factor") : "";
    for (auto f : {mesh::LossFactorModel::ohlendorf, mesh::LossFactorModel::buckingham})
        if (name == mesh::to_string(f)) return f;
    return mesh::LossFactorModel::wimmer;
}

// The derived layout (after finalise()): what the loss models multiply must be finite.
void validate_layout(const Model& m, std::vector<Issue>& out) {
    const auto& gb = m.gearbox;
    const auto& L = m.layout;
    if (L.meshes.size() != gb.meshes.size() || L.body_speed_ratio.empty()) return;  // not finalised
    const auto loss_factor = selected_loss_factor(m);
    {
        Collector c{out, "gearbox", ""};
        if (!finite(L.ratio) || L.ratio == 0.0) c.add("", "the ratio of the train is " + show(L.ratio));
        if (!finite(L.output_torque_per_Nm)) c.add("", "the output torque per N m is " + show(L.output_torque_per_Nm));
    }
    for (size_t i = 0; i < gb.meshes.size(); ++i) {
        const auto& md = L.meshes[i];
        Collector c{out, "meshes", gb.meshes[i].name};
        const double vals[] = {md.geom.a_w, md.geom.alpha_wt, md.geom.rho_redC, md.geom.b_eff, md.L_min, md.L_mean,
                               md.loss_factor(loss_factor), md.force_per_Nm, md.rolling_per_W, md.relative_speed};
        for (double v : vals)
            if (!finite(v)) {
                c.add("", "its geometry or load is not a finite number (check the gears' data)");
                break;
            }
        if (i < m.mesh_E_prime.size()) c.positive("", m.mesh_E_prime[i], "reduced modulus E' [Pa]");
    }
    for (size_t s = 0; s < gb.shafts.size() && s < L.shaft_centre.size(); ++s)
        if (!L.shaft_centre[s].allFinite())
            out.push_back({"shafts", gb.shafts[s].name, "", "its position is not a finite number (check the mesh angles)"});
    for (size_t g = 0; g < gb.gears.size() && g < L.gear_immersion.size(); ++g)
        if (!finite(L.gear_immersion[g]))
            out.push_back({"gears", gb.gears[g].spec.name, "immersion", "immersion is not a finite number"});
    for (size_t g = 0; g < gb.gears.size() && g < L.gear_mass.size(); ++g)
        if (!(finite(L.gear_mass[g]) && L.gear_mass[g] >= 0))
            out.push_back({"gears", gb.gears[g].spec.name, "mass", "its mass is not a finite, non-negative number"});
    for (size_t s = 0; s < gb.shafts.size() && s < L.shaft_mass.size(); ++s)
        if (!(finite(L.shaft_mass[s]) && L.shaft_mass[s] >= 0))
            out.push_back({"shafts", gb.shafts[s].name, "mass", "its mass is not a finite, non-negative number"});
    for (size_t i = 0; i < gb.bearings.size(); ++i) {
        bool ok = i < L.bearing_speed_ratio.size() && finite(L.bearing_speed_ratio[i]);
        for (const auto* v : {&L.bearing_Fr_pos, &L.bearing_Fa_pos, &L.bearing_Fr_neg, &L.bearing_Fa_neg, &L.bearing_Fcf_per_w2,
                              &L.bearing_Z_weight, &L.bearing_W_orbiting})
            ok = ok && i < v->size() && finite((*v)[i]);
        ok = ok && i < L.bearing_R_weight.size() && L.bearing_R_weight[i].allFinite();
        if (!ok) out.push_back({"bearings", gb.bearings[i].name, "", "its speed or load is not a finite number"});
    }
}

}  // namespace

std::string summarise(const std::vector<Issue>& issues) {
    if (issues.empty()) return {};
    std::string message = issues.front().message;
    if (issues.size() > 1) {
        message += fmt::format(" ({} more: ", issues.size() - 1);
        for (size_t i = 1; i < issues.size() && i < 4; ++i) message += (i > 1 ? "; " : "") + issues[i].path();
        message += issues.size() > 4 ? "; ...)" : ")";
    }
    return message;
}

OilValidity oil_validity(const lubricant::Oil& oil) {
    OilValidity v;
    v.T_min = 0.0;
    if (const auto* vg = std::get_if<lubricant::VogelLaw>(&oil.viscosity)) {
        // nu = k exp(b / (T + c)): the law ends at its pole T = -c.
        const double pole = 273.15 - vg->c_C;
        if (pole > v.T_min) {
            v.T_min = pole;
            v.min_reason = "pole of its Vogel viscosity law";
        }
    }
    v.T_max = kInf;
    if (oil.expansion > 0) {
        v.T_max = 288.15 + 1.0 / oil.expansion;  // rho15 (1 - expansion (T - 15 degC)) = 0
        v.max_reason = "its density reaches zero";
    }
    if (!oil.k_fixed) {
        const double k_zero = 273.15 + 1.0 / 0.00054;  // (1 - 0.00054 T_C) of the conductivity estimate
        if (k_zero < v.T_max) {
            v.T_max = k_zero;
            v.max_reason = "its thermal conductivity estimate reaches zero";
        }
    }
    return v;
}

std::optional<std::string> oil_temperature_fault(const lubricant::Oil& oil, double T) {
    if (!finite(T)) return "is " + show(T);
    const OilValidity v = oil_validity(oil);
    if (!(T > v.T_min))
        return fmt::format("{} is at or below the validity of oil '{}' ({} at {})", degC(T), oil.name, v.min_reason,
                           degC(v.T_min));
    if (!(T < v.T_max))
        return fmt::format("{} is at or above the validity of oil '{}' ({} at {})", degC(T), oil.name, v.max_reason,
                           degC(v.T_max));
    // Colder, the viscosity law runs past the cap of lubricant::Oil::nu_mm2s (1e7 mm^2/s): the oil
    // is a solid there, below its data, and a film, a churning loss or a drag computed from the
    // capped value would be nonsense labelled ok.
    constexpr double capped_nu_mm2s = 1e7;
    if (oil.nu_mm2s(T) >= capped_nu_mm2s)
        return fmt::format("{} is below the data of oil '{}' (its viscosity law gives more than {:g} mm^2/s there: a "
                           "solid)", degC(T), oil.name, capped_nu_mm2s);
    // Hotter, the law runs below the floor of lubricant::Oil::nu_mm2s (0.5 mm^2/s, a solvent rather
    // than a gear oil) or the linear expansion law has lost more than a third of the 15 degC density
    // (far past the boiling and flash points of mineral and synthetic gear oils): every loss computed
    // from the floored viscosity or that density would be nonsense labelled ok, as on the cold side.
    constexpr double floored_nu_mm2s = 0.5;
    if (!(oil.nu_mm2s(T) > floored_nu_mm2s))
        return fmt::format("{} is above the data of oil '{}' (its viscosity law gives {:g} mm^2/s or less there: no "
                           "longer a lubricant)", degC(T), oil.name, floored_nu_mm2s);
    constexpr double min_density_share = 2.0 / 3.0;
    if (oil.expansion > 0 && !(oil.density(T) > min_density_share * oil.rho15))
        return fmt::format("{} is above the data of oil '{}' (its density falls below two thirds of its 15 degC value "
                           "there)", degC(T), oil.name);
    return std::nullopt;
}

std::optional<std::string> speed_fault(double w) {
    if (!finite(w)) return "input speed is " + show(w);
    if (!(std::abs(w) * kRpm <= kMaxSpeed_rpm))
        return fmt::format("input speed {:.4g} rpm beyond the stated range |n| <= {:g} rpm", finite(w * kRpm) ? w * kRpm : w,
                           kMaxSpeed_rpm) + (finite(w * kRpm) ? "" : " (in rad/s)");
    return std::nullopt;
}

std::optional<std::string> torque_fault(double T) {
    if (!finite(T)) return "input torque is " + show(T);
    if (!(std::abs(T) <= kMaxTorque_Nm))
        return fmt::format("input torque {:.4g} N m beyond the stated range |T| <= {:g} N m", T, kMaxTorque_Nm);
    return std::nullopt;
}

std::optional<std::string> ambient_fault(double T) {
    if (!finite(T)) return "ambient temperature is " + show(T);
    // The bounds as written in degC: -100 degC is 173.14999999999998 K after the offset.
    constexpr double rounding = 1e-9;
    if (!(T >= kMinAmbient_K - rounding && T <= kMaxAmbient_K + rounding))
        return fmt::format("ambient temperature {} outside the stated range -100..300 degC", degC(T));
    return std::nullopt;
}

std::vector<Issue> validate(const Model& m) {
    std::vector<Issue> out;
    validate_oil(m.oil, out);
    validate_thermal(m, out);
    validate_calibration(m.calibration, out);
    validate_gearbox(m, out);
    // The layout is meaningful only when the description's indices are.
    bool indices_ok = true;
    for (const auto& is : out) indices_ok = indices_ok && !is.structural;
    if (indices_ok) validate_layout(m, out);
    // The mechanisms' own settings last: their checks may read the layout (the contact ratio a
    // closed-form H_V assumes), which the checks above vouch for.
    for (size_t i = 0; i < m.mechanisms.size(); ++i) m.mechanisms[i].validate(m, out);
    return out;
}

std::vector<Issue> validate_operating_point(double omega_in, double torque_in) {
    std::vector<Issue> out;
    if (auto f = speed_fault(omega_in)) out.push_back({"operating", "", "speeds", *f});
    if (auto f = torque_fault(torque_in)) out.push_back({"operating", "", "torques", *f});
    return out;
}

}  // namespace gearloss::solver
