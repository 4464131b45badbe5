#include "gearloss/mesh/viscoelastic.hpp"

#include <algorithm>
#include <cmath>

namespace gearloss::mesh {

namespace {
// The constants of one slice's exact solution (Johnson & Tevaarwerk 1977): with
// z = exp(tau/tau_E) and S = eta gamma_dot / tau_E, u_e d tau/dx = G [gamma_dot - (tau_E/eta)
// sinh(tau/tau_E)] separates into partial fractions over the roots z+- = S +- sqrt(S^2 + 1)
// (z+ z- = -1), and phi = (z+ - z)/(z - z-) decays as exp(-G sqrt(S^2 + 1) x / (u_e eta)).
struct SliceSolution {
    double z_plus, z_minus, decay, one_minus_decay, rate;
    SliceSolution(double dx, double gamma_dot, double u_e, double eta, double G, double tau_E) {
        // S capped so that an overflowing in-contact viscosity (eta -> inf: purely elastic)
        // keeps the roots finite; the rate written with sqrt(S^2 + 1)/eta = hypot(gamma_dot/tau_E, 1/eta).
        const double S = std::min(eta * gamma_dot / tau_E, 1e300);
        z_plus = S + unit_hypot(S);
        z_minus = -1.0 / z_plus;
        const double a = gamma_dot / tau_E, b = 1.0 / eta, hi = std::max(a, b), lo = std::min(a, b);
        rate = G * dx / u_e * (hi > 0 ? hi * unit_hypot(lo / hi) : 0.0);  // relaxation lengths in the slice
        // (Past kNoDecay the exponential is 0 in double: said so, without the library's underflow path.)
        constexpr double kNoDecay = 745.2;
        decay = rate > kNoDecay ? 0.0 : std::exp(-rate);
        one_minus_decay = rate > kNoDecay ? 1.0 : -std::expm1(-rate);
    }
    // The slice twice as long, from this one's constants: the decay squares, and
    // 1 - exp(-2 r) = (1 - exp(-r)) (1 + exp(-r)) keeps its digits.
    SliceSolution doubled() const {
        SliceSolution d = *this;
        d.rate = 2.0 * rate;
        d.decay = decay * decay;
        d.one_minus_decay = one_minus_decay * (1.0 + decay);
        return d;
    }
    // sqrt(x^2 + 1) for x >= 0 without overflow (the hot loop of the EHL path: the library's
    // hypot takes twice as long); beyond 1e150 the 1 is below the last digit.
    static double unit_hypot(double x) { return x < 1e150 ? std::sqrt(std::fma(x, x, 1.0)) : x; }
    // Stress after the slice from tau0 (z0 = exp(tau0/tau_E)). For a nearly elastic slice
    // (decay -> 1) the change of z is small against z: the form
    // z - z0 = (z+ - z0)(z0 - z-)(1 - decay) / ((z0 - z-) + (z+ - z0) decay) keeps its digits.
    double step(double tau0, double z0, double tau_E) const { return step_z(tau0, z0, tau_E, nullptr); }
    // The same, giving z after the slice too: z0 + dz, which is exp(tau/tau_E) without an exp.
    double step_z(double tau0, double z0, double tau_E, double* z) const {
        // (written divided by z0 - z- >= 1 so that no product overflows for huge S or z0)
        const double ahead = z_plus - z0;
        const double dz = ahead * one_minus_decay / (1.0 + ahead * decay / (z0 - z_minus));
        if (z) *z = z0 + dz;
        return tau0 + tau_E * std::log1p(dz / z0);
    }
};
double z_of(double tau, double tau_E) { return std::exp(std::clamp(tau / tau_E, -700.0, 700.0)); }
}  // namespace

double maxwell_eyring_step(double tau0, double dx, double gamma_dot, double u_e, double eta, double G, double tau_E) {
    return SliceSolution(dx, gamma_dot, u_e, eta, G, tau_E).step(tau0, z_of(tau0, tau_E), tau_E);
}

double maxwell_eyring_mean_stress(std::span<const MaxwellCell> cells, double gamma_dot, double u_e, double tau_E) {
    if (!(gamma_dot > 0) || !(u_e > 0)) return 0.0;
    // z = exp(tau/tau_E) is carried with tau from step to step (z0 + dz): an exp only where
    // the limiting stress caps tau.
    double tau = 0, z = 1, integral = 0, width = 0;
    for (const MaxwellCell& c : cells) {
        if (!(c.dx > 0)) continue;
        const auto capped = [&](double t, double& zt) {
            if (t > c.tau_L) t = c.tau_L, zt = z_of(t, tau_E);
            return t;
        };
        double z0 = z;
        const double t0 = capped(tau, z0);
        const SliceSolution half(0.5 * c.dx, gamma_dot, u_e, c.eta, c.G, tau_E);
        double z_end = 0, t_end = 0;
        const double kappa = 2.0 * half.rate;  // the slice in relaxation lengths u_e eta / (G sqrt(S^2 + 1))
        if (kappa > 2.0) {
            // Stiff slice (viscous, De of the slice < 1/2): the stress relaxes to the Eyring
            // value tau_inf = tau_E asinh(S) (capped) within a fraction 1/kappa of the slice, as
            // tau_inf + (t0 - tau_inf) exp(-kappa x/dx) near it (rate linearised about tau_inf,
            // where d/dtau of sinh(tau/tau_E) is sqrt(S^2 + 1)/tau_E): the mean of that. The end
            // in one exact step over the slice: the stress moves monotonically from t0 towards the
            // root, so an end past tau_L means it rose through the cap and stays there.
            const SliceSolution whole = half.doubled();
            t_end = capped(whole.step_z(t0, z0, tau_E, &z_end), z_end);
            const double tau_inf = std::min(tau_E * std::log(half.z_plus), c.tau_L);
            integral += c.dx * (tau_inf + (t0 - tau_inf) * whole.one_minus_decay / kappa);
        } else {
            // Two half steps (to the middle, to the end), each capped; Simpson: smooth over the slice.
            double z_mid = 0;
            const double t_mid = capped(half.step_z(t0, z0, tau_E, &z_mid), z_mid);
            t_end = capped(half.step_z(t_mid, z_mid, tau_E, &z_end), z_end);
            integral += c.dx * (t0 + 4.0 * t_mid + t_end) / 6.0;
        }
        width += c.dx;
        tau = t_end;
        z = z_end;
    }
    return width > 0 ? integral / width : 0.0;
}

double shear_modulus(const lubricant::TractionProperties& rh, double p, double T) {
    return (rh.shear_modulus_0 + rh.shear_modulus_slope * p) *
           std::exp(-rh.shear_modulus_beta * (T - rh.shear_modulus_T_ref));
}

}  // namespace gearloss::mesh
