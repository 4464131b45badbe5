#include "gearloss/results/reports.hpp"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/bearings/skf_constants.hpp"
#include "gearloss/churning/changenet_velex.hpp"
#include "gearloss/churning/fitted_range.hpp"
#include "gearloss/core/errors.hpp"
#include "gearloss/core/message_text.hpp"
#include "gearloss/mechanisms/mesh_friction_mechanism.hpp"
#include "gearloss/mesh/ehl_path.hpp"
#include "gearloss/io/json_text.hpp"

namespace gearloss::io {

namespace {
constexpr double rpm = 30.0 / std::numbers::pi;
constexpr double deg = 180.0 / std::numbers::pi;

std::string status_line(const solver::Model& m, const solver::PointResult& r) {
    if (r.status == solver::PointStatus::no_equilibrium)
        return fmt::format("status: no_equilibrium (losses exceed heat rejection up to {:.1f} degC)\n",
                           r.oil_temperature - 273.15);
    if (r.status == solver::PointStatus::out_of_range)
        return "status: " + solver::status_text(r) + " (no losses computed)\n";
    if (r.status == solver::PointStatus::above_oil_limit)
        return fmt::format("status: above_oil_limit (the oil settles above its permissible {:.1f} degC)\n",
                           m.oil.max_temperature - 273.15);
    return "status: ok\n";
}
}  // namespace

std::string point_report(const Case& c, const solver::PointResult& r) {
    const auto& m = c.model;
    std::string s;
    s += fmt::format("{} — oil {}{}\n", m.name, m.oil.name, m.ratio.empty() ? "" : ", ratio " + m.ratio);
    if (r.status == solver::PointStatus::out_of_range) {
        // The inputs as given, however large (or not finite): short, never "inf" or 300 digits.
        s += fmt::format("input  {} rpm  {} N*m  {} W\n", finite_number_text(r.speed_in * rpm),
                         finite_number_text(r.torque_in), finite_number_text(r.power_in));
        return s + status_line(m, r);
    }
    s += fmt::format("input  {:10.2f} rpm  {:10.2f} N*m  {:10.1f} W\n", r.speed_in * rpm, r.torque_in, r.power_in);
    s += status_line(m, r);
    if (!solver::has_values(r.status)) return s;
    s += fmt::format("output {:10.2f} rpm  {:10.2f} N*m  {:10.1f} W\n", r.omega_out * rpm, r.torque_out, r.power_out);
    s += fmt::format("oil temperature {:.2f} degC (ambient {:.2f} degC, {})\n", r.oil_temperature - 273.15,
                     r.ambient - 273.15, m.thermal.mode == solver::ThermalMode::fixed ? "fixed" : "stabilised");
    const auto os = m.oil_state(r.oil_temperature);  // with the case's viscosity calibration
    s += fmt::format("oil at that temperature: nu {:.3f} cSt, rho {:.1f} kg/m^3, eta {:.3f} mPa*s, alpha {:.3f} 1/GPa\n\n",
                     os.nu_cSt, os.rho, os.eta * 1e3, os.alpha_p * 1e9);
    const auto& Lo = r.losses;
    // One section per loss mechanism, from the mechanism (its oil-independent terms at this point).
    const solver::PointState p = solver::prepare_point(m, r.speed_in, r.torque_in);
    std::string totals;
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        const auto& mech = m.mechanisms[i];
        if (i < Lo.detail.size()) s += mech.report(m, p.input(), *p.data[i], Lo.detail[i]);
        totals += fmt::format("{} {:.2f}, ", mech.label(), Lo.power[i]);
    }
    s += fmt::format("\ntotals [W]: {}total {:.2f}\n", totals, Lo.total());
    if (r.has_efficiency) s += fmt::format("efficiency {:.4f} %\n", 100.0 * r.efficiency);
    if (Lo.has_lambda) s += fmt::format("minimum specific film thickness Lambda {:.3f}\n", Lo.lambda_min);
    return s;
}

namespace {
// Per dipping gear, the speed below which its churning is held at the minimum of the
// published Changenet & Velex (2007) curve over Re_c (gearloss/churning/changenet_velex.hpp).
struct ChurningCapRow {
    std::string gear;
    double below_rpm = 0, excess_at_1000rpm = 0;
};
std::vector<ChurningCapRow> churning_caps(const solver::Model& m) {
    std::vector<ChurningCapRow> out;
    const auto& gb = m.gearbox;
    if (!m.mechanisms.at("churning").enabled()) return out;
    for (size_t g = 0; g < gb.gears.size(); ++g) {
        const double h = g < m.layout.gear_immersion.size() ? m.layout.gear_immersion[g] : 0.0;
        if (!(h > 0)) continue;
        const auto& spec = gb.gears[g].spec;
        const churning::DippingGear dg{0.5 * spec.d(), spec.b, spec.z, spec.mn * (spec.ha_star + spec.hf_star), spec.alpha_t(), h};
        const auto cap = churning::transition_cap(dg, gb.oil_volume, 1000.0 * std::numbers::pi / 30.0);
        out.push_back({spec.name, cap.below_omega * 30.0 / std::numbers::pi, cap.excess_at_reference});
    }
    return out;
}

struct MeshRow {
    std::string name;
    const geometry::PairGeometry* g;
    const gearbox::Layout::MeshData* md;
};
}  // namespace

std::string check_report(const Case& c) {
    const auto& m = c.model;
    const auto& gb = m.gearbox;
    const auto& L = m.layout;
    std::string s = fmt::format("{}: configuration is valid\n", c.file);
    s += fmt::format("overall ratio n_out/n_in = {:.6f} (i = n_in/n_out = {:.5f}){}\n", L.ratio, 1.0 / L.ratio,
                     m.ratio.empty() ? "" : ", ratio '" + m.ratio + "'");
    s += "\nmeshes (lengths in mm)\n";
    for (size_t i = 0; i < gb.meshes.size(); ++i) {
        const auto& md = L.meshes[i];
        const auto& g = md.geom;
        const auto& g0 = gb.gears[gb.meshes[i].gear[0]].spec;
        const auto& g1 = gb.gears[gb.meshes[i].gear[1]].spec;
        s += fmt::format("  {} ({} / {}): {}\n", gb.meshes[i].name, g0.name, g1.name, md.loaded ? "loaded" : "idle");
        s += fmt::format("    u = {:.5f}, a = {:.3f}, a_w = {:.3f}, alpha_t = {:.4f} deg, alpha_wt = {:.4f} deg, beta_b = {:.4f} deg\n",
                         g.u, g.a * 1e3, g.a_w * 1e3, g.alpha_t * deg, g.alpha_wt * deg, g.beta_b * deg);
        s += fmt::format("    d = {:.3f} / {:.3f}, d_w = {:.3f} / {:.3f}, d_a = {:.3f} / {:.3f}, d_f = {:.3f} / {:.3f}, d_b = {:.3f} / {:.3f}\n",
                         g.d[0] * 1e3, g.d[1] * 1e3, g.dw[0] * 1e3, g.dw[1] * 1e3, g.da[0] * 1e3, g.da[1] * 1e3,
                         g.df[0] * 1e3, g.df[1] * 1e3, g.db[0] * 1e3, g.db[1] * 1e3);
        s += fmt::format("    y = {:.4f}, k = {:.4f}, tip thickness = {:.3f} / {:.3f}, tip clearance = {:.3f} / {:.3f}\n", g.y,
                         g.k, g.tip_thickness[0] * 1e3, g.tip_thickness[1] * 1e3, g.tip_clearance[0] * 1e3,
                         g.tip_clearance[1] * 1e3);
        const auto& f = g.fit;
        s += f.given ? fmt::format("    centre distance given: a_w = {:.3f}, shifts give {:.3f} (x1 + x2 = {:.4f}); a_w implies "
                                   "x1 + x2 = {:.4f}, backlash j_wt = {:.4f} / j_bn = {:.4f}, housing tolerance +/-{:.4f}{}\n",
                                   f.a_w * 1e3, f.a_w_shifts * 1e3, f.sum_x, f.sum_x_implied, f.j_wt * 1e3, f.j_bn * 1e3,
                                   f.tolerance * 1e3, f.slack() ? " [beyond the tolerance]" : "")
                     : fmt::format("    centre distance from the shifts (x1 + x2 = {:.4f}, ISO 21771): a_w = {:.3f}, no backlash "
                                   "modelled\n",
                                   f.sum_x, f.a_w * 1e3);
        s += fmt::format("    eps_1 = {:.4f}, eps_2 = {:.4f}, eps_alpha = {:.4f}, eps_beta = {:.4f}, eps_gamma = {:.4f}\n",
                         g.eps1, g.eps2, g.eps_alpha, g.eps_beta, g.eps_gamma);
        s += fmt::format("    tips: {} {} (k = {:.4f}), {} {} (k = {:.4f})\n", g0.name, geometry::to_string(g.tip_source[0]),
                         g.k_applied[0], g1.name, geometry::to_string(g.tip_source[1]), g.k_applied[1]);
        if (g.transverse_gap)
            s += fmt::format("    note: eps_alpha = {:.4f} < 1; contact stays continuous through the overlap (eps_gamma = "
                             "{:.4f}); H_V from the contact-line sweep\n",
                             g.eps_alpha, g.eps_gamma);
        s += fmt::format("    H_V: Ohlendorf {:.4f}, Buckingham {:.4f}, Wimmer (rigid) {:.4f} [used: {}]; rho_redC = {:.4f}, L_min = {:.3f}\n",
                         md.H_V_ohlendorf, md.H_V_buckingham, md.H_V_wimmer, mesh::to_string(mesh::mesh_forms(m).loss_factor),
                         g.rho_redC * 1e3, md.L_min * 1e3);
    }
    s += "\nshafts (housing frame, y up, mm) and speeds per input speed; mass [kg] on its bearings\n";
    for (size_t i = 0; i < gb.shafts.size(); ++i)
        s += fmt::format("  {:<10} centre ({:8.3f}, {:8.3f})  n/n_in = {:+.6f}  {:8.3f} kg\n", gb.shafts[i].name,
                         L.shaft_centre[i].x() * 1e3, L.shaft_centre[i].y() * 1e3, L.body_speed_ratio[L.body_of_shaft[i]],
                         L.shaft_mass[i]);
    s += "\ngears: n/n_in, immersion [mm], mass [kg] (one planet)\n";
    for (size_t g = 0; g < gb.gears.size(); ++g)
        s += fmt::format("  {:<10} {:+.6f}  {:7.2f}  {:8.3f} kg{}\n", gb.gears[g].spec.name,
                         L.body_speed_ratio[L.body_of_gear[g]], L.gear_immersion[g] * 1e3, L.gear_mass[g],
                         gb.gears[g].free ? "  (free)" : "");
    s += fmt::format("\nbearings: n/n_in, radial and axial load of the gear forces per 100 N*m input (forward / reverse "
                     "torque); load at 0 N*m (weights, gravity [{:g}, {:g}, {:g}])\n",
                     gb.gravity.x(), gb.gravity.y(), gb.gravity.z());
    for (size_t i = 0; i < gb.bearings.size(); ++i) {
        const auto& b = gb.bearings[i];
        const auto at0 = L.bearing_load(i, 0.0);
        s += fmt::format("  {:<10} {:<26} {:.5f}  Fr {:8.1f} / {:8.1f} N  Fa {:8.1f} / {:8.1f} N  at 0 N*m: Fr {:8.1f} N  "
                         "Fa {:8.1f} N{}\n",
                         b.name, bearings::to_string(b.spec.type), L.bearing_speed_ratio[i], 100 * L.bearing_Fr_pos[i],
                         100 * L.bearing_Fr_neg[i], 100 * L.bearing_Fa_pos[i], 100 * L.bearing_Fa_neg[i], at0.Fr, at0.Fa,
                         b.spec.type == bearings::BearingType::needle_roller ? "  (SKF constants: caged CRB proxy)" : "");
    }
    if (!c.bearings_resolved.empty()) {
        s += "\nbearing data as resolved (value [source]):\n";
        for (const auto& r : c.bearings_resolved) {
            s += fmt::format("  {}: {} [{}]\n", r.bearing, r.type, r.type_source);
            if (!r.designation.empty())
                s += fmt::format("    designation '{}' = catalogue row '{}' ({}); ratings: {}; verified: {}\n", r.designation,
                                 r.entry, r.entry_location, r.ratings, r.verified);
            std::string row = r.entry;
            std::erase(row, ' ');
            if (!r.suffix.empty() && row.find(r.suffix) == std::string::npos)
                s += fmt::format("    suffix '{}': sizes and ratings are the row's (seals, shields, cage, clearance and "
                                 "tolerance do not change them)\n",
                                 r.suffix);
            for (const auto& v : r.values) s += fmt::format("    {} = {} [{}]\n", v.name, v.text, v.source);
        }
    }
    s += "\nloss mechanisms: alternative forms (selected in [ ]; the axes of map --spread) and parameters (SI)\n";
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        const auto& mech = m.mechanisms[i];
        s += fmt::format("  {:<12} {}\n", mech.name(), mech.column());
        for (const auto& a : mech.forms(m)) {
            const std::string chosen = mech.form(m, a.axis);
            std::string list;
            for (const auto& f : a.forms) list += fmt::format(" {}", f == chosen ? "[" + f + "]" : f);
            s += fmt::format("    {}.{}:{}\n", mech.name(), a.axis, list);
        }
        for (const auto& p : mech.parameters())  // a setting of a form not selected is shown, and said to be unread
            s += fmt::format("    {} = {:.6g}{}{}{} ({})\n", p.name, mech.value_in(m, p.name), p.calibration ? " [calibration]" : "",
                             mech.value_source(m, p.name) == losses::LossMechanism::Source::oil ? " [from the oil]" : "",
                             mech.reads(m, p) ? "" : " [not read: " + p.used_by + " is not selected]", p.description);
    }
    if (const auto* ch = m.mechanisms.find("churning"); ch && ch->enabled()) {
        const auto r = churning::fitted_range(ch->form(m, "form"));
        const auto coefficients = churning::coefficient_provenance(r.form);
        s += fmt::format("\nchurning form {}: {} range: {} ({}){}\n", r.form, r.fitted ? "fitted" : "defined",
                         churning::describe_limits(r), r.provenance, coefficients.empty() ? "" : "; " + coefficients);
    }
    if (const auto caps = churning_caps(m); !caps.empty()) {
        s += "\nchurning across the Reynolds transition (Changenet & Velex 2007; held at the minimum of the published curve "
             "over Re_c where its high-Re form exceeds the low-Re one):\n";
        for (const auto& g : caps)
            s += g.below_rpm > 0 ? fmt::format("  {}: capped below {:.0f} rpm of the gear (high-Re / low-Re torque at Re_c = "
                                               "6000 and 1000 rpm: {:.2f})\n",
                                               g.gear, g.below_rpm, g.excess_at_1000rpm)
                                 : fmt::format("  {}: never capped (high-Re / low-Re torque at Re_c = 6000 and 1000 rpm: {:.2f})\n",
                                               g.gear, g.excess_at_1000rpm);
    }
    const auto s40 = m.oil.state(313.15), s100 = m.oil.state(373.15);
    s += fmt::format("\noil {} ({}): nu40 = {:.3f} cSt, nu100 = {:.3f} cSt, rho15 = {:.1f} kg/m^3, X_L = {:.3f}\n", m.oil.name,
                     lubricant::to_string(m.oil.base), s40.nu_cSt, s100.nu_cSt, m.oil.rho15, m.oil.X_L);
    s += fmt::format("    alpha_p(40) = {:.4g} 1/Pa, alpha_p(100) = {:.4g} 1/Pa, beta_T(40) = {:.4g} 1/K\n", s40.alpha_p,
                     s100.alpha_p, s40.beta_T);
    s += fmt::format("    permissible oil temperature {:.1f} degC (above it a stabilised point is 'above_oil_limit')\n",
                     m.oil.max_temperature - 273.15);
    s += fmt::format("operating points: {}\n", c.grid.size());
    if (!c.assumed.empty()) {
        s += fmt::format("\nassumed values ({}; the case and its oil do not give them, or declare them assumed):\n", c.assumed.size());
        for (const auto& a : c.assumed)
            s += fmt::format("  {} = {} ({}{}){}\n", a.key, a.value, a.reason, a.source.empty() ? "" : "; source: " + a.source,
                             a.location.empty() ? "" : " at " + a.location);
    }
    if (!c.warnings.empty()) {
        s += fmt::format("\nplausibility ({}):\n", c.warnings.size());
        for (const auto& w : c.warnings) s += "  " + w + "\n";
    }
    return s;
}

nlohmann::ordered_json check_json_object(const Case& c) {
    const auto& m = c.model;
    const auto& gb = m.gearbox;
    const auto& L = m.layout;
    using nlohmann::ordered_json;
    ordered_json j;
    j["file"] = c.file;
    j["name"] = m.name;
    j["valid"] = true;
    j["ratio_name"] = m.ratio;
    j["speed_ratio_out_in"] = L.ratio;
    j["meshes"] = ordered_json::array();
    for (size_t i = 0; i < gb.meshes.size(); ++i) {
        const auto& md = L.meshes[i];
        const auto& g = md.geom;
        ordered_json o;
        // A key with the values of the two gears of a mesh: [gear 1, gear 2].
        o["name"] = gb.meshes[i].name;
        o["gears"] = {gb.gears[gb.meshes[i].gear[0]].spec.name, gb.gears[gb.meshes[i].gear[1]].spec.name};
        o["loaded"] = md.loaded;
        o["u"] = g.u;
        o["centre_distance_mm"] = g.a_w * 1e3;
        o["reference_centre_distance_mm"] = g.a * 1e3;
        o["working_pressure_angle_deg"] = g.alpha_wt * deg;
        o["centre_distance_fit"] = {{"given", g.fit.given},
                                    {"reference_mm", g.fit.a * 1e3},
                                    {"working_mm", g.fit.a_w * 1e3},
                                    {"from_shifts_mm", g.fit.a_w_shifts * 1e3},
                                    {"sum_x_given", g.fit.sum_x},
                                    {"sum_x_implied", g.fit.sum_x_implied},
                                    {"working_pressure_angle_deg", g.fit.alpha_wt * deg},
                                    {"backlash_circumferential_mm", g.fit.j_wt * 1e3},
                                    {"backlash_normal_mm", g.fit.j_bn * 1e3},
                                    {"tolerance_mm", g.fit.tolerance * 1e3},
                                    {"beyond_tolerance", g.fit.beyond_tolerance()}};
        o["tip_diameters_mm"] = {g.da[0] * 1e3, g.da[1] * 1e3};
        o["tip_clearances_mm"] = {g.tip_clearance[0] * 1e3, g.tip_clearance[1] * 1e3};
        o["tip_sources"] = {geometry::to_string(g.tip_source[0]), geometry::to_string(g.tip_source[1])};
        o["tip_alteration_factors"] = {g.k_applied[0], g.k_applied[1]};
        o["root_diameters_mm"] = {g.df[0] * 1e3, g.df[1] * 1e3};
        o["working_pitch_diameters_mm"] = {g.dw[0] * 1e3, g.dw[1] * 1e3};
        o["eps_1"] = g.eps1;
        o["eps_2"] = g.eps2;
        o["eps_alpha"] = g.eps_alpha;
        o["eps_beta"] = g.eps_beta;
        o["eps_gamma"] = g.eps_gamma;
        o["H_V_ohlendorf"] = md.H_V_ohlendorf;
        o["H_V_buckingham"] = md.H_V_buckingham;
        o["H_V_wimmer"] = md.H_V_wimmer;
        o["H_V_model"] = mesh::to_string(mesh::mesh_forms(m).loss_factor);
        o["H_V"] = md.loss_factor(mesh::mesh_forms(m).loss_factor);
        o["rho_redC_mm"] = g.rho_redC * 1e3;
        j["meshes"].push_back(std::move(o));
    }
    j["shafts"] = ordered_json::array();
    for (size_t i = 0; i < gb.shafts.size(); ++i)
        j["shafts"].push_back({{"name", gb.shafts[i].name},
                               {"x_mm", L.shaft_centre[i].x() * 1e3},
                               {"y_mm", L.shaft_centre[i].y() * 1e3},
                               {"speed_ratio", L.body_speed_ratio[L.body_of_shaft[i]]},
                               {"mass_kg", L.shaft_mass[i]}});
    j["gears"] = ordered_json::array();
    for (size_t g = 0; g < gb.gears.size(); ++g)
        j["gears"].push_back({{"name", gb.gears[g].spec.name},
                              {"speed_ratio", L.body_speed_ratio[L.body_of_gear[g]]},
                              {"immersion_mm", L.gear_immersion[g] * 1e3},
                              {"mass_kg", L.gear_mass[g]}});
    j["bearings"] = ordered_json::array();
    for (size_t i = 0; i < gb.bearings.size(); ++i) {
        ordered_json b{{"name", gb.bearings[i].name},
                       {"type", bearings::to_string(gb.bearings[i].spec.type)},
                       {"speed_ratio", L.bearing_speed_ratio[i]},
                       {"Fr_per_Nm", L.bearing_Fr_pos[i]},
                       {"Fa_per_Nm", L.bearing_Fa_pos[i]},
                       {"Fr_at_0_Nm", L.bearing_load(i, 0.0).Fr},
                       {"Fa_at_0_Nm", L.bearing_load(i, 0.0).Fa}};
        // The bearing block this bearing came from (one block may give `count` bearings).
        for (const auto& r : c.bearings_resolved) {
            if (gb.bearings[i].name != r.bearing && gb.bearings[i].name.rfind(r.bearing + ".", 0) != 0) continue;
            // Only blocks with a designation: the check JSON of cases without one stays as it was.
            if (r.designation.empty()) break;
            b["designation"] = r.designation;
            b["catalogue_entry"] = r.entry;
            b["catalogue_location"] = r.entry_location;
            b["designation_suffix"] = r.suffix;
            b["type_source"] = r.type_source;
            ordered_json resolved = ordered_json::array();
            for (const auto& v : r.values) {
                ordered_json e{{"name", v.name}, {"text", v.text}};
                if (v.name == "series" || v.name == "seals") e["value"] = v.text;
                else e["value_si"] = v.si;
                e["source"] = v.source;
                resolved.push_back(std::move(e));
            }
            b["resolved"] = std::move(resolved);
            break;
        }
        j["bearings"].push_back(std::move(b));
    }
    const auto s40 = m.oil.state(313.15), s100 = m.oil.state(373.15);
    j["oil"] = {{"name", m.oil.name},
                {"base", lubricant::to_string(m.oil.base)},
                {"nu40_cSt", s40.nu_cSt},
                {"nu100_cSt", s100.nu_cSt},
                {"rho15_kg_m3", m.oil.rho15},
                {"X_L", m.oil.X_L},
                {"max_temperature_C", m.oil.max_temperature - 273.15}};
    j["mechanisms"] = ordered_json::array();
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        const auto& mech = m.mechanisms[i];
        ordered_json o;
        o["name"] = std::string(mech.name());
        o["column"] = std::string(mech.column());
        o["forms"] = ordered_json::array();
        for (const auto& a : mech.forms(m))
            o["forms"].push_back({{"axis", a.axis}, {"selected", mech.form(m, a.axis)}, {"forms", a.forms}});
        o["parameters"] = ordered_json::object();
        std::vector<std::string> from_oil;  // the values in force that the oil gives
        for (const auto& p : mech.parameters()) {
            o["parameters"][p.name] = mech.value_in(m, p.name);
            if (mech.value_source(m, p.name) == losses::LossMechanism::Source::oil) from_oil.push_back(p.name);
        }
        if (!from_oil.empty()) o["parameters_from_oil"] = from_oil;
        j["mechanisms"].push_back(std::move(o));
    }
    j["operating_points"] = c.grid.size();
    if (const auto* ch = m.mechanisms.find("churning"); ch && ch->enabled()) {
        const auto r = churning::fitted_range(ch->form(m, "form"));
        ordered_json range{{"form", r.form}, {"kind", r.fitted ? "fitted" : "defined"}, {"limits", ordered_json::array()}};
        for (const auto& l : r.limits)
            range["limits"].push_back({{"quantity", l.quantity},
                                       {"lo", l.lo},
                                       {"hi", std::isfinite(l.hi) ? ordered_json(l.hi) : ordered_json(nullptr)},
                                       {"lo_open", l.lo_open},
                                       {"unit", l.unit}});
        range["provenance"] = r.provenance;
        if (const auto coefficients = churning::coefficient_provenance(r.form); !coefficients.empty())
            range["coefficients"] = coefficients;
        j["churning_range"] = std::move(range);
    }
    j["churning_transition"] = ordered_json::array();
    for (const auto& g : churning_caps(m))
        j["churning_transition"].push_back(
            {{"gear", g.gear},
             {"capped_below_rpm", std::isfinite(g.below_rpm) ? ordered_json(g.below_rpm) : ordered_json(nullptr)},
             {"high_over_low_at_1000rpm", g.excess_at_1000rpm}});
    j["assumed"] = assumed_json(c.assumed);
    j["warnings"] = c.warnings;
    return j;
}

std::string check_json(const Case& c) { return json_line(check_json_object(c)); }

nlohmann::ordered_json assumed_json(const std::vector<AssumedValue>& assumed) {
    auto out = nlohmann::ordered_json::array();
    for (const auto& a : assumed) {
        nlohmann::ordered_json j = {{"key", a.key},
                                    {"value", a.value},
                                    {"reason", a.reason},
                                    {"location", a.location.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(a.location)}};
        if (!a.source.empty()) j["source"] = a.source;  // only values the case's own `assumed:` list declares
        out.push_back(std::move(j));
    }
    return out;
}

std::string mesh_profile_csv(const Case& c, const std::string& mesh_name, double omega_in, double torque_in,
                             double oil_temperature, int positions) {
    const auto& m = c.model;
    int k = -1;
    std::string names;
    for (size_t i = 0; i < m.gearbox.meshes.size(); ++i) {
        names += (names.empty() ? "" : ", ") + m.gearbox.meshes[i].name;
        if (m.gearbox.meshes[i].name == mesh_name) k = static_cast<int>(i);
    }
    if (k < 0) throw InputError("", 0, 0, "--mesh", "unknown mesh '" + excerpt(mesh_name) + "'; meshes: " + names);
    const solver::PointState p = solver::prepare_point(m, omega_in, torque_in);
    const auto& ms = mesh::mesh_friction_point(m, p.data).meshes[static_cast<size_t>(k)];
    const auto& md = m.layout.meshes[static_cast<size_t>(k)];
    if (ms.F_bn <= 0.0 || ms.omega_rel == 0.0)
        throw InputError("", 0, 0, "--mesh", "mesh '" + excerpt(mesh_name) + "' carries no load or does not turn at this point");
    const auto prof = mesh::ehl_path(md.geom, md.L_mean, ms.omega_rel, ms.F_bn, md.planets, ms.contact.E_prime, ms.sigma,
                                     oil_temperature, m.oil, m.oil.traction, positions, true,
                                     mesh::traction_law(mesh::mesh_forms(m).friction), m.calibration.viscosity_factor);
    std::string s =
        "position_from_pitch_mm,position_from_T1_mm,load_share,p0_GPa,hertz_halfwidth_um,u_entrainment_m_s,v_slide_m_s,"
        "slide_to_roll,h_c_um,h_min_um,lambda,film_temp_C,flash_rise_K,shear_rise_K,mu_ehl,mu,local_efficiency,deborah\n";
    for (const auto& pt : prof.points)
        s += fmt::format("{:.4f},{:.4f},{:.4f},{:.5f},{:.3f},{:.5f},{:.5f},{:.5f},{:.5f},{:.5f},{:.4f},{:.3f},{:.3f},{:.3f},{:.6f},"
                         "{:.6f},{:.6f},{:.4g}\n",
                         pt.from_pitch * 1e3, pt.xi * 1e3, pt.load_share, pt.c.p0 * 1e-9, pt.c.a * 1e6, pt.u_e, pt.v_slide,
                         pt.srr, pt.c.h_c * 1e6, pt.c.h_min * 1e6, pt.c.lambda, pt.c.T_film - 273.15, pt.c.dT_flash,
                         pt.c.dT_shear, pt.c.mu_ehl, pt.c.mu, pt.local_efficiency, pt.c.deborah);
    return s;
}

}  // namespace gearloss::io
