#pragma once
// Churning of a gear dipping in the sump: Changenet & Velex (2007),
// J. Mech. Des. 129(1) 128-133 (drag coefficient C_m of both Reynolds regimes),
// made monotone in the oil's viscosity by a running minimum over Re_c (see
// ChurningAtSpeed and docs/config.md, "Churning").

namespace gearloss::churning {

// `capped` (appended last: the detail stores the regime as a number): beyond the minimum
// of the published curve over Re_c, where the torque is held at that minimum.
enum class Regime { none, low_reynolds, transition, high_reynolds, capped };
const char* to_string(Regime r);

struct DippingGear {
    double Rp = 0;          // pitch radius [m]
    double b = 0;           // face width [m]
    int z = 0;              // teeth
    double tooth_height = 0;// [m]
    double alpha = 0;       // pressure angle used for the flank term [rad]
    double h = 0;           // immersion depth below the oil level [m]
};

// Wetted surface S_m of the immersed part (periphery, two side faces, flanks).
double submerged_surface(const DippingGear& g);

// Critical Reynolds number Re_c = Omega Rp b / nu (seed 000, the symbol list of its eqs. 15-17).
double critical_reynolds(double omega, double Rp, double b, double nu);

// Dimensionless churning torque C_m of the default form (the running minimum over Re_c
// of the published curve, see ChurningAtSpeed).
double dimensionless_torque(const DippingGear& g, double omega, double nu, double V0, Regime* regime = nullptr);

// Churning torque C_ch = 1/2 rho Omega^2 S_m Rp^3 C_m [N m] of the default form (sign of
// omega ignored).
double churning_torque(const DippingGear& g, double omega, double rho, double nu, double V0,
                       Regime* regime = nullptr);

// The published curve as it stands: Re_c < 6000 low-Re formula, Re_c > 9000 high-Re
// formula, linear interpolation on Re_c between (as seed 000 applies it). Where the
// high-Re value exceeds the low-Re one this curve rises as the oil warms.
double published_torque(const DippingGear& g, double omega, double rho, double nu, double V0,
                        Regime* regime = nullptr);

// Precomputed form for repeated evaluation at one speed: the terms that do not
// depend on the oil are folded once, leaving nu^-0.21 and rho to the caller.
//
// At a fixed speed the published C_m is a function of Re_c alone (Re = Re_c Rp / b).
// The low-Re formula falls as the oil warms (C_m ~ nu^0.21), the high-Re formula does
// not depend on nu; where the high-Re value at the transition exceeds the low-Re one, the
// linear band between them rises with Re_c, so churning would grow as the same oil warms
// at the same level and speed -- by up to several times, an artefact of two fits meeting,
// not a measured effect (Changenet & Velex 2007 fitted each regime on its own data). The
// torque used is therefore the running minimum over Re_c' <= Re_c of the published curve:
// continuous, never rising with temperature, and equal to the published form wherever
// the published curve itself falls. The band blend g(Re_c) is strictly convex in Re_c
// (g'' = 0.21 a Re_c^-2.21 [2 Re_c/3000 + 1.21 (1 - f)] > 0 for a = coef_low (Omega Rp b)^0.21),
// so the running minimum is g up to its minimiser Re_c* and g(Re_c*) after it: two numbers
// per gear and speed, found once here, leave the hot path one comparison.
struct ChurningAtSpeed {
    double omega = 0;
    double coef_low = 0;   // C_ch / (rho * nu^0.21) in the low-Re regime
    double coef_high = 0;  // C_ch / rho in the high-Re regime
    double ReC_times_nu = 0;
    double ReC_cap = 0;    // Re_c beyond which the torque is capped (+inf: never)
    double coef_cap = 0;   // C_ch / rho when capped
    static ChurningAtSpeed make(const DippingGear& g, double omega, double V0);
    // The default form (running minimum over Re_c).
    double torque(double rho, double nu, double nu_pow_021, Regime* regime = nullptr) const;
    // The published curve (no minimum).
    double published(double rho, double nu, double nu_pow_021, Regime* regime = nullptr) const;
    bool capped_somewhere() const { return ReC_cap < 9000.0; }
    // High-Re over low-Re torque at the onset of the transition (Re_c = 6000); > 1 where
    // the published curve rises across the band.
    double transition_excess() const;
};

// Where the running minimum departs from the published curve, for one gear: both forms
// are power laws of Omega, so is the ratio of the high-Re to the low-Re torque at Re_c = 6000
// (~ Omega^-0.56); the torque is capped somewhere along Re_c at the speeds where that ratio
// exceeds (6000/9000)^0.21, i.e. below `below_omega` [rad/s] (0: at no speed).
struct TransitionCap {
    double below_omega = 0;
    double excess_at_reference = 0;  // the ratio at omega_reference
};
TransitionCap transition_cap(const DippingGear& g, double V0, double omega_reference);

}  // namespace gearloss::churning
