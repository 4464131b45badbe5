#include "solver/operating_point.hpp"

#include "core/message_text.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "mesh/ehl_path.hpp"
#include "seals/radial_lip_seal.hpp"
#include "solver/validate.hpp"

namespace gearloss::solver {

const char* to_string(PointStatus s) {
    switch (s) {
        case PointStatus::ok: return "ok";
        case PointStatus::no_equilibrium: return "no_equilibrium";
        case PointStatus::above_oil_limit: return "above_oil_limit";
        case PointStatus::out_of_range: return "out_of_range";
    }
    return "?";
}

std::string status_text(const PointResult& r) {
    std::string s = to_string(r.status);
    if (r.status != PointStatus::out_of_range || r.cause.empty()) return s;
    s += ": ";
    for (char c : r.cause) s += (c == ',' || c == '"' || c == '\n' || c == '\r') ? ' ' : c;
    return s;
}

namespace {
constexpr double rad_s_to_rpm = 30.0 / std::numbers::pi;

bool finite(double v) { return std::isfinite(v); }
bool finite_non_negative(double v) { return std::isfinite(v) && v >= 0.0; }

// The oil-independent terms of every component at the point, first fault found.
std::string point_fault(const Model& m, const PointState& p) {
    const auto& gb = m.gearbox;
    if (!finite(p.omega_in)) return "input speed";
    if (!finite(p.torque_in)) return "input torque";
    if (!finite(p.power_in)) return "input power";
    for (size_t i = 0; i < p.meshes.size(); ++i) {
        const auto& ms = p.meshes[i];
        const std::string name = "mesh " + gb.meshes[i].name;
        if (!finite(ms.power) || !finite(ms.F_bn) || !finite(ms.contact.w_line)) return name + " load";
        if (!finite(ms.contact.u_e) || !finite(ms.omega_rel)) return name + " speed";
        if (!finite(ms.mu_prefactor)) return name + " friction coefficient";
        if (!finite(ms.H_V) || !finite(ms.sigma)) return name + " loss factor";
    }
    for (size_t g = 0; g < p.churn.size(); ++g) {
        const auto& c = p.churn[g];
        if (!finite(c.omega) || !finite(c.coef_low) || !finite(c.coef_high) || !finite(c.ReC_times_nu))
            return "churning gear " + gb.gears[g].spec.name;
    }
    for (size_t i = 0; i < p.bearings.size(); ++i) {
        if (!finite(p.bearing_omega[i])) return "bearing " + gb.bearings[i].name + " speed";
        if (const char* f = p.bearings[i].fault()) return "bearing " + gb.bearings[i].name + " " + f;
        if (!finite(p.bearing_drag_coef[i])) return "bearing " + gb.bearings[i].name + " drag";
    }
    for (size_t i = 0; i < p.seal_power.size(); ++i)
        if (!finite_non_negative(p.seal_power[i])) return "seal " + gb.seals[i].name;
    for (size_t i = 0; i < p.clutch_slip.size(); ++i)
        if (!finite(p.clutch_slip[i])) return "clutch " + gb.clutches[i].pack.name + " slip";
    if (!finite_non_negative(p.windage)) return "windage";
    return {};
}

std::string degC(double T) { return celsius_text(T); }
}  // namespace

PointState prepare_point(const Model& m, double omega_in, double torque_in) {
    PointState p;
    prepare_point(m, omega_in, torque_in, p);
    return p;
}

void prepare_point(const Model& m, double omega_in, double torque_in, PointState& p) {
    const auto& gb = m.gearbox;
    const auto& L = m.layout;
    const auto& opt = m.options;
    p.meshes.assign(gb.meshes.size(), PointState::MeshState{});
    p.churn.assign(gb.gears.size(), churning::ChurningAtSpeed{});
    p.bearings.assign(gb.bearings.size(), bearings::SkfAtPoint{});
    p.bearing_omega.assign(gb.bearings.size(), 0.0);
    p.seal_power.assign(gb.seals.size(), 0.0);
    p.seal_total = 0.0;
    p.clutch_slip.assign(gb.clutches.size(), 0.0);
    for (size_t i = 0; i < gb.clutches.size(); ++i) p.clutch_slip[i] = L.clutch_slip_ratio[i] * std::abs(omega_in);
    p.any_drag = false;
    p.bearing_drag_coef.assign(gb.bearings.size(), 0.0);
    const Calibration& cal = m.calibration;
    p.windage = cal.windage_W_at_1000rpm * std::pow(std::abs(omega_in) * rad_s_to_rpm / 1000.0, 2.9);
    p.omega_in = omega_in;
    p.torque_in = torque_in;
    p.power_in = omega_in * torque_in;

    for (size_t i = 0; i < gb.meshes.size(); ++i) {
        const auto& md = L.meshes[i];
        auto& ms = p.meshes[i];
        ms.ehl_film_rise.clear();  // no warm start carried over from another point
        const auto& g0 = gb.gears[gb.meshes[i].gear[0]].spec;
        const auto& g1 = gb.gears[gb.meshes[i].gear[1]].spec;
        ms.H_V = md.loss_factor(opt.loss_factor);
        if (opt.lambda_roughness == LambdaRoughness::average_Ra) {
            ms.sigma = 0.5 * (g0.Ra + g1.Ra);
        } else {
            const double q0 = g0.Rq ? *g0.Rq : 1.25 * g0.Ra, q1 = g1.Rq ? *g1.Rq : 1.25 * g1.Ra;
            ms.sigma = std::sqrt(q0 * q0 + q1 * q1);
        }
        // Speeds relative to the carrier (the housing for an ordinary mesh).
        const double w0 = md.relative_speed * omega_in;
        const double vt = std::abs(w0) * 0.5 * md.geom.dw[0];
        const double v_sum = 2.0 * vt * std::sin(md.geom.alpha_wt);
        ms.contact.u_e = 0.5 * v_sum;
        ms.contact.R = md.geom.rho_redC;
        ms.contact.E_prime = m.mesh_E_prime[i];
        ms.contact.SRR = 0.0;  // pitch point
        if (!md.loaded || !opt.mesh || torque_in == 0.0 || w0 == 0.0) continue;
        // Mesh loss on the rolling power (relative to the carrier): P_VZP = mu H_V |P_roll|.
        ms.power = std::abs(p.power_in) * md.rolling_per_W;
        // Line load of one mesh (load shared by the planets of a set).
        const double F_wt = std::abs(md.force_per_Nm * torque_in) / md.planets;
        const double F_bt = F_wt / std::cos(md.geom.alpha_wt);
        const double w_Nmm = F_bt / (md.geom.b_eff * 1e3);
        const double rho_mm = md.geom.rho_redC * 1e3;
        const double Ra_um = 0.5 * (g0.Ra + g1.Ra) * 1e6;
        ms.contact.w_line = F_bt / std::cos(md.geom.beta_b) / md.L_min;
        ms.F_bn = F_bt / std::cos(md.geom.beta_b);
        ms.omega_rel = w0;
        switch (opt.friction) {
            case mesh::FrictionModel::ehl_local:
            case mesh::FrictionModel::schlenk:
            case mesh::FrictionModel::fernandes_mixed:
                ms.mu_prefactor = mesh::mean_friction_schlenk(w_Nmm, v_sum, rho_mm, 1.0, Ra_um, m.oil.X_L);
                break;
            case mesh::FrictionModel::iso_6336_20: {
                // ISO/TS 6336-20 caps the pitch-line speed at 50 m/s in v_sum.
                const double v_sum_c = 2.0 * std::min(vt, 50.0) * std::sin(md.geom.alpha_wt);
                ms.mu_prefactor = mesh::mean_friction_iso_6336_20(w_Nmm, v_sum_c, rho_mm, 1.0, Ra_um, m.oil.X_L);
                break;
            }
        }
    }

    if (opt.churning) {
        for (size_t g = 0; g < gb.gears.size(); ++g) {
            const double h = L.gear_immersion[g];
            if (h <= 0.0) continue;
            const auto& spec = gb.gears[g].spec;
            churning::DippingGear dg;
            dg.Rp = 0.5 * spec.d();
            dg.b = spec.b;
            dg.z = spec.z;
            dg.tooth_height = spec.mn * (spec.ha_star + spec.hf_star);
            dg.alpha = spec.alpha_t();
            dg.h = h;
            const double w = L.body_speed_ratio[L.body_of_gear[g]] * omega_in;
            p.churn[g] = churning::ChurningAtSpeed::make(dg, w, gb.oil_volume);
        }
    }

    const bool neg = torque_in < 0.0;
    const double T = std::abs(torque_in);
    for (size_t i = 0; i < gb.bearings.size(); ++i) {
        const double w = L.bearing_speed_ratio[i] * std::abs(omega_in);
        p.bearing_omega[i] = w;
        if (!opt.bearings) continue;
        const double Fr_gear = T * (neg ? L.bearing_Fr_neg[i] : L.bearing_Fr_pos[i]);
        const double Fcf = L.bearing_Fcf_per_w2[i] * omega_in * omega_in;  // planet centrifugal load
        const double Fr = Fcf > 0.0 ? std::hypot(Fr_gear, Fcf) : Fr_gear;
        const double Fa = T * (neg ? L.bearing_Fa_neg[i] : L.bearing_Fa_pos[i]);
        p.bearings[i] = bearings::SkfAtPoint::make(gb.bearings[i].spec, Fr, Fa, w * rad_s_to_rpm);
        if (cal.bearing_drag_f0 > 0.0) {
            // Palmgren (1959) no-load moment M0 = 1e-7 f0 (nu n)^(2/3) d_m^3 [N mm], P = M0 omega.
            const double n = w * rad_s_to_rpm, dm = gb.bearings[i].spec.dm();
            p.bearing_drag_coef[i] = 1e-7 * cal.bearing_drag_f0 * std::cbrt(n * n) * dm * dm * dm * 1e-3 * w;
        }
        p.any_drag = p.any_drag || p.bearings[i].drag_b != 0.0;
    }

    if (opt.seals)
        for (size_t i = 0; i < gb.seals.size(); ++i) {
            p.seal_power[i] = cal.seal_factor *
                              seals::radial_seal_power(gb.seals[i].diameter, L.seal_speed_ratio[i] * omega_in);
            p.seal_total += p.seal_power[i];
        }
    p.fault = point_fault(m, p);
}

LossBreakdown evaluate_losses(const Model& m, const PointState& p, const lubricant::OilState& s, bool detail,
                              bool film) {
    const auto& gb = m.gearbox;
    const auto& opt = m.options;
    LossBreakdown r;
    const double nu = s.nu_cSt;
    const double lnnu = std::log(nu);

    // Mesh friction.
    const double eta_factor = std::exp(-0.05 * std::log(s.eta * 1e3));  // eta [mPa s]^-0.05
    const bool need_film = detail || film || opt.friction == mesh::FrictionModel::fernandes_mixed;
    if (detail) {
        const size_t n = gb.meshes.size();
        r.mesh_each.assign(n, 0.0);
        r.mesh_mu.assign(n, 0.0);
        r.mesh_lambda.assign(n, 0.0);
        r.mesh_hmin.assign(n, 0.0);
        r.mesh_hc.assign(n, 0.0);
    }
    double lambda_min = 0;
    bool has_lambda = false;
    for (size_t i = 0; i < p.meshes.size(); ++i) {
        const auto& ms = p.meshes[i];
        if (ms.power == 0.0) continue;
        double mu = ms.mu_prefactor * eta_factor * m.calibration.mesh_friction_factor;
        if (need_film) {
            const mesh::Film f =
                mesh::line_contact_film(ms.contact, s.eta, s.alpha_p, s.beta_T, s.k, opt.film_correction);
            const double lambda = f.h_c / ms.sigma;
            if (opt.friction == mesh::FrictionModel::fernandes_mixed) {
                const double xi = mesh::boundary_share_doleschel(lambda);
                mu = (xi * opt.gear_mu_bl + (1.0 - xi) * opt.gear_mu_ehl) * m.calibration.mesh_friction_factor;
            }
            if (!has_lambda || lambda < lambda_min) lambda_min = lambda;
            has_lambda = true;
            if (detail) {
                r.mesh_lambda[i] = lambda;
                r.mesh_hmin[i] = f.h_min;
                r.mesh_hc[i] = f.h_c;
            }
        }
        double loss = ms.power * mu * ms.H_V;
        if (opt.friction == mesh::FrictionModel::ehl_local) {
            // Local thermal EHL along the path of contact at the oil temperature.
            const auto& md = m.layout.meshes[i];
            loss = mesh::ehl_mesh_loss(md.geom, md.L_mean, ms.omega_rel, ms.F_bn, md.planets, ms.contact.E_prime,
                                       ms.sigma, s.T, m.oil, m.oil.traction, &ms.ehl_film_rise) *
                   m.calibration.mesh_friction_factor;
            mu = ms.power * ms.H_V > 0 ? loss / (ms.power * ms.H_V) : 0.0;  // equivalent mean friction
        }
        r.mesh += loss;
        if (detail) {
            r.mesh_each[i] = loss;
            r.mesh_mu[i] = mu;
        }
    }
    r.lambda_min = lambda_min;
    r.has_lambda = has_lambda;

    // Churning.
    if (detail) {
        r.churn_each.assign(gb.gears.size(), 0.0);
        r.churn_regime.assign(gb.gears.size(), churning::Regime::none);
    }
    if (opt.churning) {
        // Re = Omega Rp^2 / nu with nu in m^2/s (SI, as folded in ChurningAtSpeed).
        const double nu021 = std::exp(0.21 * std::log(s.nu));
        for (size_t g = 0; g < p.churn.size(); ++g) {
            const auto& c = p.churn[g];
            if (c.coef_low == 0.0 && c.coef_high == 0.0) continue;
            churning::Regime reg;
            const double P = m.calibration.churning_factor * c.torque(s.rho, s.nu, nu021, &reg) * c.omega;
            r.churning += P;
            if (detail) {
                r.churn_each[g] = P;
                r.churn_regime[g] = reg;
            }
        }
    }

    // Bearings.
    if (detail) r.bearing_each.assign(gb.bearings.size(), 0.0);
    if (opt.bearings && !p.bearings.empty()) {
        const double nu06 = std::exp(0.6 * lnnu), nu064 = std::exp(0.64 * lnnu), nu14 = std::exp(1.4 * lnnu);
        const double nu1379 = p.any_drag ? std::exp(1.379 * lnnu) : 0.0;
        for (size_t i = 0; i < p.bearings.size(); ++i) {
            const double M = p.bearings[i].moment(nu, nu06, nu064, nu14, nu1379);  // N*mm
            const double P = M * 1e-3 * p.bearing_omega[i] * gb.bearings[i].multiplicity;  // x planets
            r.bearings += P;
            if (detail) r.bearing_each[i] = P;
        }
    }

    r.windage = p.windage;
    r.churning += p.windage;
    if (m.calibration.bearing_drag_f0 > 0.0) {
        const double nu23 = std::cbrt(nu * nu);
        for (size_t i = 0; i < p.bearing_drag_coef.size(); ++i) {
            const double P = p.bearing_drag_coef[i] * nu23 * gb.bearings[i].multiplicity;
            r.bearings += P;
            if (detail) r.bearing_each[i] += P;
        }
    }
    r.seals = p.seal_total;
    if (detail) r.seal_each = p.seal_power;
    if (detail) r.clutch_each.assign(gb.clutches.size(), 0.0);
    for (size_t i = 0; i < gb.clutches.size(); ++i) {
        if (p.clutch_slip[i] == 0.0) continue;
        const double P = clutch::open_pack_drag(gb.clutches[i].pack, s.eta, s.rho, p.clutch_slip[i]).power;
        r.clutches += P;
        if (detail) r.clutch_each[i] = P;
    }
    if (p.omega_in != 0.0) r.auxiliary = m.calibration.auxiliary_W;
    return r;
}

double total_loss(const Model& m, const PointState& p, double T_oil) {
    return evaluate_losses(m, p, m.oil_state(T_oil), false).total();
}

std::string loss_fault(const Model& m, const PointState& p, double T, double ambient) {
    const auto& gb = m.gearbox;
    if (auto f = oil_temperature_fault(m.oil, T)) return "oil temperature " + *f;
    const lubricant::OilState s = m.oil_state(T);
    const std::string at = " at " + degC(T);
    if (!(s.nu > 0 && finite(s.nu) && finite(s.eta) && s.eta > 0)) return "oil '" + m.oil.name + "' viscosity" + at;
    if (!(s.rho > 0 && finite(s.rho))) return "oil '" + m.oil.name + "' density" + at;
    if (!(finite(s.alpha_p) && finite(s.beta_T) && s.k > 0 && finite(s.k) && finite(s.cp)))
        return "oil '" + m.oil.name + "' properties" + at;
    const LossBreakdown L = evaluate_losses(m, p, s, true, true);
    for (size_t i = 0; i < gb.meshes.size(); ++i) {
        if (!finite_non_negative(L.mesh_each[i])) return "mesh " + gb.meshes[i].name + " friction loss" + at;
        if (p.meshes[i].power > 0 && !finite(L.mesh_lambda[i])) return "mesh " + gb.meshes[i].name + " film thickness" + at;
    }
    for (size_t g = 0; g < gb.gears.size(); ++g)
        if (!finite_non_negative(L.churn_each[g])) return "churning gear " + gb.gears[g].spec.name + at;
    for (size_t i = 0; i < gb.bearings.size(); ++i)
        if (!finite_non_negative(L.bearing_each[i])) return "bearing " + gb.bearings[i].name + " loss" + at;
    for (size_t i = 0; i < gb.seals.size(); ++i)
        if (!finite_non_negative(L.seal_each[i])) return "seal " + gb.seals[i].name + at;
    for (size_t i = 0; i < gb.clutches.size(); ++i)
        if (!finite_non_negative(L.clutch_each[i])) return "clutch " + gb.clutches[i].pack.name + " drag" + at;
    if (!finite_non_negative(L.windage)) return "windage" + at;
    if (!finite_non_negative(L.auxiliary)) return "auxiliary loss" + at;
    if (!finite_non_negative(L.total())) return "total loss" + at;
    if (!finite(m.heat_flow(T, ambient, p.omega_in))) return "heat rejection" + at;
    return {};
}

thermal::Equilibrium solve_temperature(const Model& m, const PointState& p, double ambient) {
    auto F = [&](double Toil) { return total_loss(m, p, Toil) - m.heat_flow(Toil, ambient, p.omega_in); };
    auto G = [&](double Toil) {
        const double Tq = std::max(Toil, ambient + 0.5);
        return m.heat_flow(Tq, ambient, p.omega_in) / (Tq - ambient);
    };
    return thermal::solve_equilibrium(F, G, ambient, m.thermal.equilibrium);
}

PointResult solve_point(const Model& m, double omega_in, double torque_in, bool detail, double ambient) {
    PointResult r;
    r.speed_in = omega_in;
    r.torque_in = torque_in;
    r.ambient = ambient;
    r.power_in = omega_in * torque_in;
    // Out of range: no numbers, the cause in the status.
    auto out_of_range = [&r](std::string cause) {
        r.status = PointStatus::out_of_range;
        r.cause = std::move(cause);
        r.losses = LossBreakdown{};
        r.oil_temperature = std::numeric_limits<double>::quiet_NaN();
        r.power_out = r.torque_out = r.omega_out = r.efficiency = 0.0;
        r.has_efficiency = false;
        return r;
    };
    if (auto f = speed_fault(omega_in)) return out_of_range(*f);
    if (auto f = torque_fault(torque_in)) return out_of_range(*f);
    const bool fixed = m.thermal.mode == ThermalMode::fixed;
    if (!fixed) {
        if (auto f = ambient_fault(ambient)) return out_of_range(*f);
        if (auto f = oil_temperature_fault(m.oil, ambient)) return out_of_range("ambient " + *f);
    } else if (auto f = oil_temperature_fault(m.oil, m.thermal.oil_temperature)) {
        return out_of_range("fixed oil temperature " + *f);
    }
    // Per-thread storage: a map solves many points per thread without allocating.
    thread_local PointState p;
    prepare_point(m, omega_in, torque_in, p);
    if (!p.fault.empty()) return out_of_range(p.fault);
    r.power_in = p.power_in;
    double T;
    if (fixed) {
        T = m.thermal.oil_temperature;
    } else {
        const thermal::Equilibrium eq = solve_temperature(m, p, ambient);
        r.evaluations = eq.evaluations;
        r.thermal_residual = eq.residual;
        switch (eq.status) {
            case thermal::EquilibriumStatus::ok: break;
            case thermal::EquilibriumStatus::no_equilibrium:
                r.status = PointStatus::no_equilibrium;
                r.oil_temperature = eq.T;
                return r;
            case thermal::EquilibriumStatus::non_finite: {
                const std::string f = loss_fault(m, p, eq.T, ambient);
                return out_of_range(f.empty() ? "thermal equilibrium: a value that is not finite at " + degC(eq.T) : f);
            }
            case thermal::EquilibriumStatus::iteration_limit:
                return out_of_range("thermal equilibrium: no bracket within " +
                                    std::to_string(m.thermal.equilibrium.max_bracket_steps) + " steps (last at " +
                                    degC(eq.T) + ")");
        }
        T = eq.T;
        if (T > m.oil.max_temperature) r.status = PointStatus::above_oil_limit;
    }
    r.oil_temperature = T;
    r.losses = evaluate_losses(m, p, m.oil_state(T), detail, true);
    const double Ploss = r.losses.total();
    // Every component's loss a finite, non-negative number (the film too), else the cause.
    if (!finite_non_negative(Ploss) || !finite(r.losses.lambda_min) || !finite_non_negative(r.losses.churning) ||
        !finite_non_negative(r.losses.mesh) || !finite_non_negative(r.losses.bearings) ||
        !finite_non_negative(r.losses.seals) || !finite_non_negative(r.losses.clutches)) {
        const std::string f = loss_fault(m, p, T, ambient);
        return out_of_range(f.empty() ? "losses at " + degC(T) + " are not finite" : f);
    }
    r.power_out = r.power_in - Ploss;
    r.omega_out = m.layout.ratio * omega_in;
    // Output torque in the output's own sense of rotation: positive when power
    // leaves through the output shaft.
    if (r.omega_out != 0.0) {
        r.torque_out = r.power_out / std::abs(r.omega_out);
    } else {
        r.torque_out = torque_in / std::abs(m.layout.ratio);  // standstill: ideal torque ratio
    }
    if (r.power_in > 0.0) {
        // When the losses exceed the input power no power reaches the output
        // (power_out < 0 says by how much); the efficiency is then 0, not negative.
        r.efficiency = std::max(0.0, r.power_out / r.power_in);
        r.has_efficiency = true;
    } else if (r.power_in < 0.0) {
        // Driven from the output: power enters there, |P_in| leaves at the input.
        r.efficiency = -r.power_in / (-r.power_in + Ploss);
        r.has_efficiency = true;
    }
    if (!finite(r.power_out) || !finite(r.torque_out) || !finite(r.omega_out) || !finite(r.efficiency))
        return out_of_range("output power, torque or efficiency is not finite");
    return r;
}

}  // namespace gearloss::solver
