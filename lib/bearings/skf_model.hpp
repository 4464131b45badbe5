#pragma once
// SKF (2004) rolling-bearing frictional moment (the catalogue's total-moment equation):
//   M = phi_ish phi_rs M_rr + M_sl + M_seal + M_drag
// Units of the source: d, D, B, d_m in mm; n in r/min; nu in mm^2/s; loads N; M in N*mm.
#include <optional>

#include "bearings/skf_constants.hpp"

namespace gearloss::bearings {

struct BearingSpec {
    BearingType type = BearingType::deep_groove_ball;
    double d = 0, D = 0, B = 0;   // mm
    double C0 = 0;                // static load rating, N (deep groove ball: needed for axial load)
    double Y = 1.6;               // tapered roller axial factor (product table)
    SkfConstants k;
    double K_rs = 3e-8;           // replenishment/starvation constant (low-level oil bath, splash)
    double mu_bl = 0.15;
    double mu_ehl = 0.05;
    // Integral contact seals (both sides): M_seal = K_S1 d_s^beta + K_S2.
    double seal_KS1 = 0, seal_KS2 = 0, seal_beta = 2.0, seal_ds = 0;
    // Oil bath drag: oil level H above the lowest point of the outer-ring raceway [mm]
    // and the drag factor V_M read from the SKF diagram for H/d_m.
    std::optional<double> bath_H;
    double bath_VM = 0;

    double dm() const { return 0.5 * (d + D); }
};

struct SkfLoadTerms {
    double G_rr = 0, G_sl = 0;
    // Deep groove ball under axial load: the contact angle alpha_F [rad] of SKF's formula
    // (0 otherwise). Past 90 deg the formula has left its range (F_a far above C0).
    double alpha_F = 0;
};

// Load/geometry functions G_rr, G_sl (SKF Table 2a). Fr, Fa in N, n in r/min
// (speed enters only through the centrifugal F_g of angular-contact types).
SkfLoadTerms skf_load_terms(const BearingSpec& b, double Fr, double Fa, double n_rpm);

struct SkfMoment {
    double rolling = 0, sliding = 0, seal = 0, drag = 0;  // N*mm
    double phi_ish = 1, phi_rs = 1, phi_bl = 1;
    double total() const { return rolling + sliding + seal + drag; }
};

// Full evaluation (used by `point` and the tests).
SkfMoment skf_moment(const BearingSpec& b, double Fr, double Fa, double n_rpm, double nu_mm2s);

// Oil-bath drag moment [N*mm] (2013 catalogue form).
double skf_drag_moment(const BearingSpec& b, double n_rpm, double nu_mm2s);

// Terms folded once per operating point so that each temperature costs a few
// exponentials; the caller supplies the shared powers of nu.
struct SkfAtPoint {
    double n = 0;            // r/min, magnitude
    double rr = 0;           // G_rr n^0.6
    double a_ish = 0;        // 1.84e-9 (n d_m)^1.28
    double a_rs = 0;         // K_rs n (d+D) sqrt(K_Z / (2 (D-d)))
    double a_bl = 0;         // 2.6e-8 n^1.4 d_m
    double G_sl = 0, mu_bl = 0, mu_ehl = 0;
    double M_seal = 0;
    double drag_a = 0;       // drag first term (independent of nu)
    double drag_b = 0;       // drag second term / nu^1.379
    double alpha_F = 0;      // contact angle of a deep groove ball bearing under axial load [rad]
    static SkfAtPoint make(const BearingSpec& b, double Fr, double Fa, double n_rpm);
    // nu^0.6, nu^0.64, nu^1.4, nu^1.379 passed in; returns M [N*mm].
    double moment(double nu, double nu06, double nu064, double nu14, double nu1379) const;
    // What is out of the model's range at this point ("contact angle", "rolling moment", ...),
    // or nullptr: the contact angle at or past 90 deg, or a term that is not a finite number.
    const char* fault() const;
};

}  // namespace gearloss::bearings
