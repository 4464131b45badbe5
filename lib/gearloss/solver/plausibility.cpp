#include "gearloss/solver/plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/geometry/gear_geometry.hpp"
#include "gearloss/clutch/film_heating.hpp"
#include "gearloss/mechanisms/mesh_friction_mechanism.hpp"
#include "gearloss/mesh/friction.hpp"
#include "gearloss/model/validate.hpp"
#include "gearloss/churning/fitted_range.hpp"
#include "gearloss/losses/loss_mechanism.hpp"
#include "gearloss/bearings/skf_model.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::solver {

std::optional<HousingBox> housing_box(double area, double height, double length) {
    // A = 2(LH + LW + HW)  ->  W = (A/2 - L H) / (L + H)
    const double width = (0.5 * area - length * height) / (length + height);
    if (!(width > 0) || !std::isfinite(width)) return std::nullopt;
    return HousingBox{length, width, height};
}

namespace {

double tip_radius(const Model& m, size_t g) {
    const auto& gb = m.gearbox;
    const auto& spec = gb.gears[g].spec;
    double ra = 0.5 * spec.d() + spec.mn * (spec.ha_star + spec.x);
    for (size_t k = 0; k < gb.meshes.size(); ++k)
        for (int s = 0; s < 2; ++s)
            if (gb.meshes[k].gear[s] == static_cast<int>(g)) ra = 0.5 * m.layout.meshes[k].geom.da[s];
    return ra;
}

// Area of the circular segment of radius r below a chord at depth h (0 <= h <= 2r).
double segment_area(double r, double h) {
    h = std::clamp(h, 0.0, 2.0 * r);
    const double theta = std::acos(1.0 - h / r);  // half angle
    return r * r * (theta - std::sin(theta) * std::cos(theta));
}

}  // namespace

std::vector<PlausibilityFinding> check_plausibility(const Model& m, Lubrication lubrication,
                                                    const std::optional<HousingBox>& box,
                                                    std::optional<double> housing_height) {
    using S = PlausibilityFinding::Severity;
    using J = PlausibilityFinding::Subject;
    std::vector<PlausibilityFinding> out;
    const auto& gb = m.gearbox;
    const auto& L = m.layout;
    const double mm = 1e3;

    double deepest = 0, displaced = 0;
    bool any_dipping = false;
    for (size_t g = 0; g < gb.gears.size(); ++g) {
        const double h = L.gear_immersion[g];
        if (!(h > 0)) continue;
        any_dipping = true;
        deepest = std::max(deepest, h);
        const double ra = tip_radius(m, g);
        const auto& gear = gb.gears[g];
        displaced += segment_area(ra, h) * gear.spec.b;
        // The churning correlation of Changenet & Velex (2007) was fitted on partly
        // immersed gears; a gear under the oil altogether is outside it.
        if (h >= 2.0 * ra)
            out.push_back({S::warning, J::gear, static_cast<int>(g),
                           fmt::format("gear '{}' is fully submerged (immersion {:.1f} mm, tip diameter {:.1f} mm): the "
                                       "churning model (Changenet & Velex 2007) is fitted for partly immersed gears and "
                                       "is extrapolated here; check the oil level",
                                       gear.spec.name, h * mm, 2.0 * ra * mm)});
        else if (h > ra && !gear.is_planet() && !gear.spec.internal)
            out.push_back({S::note, J::gear, static_cast<int>(g),
                           fmt::format("the oil stands {:.1f} mm above the axis of gear '{}' (immersion {:.1f} mm > tip "
                                       "radius {:.1f} mm): the shaft's seals and bearings run submerged",
                                       (h - ra) * mm, gear.spec.name, h * mm, ra * mm)});
    }
    // The selected churning form against its range, per dipping gear (once per case, not per
    // operating point: the quantities checked do not depend on the point).
    if (const auto* churn = m.mechanisms.find("churning"); churn && churn->enabled()) {
        const auto range = churning::fitted_range(churn->form(m, "form"));
        if (!range.limits.empty())
            for (size_t g = 0; g < gb.gears.size(); ++g) {
                if (!(L.gear_immersion[g] > 0)) continue;
                const auto& spec = gb.gears[g].spec;
                const double D = 2.0 * tip_radius(m, g);
                const std::vector<churning::GivenSpan> given{
                    {"helix angle", spec.beta * 180.0 / std::numbers::pi, spec.beta * 180.0 / std::numbers::pi},
                    {"h/D", L.gear_immersion[g] / D, L.gear_immersion[g] / D},
                    {"b/D", spec.b / D, spec.b / D},
                    {"V0/D^3", gb.oil_volume / (D * D * D), gb.oil_volume / (D * D * D)}};
                const std::string why = churning::outside_range(range, given);
                if (!why.empty())
                    out.push_back({S::note, J::gear, static_cast<int>(g),
                                   fmt::format("churning form {} outside its {} range for gear '{}': {}{}", range.form,
                                               range.fitted ? "fitted" : "defined", spec.name, why,
                                               range.form == "heingartner_mba_2003"
                                                   ? " (the gear keeps the default form, changenet_velex_2007)"
                                                   : "")});
            }
    }
    if (!any_dipping && lubrication == Lubrication::dip)
        out.push_back({S::warning, J::lubrication, -1,
                       gb.oil_level ? fmt::format("no gear touches the oil (oil level {:.1f} mm is below every gear tip): "
                                                  "churning is zero; set 'housing.lubrication: injection' for a "
                                                  "jet-lubricated box, or check the oil level",
                                                  *gb.oil_level * mm)
                                    : std::string("no gear dips (no 'oil_level' and no gear 'immersion'): churning is zero; "
                                                  "set 'housing.lubrication: injection' for a jet-lubricated box")});
    if (box) {
        const double V = gb.oil_volume, Vh = box->volume();
        if (V > Vh)
            out.push_back({S::error, J::oil_volume, -1,
                           fmt::format("oil volume {:.2f} L exceeds the volume of the housing ({:.0f} x {:.0f} x {:.0f} mm "
                                       "= {:.2f} L, from housing area, height and length)",
                                       V * 1e3, box->length * mm, box->width * mm, box->height * mm, Vh * 1e3)});
        // The floor lies below the deepest gear tip, so the oil stands at least `deepest`
        // over the whole floor; the dipping gears displace part of that pool.
        const double needed = box->length * box->width * deepest - displaced;
        if (any_dipping && V < 0.5 * needed)
            out.push_back({S::warning, J::oil_volume, -1,
                           fmt::format("oil volume {:.2f} L cannot reach the oil level: a pool {:.1f} mm deep (the deepest "
                                       "immersion) over the housing floor ({:.0f} x {:.0f} mm) holds at least {:.2f} L",
                                       V * 1e3, deepest * mm, box->length * mm, box->width * mm, needed * 1e3)});
    }
    if (gb.oil_level && housing_height && *housing_height > 0) {
        // The housing cannot be lower than the gears, so the oil cannot stand higher
        // above the lowest gear tip than the housing is tall.
        double bottom = 1e300;
        for (size_t g = 0; g < gb.gears.size(); ++g)
            if (!gb.gears[g].is_planet()) bottom = std::min(bottom, L.shaft_centre[gb.gears[g].shaft].y() - tip_radius(m, g));
        if (bottom < 1e300 && *gb.oil_level - bottom > *housing_height)
            out.push_back({S::error, J::oil_level, -1,
                           fmt::format("oil level {:.1f} mm is {:.1f} mm above the lowest gear tip, more than the "
                                       "housing height {:.0f} mm",
                                       *gb.oil_level * mm, (*gb.oil_level - bottom) * mm, *housing_height * mm)});
    }
    const auto geometry = check_mesh_geometry(m);
    out.insert(out.end(), geometry.begin(), geometry.end());
    return out;
}

std::vector<PlausibilityFinding> check_mesh_geometry(const Model& m) {
    using S = PlausibilityFinding::Severity;
    using J = PlausibilityFinding::Subject;
    std::vector<PlausibilityFinding> out;
    const auto& gb = m.gearbox;
    if (m.layout.meshes.size() != gb.meshes.size()) return out;  // not finalised
    std::vector<bool> tip_checked(gb.gears.size(), false);
    for (size_t k = 0; k < gb.meshes.size(); ++k) {
        const auto& geom = m.layout.meshes[k].geom;
        if (geom.fit.slack()) {
            PlausibilityFinding f{S::warning, J::centre_distance, -1,
                                  geometry::describe_fit(geom.fit) +
                                      ": the shifts and the centre distance disagree beyond the housing tolerance "
                                      "(the losses use alpha_wt at the given centre distance)"};
            f.mesh = static_cast<int>(k);
            out.push_back(std::move(f));
        }
        // A given tip against its shift: ISO 21771 d_a = d + 2 m_n (h*_a + x + k) with k <= 0; a
        // tip longer than the full-depth one (k > 0) beyond the tip-diameter tolerance h11
        // (IT11, ISO 286-1) does not fit the shift (or the shift is missing).
        for (int s = 0; s < 2; ++s) {
            const int g = gb.meshes[k].gear[s];
            if (tip_checked[g] || geom.tip_source[s] == geometry::TipSource::iso_tip_alteration) continue;
            tip_checked[g] = true;
            const auto& spec = gb.gears[g].spec;
            const double longer = 2.0 * spec.mn * geom.k_applied[s];
            const double tol = geom.tip_source[s] == geometry::TipSource::given_tip_diameter
                                   ? geometry::iso286_tolerance(geom.da[s], 11) : 1e-9;
            if (longer > tol)
                out.push_back({S::warning, J::tip, g,
                               fmt::format("gear '{}': its {} gives d_a = {:.3f} mm, {:.3f} mm {} than the full-depth tip {:.3f} mm of its "
                                           "profile shift x = {:.4f} (ISO 21771: d_a = d + 2 m_n (h*_a + x + k), k = "
                                           "{:.4f} > 0); check the tip or the shift",
                                           spec.name, geometry::to_string(geom.tip_source[s]), geom.da[s] * 1e3,
                                           longer * 1e3, spec.internal ? "smaller" : "larger",
                                           (geom.da[s] + (spec.internal ? longer : -longer)) * 1e3, spec.x,
                                           geom.k_applied[s])});
        }
    }
    return out;
}

std::vector<PlausibilityFinding> check_churning_speed_range(const Model& m, const std::vector<double>& input_speeds) {
    std::vector<PlausibilityFinding> out;
    const auto* churn = m.mechanisms.find("churning");
    if (!churn || !churn->enabled() || input_speeds.empty()) return out;
    const auto range = churning::fitted_range(churn->form(m, "form"));
    const auto speed_limit = std::find_if(range.limits.begin(), range.limits.end(),
                                          [](const auto& l) { return l.quantity == "pitch-line speed"; });
    if (speed_limit == range.limits.end()) return out;
    double w_lo = 1e300, w_hi = 0;
    for (double w : input_speeds) {
        w_lo = std::min(w_lo, std::abs(w));
        w_hi = std::max(w_hi, std::abs(w));
    }
    const auto& gb = m.gearbox;
    const auto& L = m.layout;
    for (size_t g = 0; g < gb.gears.size(); ++g) {
        if (!(L.gear_immersion[g] > 0)) continue;
        // Pitch-line speed at the reference circle: |Omega_g| d/2.
        const double r = std::abs(L.body_speed_ratio[L.body_of_gear[g]]) * 0.5 * gb.gears[g].spec.d();
        const std::string why = churning::outside_range(range, {{"pitch-line speed", r * w_lo, r * w_hi}});
        if (!why.empty())
            out.push_back({PlausibilityFinding::Severity::note, PlausibilityFinding::Subject::gear, static_cast<int>(g),
                           fmt::format("churning form {} outside its {} range for gear '{}': {} ({})", range.form,
                                       range.fitted ? "fitted" : "defined", gb.gears[g].spec.name, why, range.provenance)});
    }
    return out;
}

std::vector<PlausibilityFinding> check_clutch_film_range(const Model& m, const std::vector<double>& input_speeds) {
    std::vector<PlausibilityFinding> out;
    const auto& gb = m.gearbox;
    if (gb.clutches.empty() || input_speeds.empty()) return out;
    const auto valid = oil_validity(m.oil);
    constexpr double rpm = 30.0 / std::numbers::pi;
    for (size_t i = 0; i < gb.clutches.size() && i < m.layout.clutch_slip_ratio.size(); ++i) {
        const double ratio = m.layout.clutch_slip_ratio[i];
        if (!(ratio > 0)) continue;  // engaged
        const auto& pack = gb.clutches[i].pack;
        // Without a supply the gap is taken as always full: the drag then rises with slip speed
        // forever, without the peak and gradual fall of a pack whose supply can no longer fill it.
        if (!(pack.oil_supply > 0) && std::any_of(input_speeds.begin(), input_speeds.end(), [](double w) { return w > 0; }))
            out.push_back({PlausibilityFinding::Severity::note, PlausibilityFinding::Subject::clutch, static_cast<int>(i),
                           fmt::format("open pack '{}' has no oil_supply: its gaps are taken as always full of oil, so "
                                       "its drag keeps rising with slip speed, without the peak and fall of a film "
                                       "that its supply can no longer fill (give oil_supply to model the breakup)",
                                       pack.name)});
        // The warmest oil temperature (1 K steps) at which, at one of the case's input speeds, the pack
        // still holds oil that drags more than the air (the film is not broken) and whose Nahme number
        // is beyond the range.
        double below = 0, at_speed = 0;
        for (double w : input_speeds) {
            const double slip = ratio * w;
            if (!(slip > 0)) continue;
            for (double T = std::ceil(valid.T_min) + 1.0; T < valid.T_max; T += 1.0) {
                if (T <= below) continue;
                const auto s = m.oil_state(T);
                if (!(clutch::nahme_number(s.beta_T, s.eta, slip * pack.r_outer, s.k) > clutch::film_heating_nahme_limit))
                    break;  // the Nahme number falls as the oil warms
                if (clutch::open_pack_drag(pack, s, slip).regime != clutch::FilmRegime::broken) below = T, at_speed = w;
            }
        }
        if (below == 0) continue;
        out.push_back({PlausibilityFinding::Severity::note, PlausibilityFinding::Subject::clutch, static_cast<int>(i),
                       fmt::format("open pack '{}' (slip {:.0f} rpm at input speed {:.0f} rpm): below {:.0f} degC its "
                                   "oil film heats beyond the range of the drag model (Nahme number above {:.1f}: the "
                                   "film's core runs more than 1/beta above plates taken at the oil temperature); the "
                                   "clutch drag there is extrapolated",
                                   pack.name, ratio * at_speed * rpm, at_speed * rpm, below - 273.15,
                                   clutch::film_heating_nahme_limit)});
    }
    return out;
}

std::vector<PlausibilityFinding> check_bearing_starvation(const Model& m, double omega_in) {
    std::vector<PlausibilityFinding> out;
    if (m.thermal.mode != ThermalMode::fixed || !(omega_in > 0)) return out;
    const double nu = m.oil_state(m.thermal.oil_temperature).nu_cSt;  // mm^2/s
    std::string past;
    for (size_t i = 0; i < m.gearbox.bearings.size(); ++i) {
        const auto& b = m.gearbox.bearings[i];
        const double w = m.layout.bearing_speed_ratio[i] * omega_in;
        const double limit = bearings::skf_starvation_limit_nu(b.spec, w) * 1e6;  // mm^2/s
        if (!(nu > limit)) continue;
        past += fmt::format("{}'{}' (limit {:.4g} mm^2/s at {:.0f} r/min)", past.empty() ? "" : ", ", b.name, limit,
                            w * 30.0 / std::numbers::pi);
    }
    if (!past.empty())
        out.push_back({PlausibilityFinding::Severity::note, PlausibilityFinding::Subject::lubrication, -1,
                       fmt::format("at {:.1f} degC ({:.0f} mm^2/s) and {:.0f} rpm the SKF (2004) starvation factor "
                                   "phi_rs of bearing(s) {} is past its limit (the viscosity where phi_ish phi_rs (nu n)^0.6 "
                                   "peaks): their rolling moment is held at its value at the limit",
                                   m.thermal.oil_temperature - 273.15, nu, omega_in * 30.0 / std::numbers::pi, past)});
    return out;
}

std::vector<PlausibilityFinding> check_mesh_film_range(const Model& m,
                                                       const std::vector<std::pair<double, double>>& points) {
    std::vector<PlausibilityFinding> out;
    const auto& gb = m.gearbox;
    if (gb.meshes.empty() || points.empty() || !m.mechanisms.find("mesh") || !m.mechanisms.at("mesh").enabled()) return out;
    const auto& forms = mesh::mesh_forms(m);
    const bool local = forms.friction == mesh::FrictionModel::ehl_local || forms.friction == mesh::FrictionModel::ehl_maxwell;
    // The local forms always correct their films by Gupta et al. (1992); the others when chosen.
    if (!local && forms.film_correction != mesh::ThermalFilmCorrection::gupta) return out;
    const auto valid = oil_validity(m.oil);
    // The coldest oil the case runs with: its fixed oil temperature, else the ambient (a
    // stabilised or transient oil does not fall below it); a colder oil is another case.
    const double T_case = m.thermal.mode == ThermalMode::fixed ? m.thermal.oil_temperature : m.thermal.ambient;
    constexpr double rpm = 30.0 / std::numbers::pi;
    for (size_t i = 0; i < gb.meshes.size(); ++i) {
        // The warmest oil temperature (1 K steps) at which, at one of the case's points, the
        // pitch-point film's thermal loading L = beta eta0 u_e^2 / k is past the turning point
        // L* of the correlation (mesh::gupta_turning_point): the load term is held there.
        double below = 0, at_speed = 0, at_torque = 0, at_L_star = 0;
        for (const auto& [w, torque] : points) {
            if (!(std::abs(w) > 0) || torque == 0.0) continue;
            const auto p = prepare_point(m, w, torque);
            const auto& ms = mesh::mesh_friction_point(m, p.data).meshes.at(i);
            const auto& lc = ms.contact;
            if (!(ms.power > 0) || !(lc.u_e > 0) || !(lc.w_line > 0)) continue;
            const double L_star =
                mesh::gupta_turning_point(mesh::hertz_pressure(lc.w_line, lc.R, lc.E_prime) / lc.E_prime, lc.SRR);
            for (double T = std::max(std::ceil(valid.T_min) + 1.0, T_case); T < valid.T_max; T += 1.0) {
                if (T <= below) continue;
                const auto s = m.oil_state(T);
                if (!(s.beta_T * s.eta * lc.u_e * lc.u_e / s.k > L_star)) break;  // L falls as the oil warms
                below = T, at_speed = w, at_torque = torque, at_L_star = L_star;
            }
        }
        if (below == 0) continue;
        PlausibilityFinding f{PlausibilityFinding::Severity::note, PlausibilityFinding::Subject::mesh_film, -1,
                              fmt::format("mesh '{}' (input {:.0f} rpm, {:.0f} N m): below {:.0f} degC the thermal "
                                          "film correction of Gupta et al. (1992) is past its turning point (the "
                                          "pitch point's inlet heating parameter beta eta u_e^2/k above {:.3g}): its load term is "
                                          "held there, and the film{} and Lambda are extrapolated",
                                          gb.meshes[i].name, std::abs(at_speed) * rpm, at_torque, below - 273.15, at_L_star,
                                          local ? ", the local EHL friction" : "")};
        f.mesh = static_cast<int>(i);
        out.push_back(std::move(f));
    }
    return out;
}

}  // namespace gearloss::solver
