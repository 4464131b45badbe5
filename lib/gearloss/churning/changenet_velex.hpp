#pragma once
// Churning of a gear dipping in the sump: Changenet & Velex (2007),
// J. Mech. Des. 129(1) 128-133 (drag coefficient C_m of both Reynolds regimes).

namespace gearloss::churning {

enum class Regime { none, low_reynolds, transition, high_reynolds };
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

// Dimensionless churning torque C_m: Re_c < 6000 laminar-like formula,
// Re_c > 9000 turbulent-like formula, linear interpolation on Re_c between.
double dimensionless_torque(const DippingGear& g, double omega, double nu, double V0, Regime* regime = nullptr);

// Churning torque C_ch = 1/2 rho Omega^2 S_m Rp^3 C_m [N m] (sign of omega ignored).
double churning_torque(const DippingGear& g, double omega, double rho, double nu, double V0,
                       Regime* regime = nullptr);

// Precomputed form for repeated evaluation at one speed: the terms that do not
// depend on the oil are folded once, leaving nu^-0.21 and rho to the caller.
struct ChurningAtSpeed {
    double omega = 0;
    double coef_low = 0;   // C_ch / (rho * nu^0.21) in the low-Re regime
    double coef_high = 0;  // C_ch / rho in the high-Re regime
    double ReC_times_nu = 0;
    static ChurningAtSpeed make(const DippingGear& g, double omega, double V0);
    double torque(double rho, double nu, double nu_pow_021, Regime* regime = nullptr) const;
};

}  // namespace gearloss::churning
