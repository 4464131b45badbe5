#pragma once
// SKF (2004) rolling-bearing frictional moment (the catalogue's total-moment equation):
//   M = phi_ish phi_rs M_rr + M_sl + M_seal + M_drag
// Interface in SI: lengths in m, speed omega in rad/s, kinematic viscosity in m^2/s, loads in N,
// moments in N*m, powers in W. The SKF correlations are empirical and dimensional (fitted with
// lengths in mm, speed in r/min, viscosity in mm^2/s, moments in N*mm): skf_model.cpp converts to
// those units in one place. The catalogue constants (SkfConstants, K_rs, the seal's K_S1 and K_S2)
// keep the catalogue's units. One exception, for speed: SkfAtPoint::moment takes the viscosity
// powers that every bearing shares in cSt (= mm^2/s), computed once per temperature by the caller.
#include <array>
#include <optional>

#include "gearloss/bearings/skf_constants.hpp"

namespace gearloss::bearings {

struct BearingSpec {
    BearingType type = BearingType::deep_groove_ball;
    double d = 0, D = 0, B = 0;   // bore, outside diameter, width [m]
    double C0 = 0;                // static load rating, N (deep groove ball: needed for axial load)
    double Y = 1.6;               // tapered roller axial factor (product table)
    SkfConstants k;
    // Replenishment/starvation constant of phi_rs (SKF 2004): 3e-8 for a low-level oil bath, splash
    // and oil jet, 6e-8 for grease and oil-air, 0 where the rolling elements are flooded (an oil
    // bath at or above the centre of the lowest rolling element: phi_rs does not apply).
    double K_rs = 3e-8;
    double mu_bl = 0.15;
    double mu_ehl = 0.05;
    // Integral contact seals (both sides): M_seal = K_S1 d_s^beta + K_S2, with the catalogue's
    // K_S1 and K_S2 (for d_s in mm and M_seal in N*mm). seal_ds: seal counterface diameter [m];
    // unset: the inner-ring shoulder estimate d + 0.2 (D - d).
    double seal_KS1 = 0, seal_KS2 = 0, seal_beta = 2.0;
    std::optional<double> seal_ds;
    // Oil bath drag: oil level H above the lowest point of the outer-ring raceway [m]
    // and the drag factor V_M read from the SKF diagram for H/d_m. A level at or above the
    // centre of the lowest rolling element (flooded_level()) also floods the bearing: no phi_rs.
    std::optional<double> bath_H;
    double bath_VM = 0;

    double dm() const { return 0.5 * (d + D); }  // mean diameter [m]
    // Height of the lowest rolling element's centre above the lowest point of the outer-ring
    // raceway [m]: half a rolling-element diameter, estimated as D_w = 0.3 (D - d) (the section of
    // radial ball and roller bearings of the 62/63/2/3/303 series, e.g. 6205: 7.94 mm of 27 mm).
    double flooded_level() const { return 0.15 * (D - d); }
    // Whether SKF's starvation factor phi_rs applies: K_rs > 0 and no oil bath up to flooded_level().
    bool starvation_applies() const { return K_rs > 0.0 && !(bath_H && *bath_H >= flooded_level()); }
};

struct SkfLoadTerms {
    // The catalogue's load/geometry functions, in its units: M_rr = G_rr (nu n)^0.6 [N*mm] and
    // M_sl = G_sl mu_sl [N*mm] for nu in mm^2/s and n in r/min.
    double G_rr = 0, G_sl = 0;
    // Deep groove ball under axial load: the contact angle alpha_F [rad] of SKF's formula
    // (0 otherwise). Past 90 deg the formula has left its range (F_a far above C0).
    double alpha_F = 0;
};

// Load/geometry functions G_rr, G_sl (SKF Table 2a). Fr, Fa in N, omega in rad/s
// (speed enters only through the centrifugal F_g of angular-contact types).
SkfLoadTerms skf_load_terms(const BearingSpec& b, double Fr, double Fa, double omega);

// The powers of a bearing's dimensions in its SKF terms (d_m to the type's exponents in the load
// functions, the seal counterface term d_s^beta, d_m^4 or d_m^5 of the drag): independent of
// load, speed and oil, so a caller that evaluates a bearing at many points computes them once
// (SkfAtPoint::make's second form) and again only when the dimensions it was made from change.
struct SkfGeometry {
    std::array<double, 6> power{};
    static SkfGeometry of(const BearingSpec& b);
    // Whether these powers were made from b's present dimensions, type and seal exponent.
    bool matches(const BearingSpec& b) const {
        return made && type == b.type && d == b.d && D == b.D && seal_beta == b.seal_beta &&
               seal_ds == b.seal_ds.value_or(-1.0);
    }

private:
    bool made = false;
    BearingType type{};
    double d = 0, D = 0, seal_beta = 0, seal_ds = -1.0;
};

struct SkfMoment {
    double rolling = 0, sliding = 0, seal = 0, drag = 0;  // N*m
    double phi_ish = 1, phi_rs = 1, phi_bl = 1;
    // The point lies beyond the starvation limit (skf_starvation_limit_nu): the rolling moment
    // is the one at the limit viscosity (phi_ish and phi_rs included).
    bool starvation_held = false;
    double total() const { return rolling + sliding + seal + drag; }
};

// Full evaluation (used by the tests): Fr, Fa in N, omega in rad/s, nu in m^2/s.
SkfMoment skf_moment(const BearingSpec& b, double Fr, double Fa, double omega, double nu_m2s);

// The starvation limit: the kinematic viscosity [m^2/s] at speed omega [rad/s] past which SKF's
// starved rolling moment phi_ish phi_rs G_rr (nu n)^0.6 would fall as the oil thickens (its
// maximum over nu; phi_rs alone gives K_rs nu n (d+D) sqrt(K_Z / (2 (D-d))) = 0.6, phi_ish moves it
// lower); infinity where phi_rs does not apply (flooded, K_rs = 0) or the bearing stands. Beyond it
// the model holds the rolling moment at its value at this viscosity: a starved film is set by the
// oil that reaches the contact, and SKF's exponential, fitted over moderate nu n, is not
// extrapolated into a loss that falls with speed or with colder oil.
double skf_starvation_limit_nu(const BearingSpec& b, double omega);

// Oil-bath drag moment [N*m] (SKF (2013) catalogue form): omega in rad/s, nu in m^2/s.
double skf_drag_moment(const BearingSpec& b, double omega, double nu_m2s);

// Palmgren (1959) no-load moment M0 = 1e-7 f0 (nu n)^(2/3) d_m^3 [N*mm; nu in mm^2/s, n in r/min,
// d_m in mm] as a power P = M0 omega = c nu_cSt^(2/3): returns c [W per cSt^(2/3)] at omega [rad/s].
// With another power b of nu n, anchored where Palmgren's law begins (nu n = 2000, below which
// he gives M0 = 160e-7 f0 d_m^3): M0 = 1e-7 f0 2000^(2/3) (nu n/2000)^b d_m^3, P = c nu_cSt^b.
double palmgren_drag_coef(const BearingSpec& b, double f0, double omega, double exponent = 2.0 / 3.0);

// Terms folded once per operating point so that each temperature costs a few
// exponentials; the caller supplies the shared powers of nu. The folded terms are in the
// catalogue's units (r/min, mm, N*mm).
struct SkfAtPoint {
    double n = 0;            // speed in the catalogue unit r/min, magnitude
    double rr = 0;           // G_rr n^0.6
    double a_ish = 0;        // 1.84e-9 (n d_m)^1.28
    double a_rs = 0;         // K_rs n (d+D) sqrt(K_Z / (2 (D-d))); 0 where phi_rs does not apply
    double nu_rs_limit = 0;  // starvation limit in cSt (skf_starvation_limit_nu; infinity when a_rs = 0)
    double a_bl = 0;         // 2.6e-8 n^1.4 d_m
    double G_sl = 0, mu_bl = 0, mu_ehl = 0;
    double M_seal = 0;
    double drag_a = 0;       // drag first term (independent of nu)
    double drag_b = 0;       // drag second term / nu^1.379
    double alpha_F = 0;      // contact angle of a deep groove ball bearing under axial load [rad]
    // Fr, Fa in N, omega in rad/s.
    static SkfAtPoint make(const BearingSpec& b, double Fr, double Fa, double omega);
    // Same with the bearing's geometry powers computed beforehand (g.matches(b)).
    static SkfAtPoint make(const BearingSpec& b, const SkfGeometry& g, double Fr, double Fa, double omega);
    // The kinematic viscosity in cSt (= mm^2/s, the catalogue unit) and its powers ^0.6, ^0.64,
    // ^1.4, ^1.379, shared by every bearing at one temperature (from losses::Evaluation::ln_nu_cSt);
    // returns M [N*m]. Past nu_rs_limit the rolling term is evaluated at nu_rs_limit.
    double moment(double nu_cSt, double nu_cSt_06, double nu_cSt_064, double nu_cSt_14, double nu_cSt_1379) const;
    // What is out of the model's range at this point ("contact angle", "rolling moment", ...),
    // or nullptr: the contact angle at or past 90 deg, or a term that is not a finite number.
    const char* fault() const;
};

}  // namespace gearloss::bearings
