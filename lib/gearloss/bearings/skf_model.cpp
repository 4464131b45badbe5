// SKF (2004/2013) rolling-bearing friction: load terms, moments and oil-bath drag, evaluated in the
// catalogue's units behind the SI interface of skf_model.hpp.
#include "gearloss/bearings/skf_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace gearloss::bearings {
namespace {

// The SKF correlations are empirical and dimensional (e.g. M_rr = G_rr (nu n)^0.6 with
// G_rr ~ d_m^1.96): they were fitted with lengths in mm, speed in r/min, kinematic viscosity
// in mm^2/s and moments in N*mm, and are evaluated in those units. These are the bearing
// model's only unit conversions: the inputs on entry (Catalogue::of), the moments on exit.
constexpr double kMmPerM = 1e3;
constexpr double kRpmPerRadS = 30.0 / std::numbers::pi;
constexpr double kCStPerM2s = 1e6;  // mm^2/s per m^2/s
constexpr double kNmPerNmm = 1e-3;

// A bearing and its speed in the catalogue's units.
struct Catalogue {
    double n = 0;                     // r/min, magnitude
    double d = 0, D = 0, B = 0, dm = 0;  // mm
    double seal_ds = 0;               // seal counterface diameter, mm
    std::optional<double> H;          // oil-bath level, mm

    static Catalogue of(const BearingSpec& b, double omega) {
        Catalogue c;
        c.n = std::abs(omega) * kRpmPerRadS;
        c.d = b.d * kMmPerM;
        c.D = b.D * kMmPerM;
        c.B = b.B * kMmPerM;
        c.dm = 0.5 * (c.d + c.D);
        c.seal_ds = b.seal_ds ? *b.seal_ds * kMmPerM : c.d + 0.2 * (c.D - c.d);  // inner-ring shoulder estimate
        if (b.bath_H) c.H = *b.bath_H * kMmPerM;
        return c;
    }
};

// The exponents of d_m in the load functions G_rr, G_sl of SKF (2004) Table 2a, per bearing type,
// in the order load_terms uses them (SkfGeometry::power slots 0-3; slot 4 is the seal's
// d_s^beta, slot 5 the drag's d_m^4 or d_m^5).
constexpr std::array<std::array<double, 4>, 8> kDmExponents = {{
    {1.96, -0.26, -0.145, 1.5},  // deep groove ball (radial load only: the first two)
    {4, 1.97, 0.26, 0},          // angular contact ball, double row, four-point contact
    {3.5, 2.0, -0.12, 0},        // self-aligning ball
    {2.41, 0.9, 0, 0},           // cylindrical roller, full complement, needle roller
    {2.38, 0.82, 0, 0},          // tapered roller
    {1.85, 2.3, 0.25, 0.94},     // spherical roller
    {1.83, 0.05, 0, 0},          // thrust ball
    {2.38, 0.62, 0, 0},          // cylindrical roller thrust
}};
size_t exponent_row(BearingType t) {
    switch (t) {
        case BearingType::deep_groove_ball: return 0;
        case BearingType::angular_contact_ball:
        case BearingType::angular_contact_ball_double:
        case BearingType::four_point_contact: return 1;
        case BearingType::self_aligning_ball: return 2;
        case BearingType::cylindrical_roller:
        case BearingType::cylindrical_roller_full:
        case BearingType::needle_roller: return 3;
        case BearingType::tapered_roller: return 4;
        case BearingType::spherical_roller: return 5;
        case BearingType::thrust_ball: return 6;
        case BearingType::cylindrical_roller_thrust: return 7;
    }
    return 0;
}

SkfLoadTerms load_terms(const BearingSpec& b, const Catalogue& c, const SkfGeometry& geo, double Fr, double Fa) {
    using std::pow;
    const auto& w = geo.power;  // the powers of d_m, in the order of kDmExponents[type]
    const SkfConstants& k = b.k;
    const double dm = c.dm, n = c.n;
    Fr = std::abs(Fr);
    Fa = std::abs(Fa);
    SkfLoadTerms g;
    switch (b.type) {
        case BearingType::deep_groove_ball:
            if (Fa <= 0.0) {
                g.G_rr = k.R1 * w[0] * pow(Fr, 0.54);
                g.G_sl = k.S1 * w[1] * pow(Fr, 5.0 / 3.0);
            } else {
                // alpha_F = 24.6 (F_a/C0)^0.24 degrees
                const double aF = 24.6 * pow(Fa / b.C0, 0.24) * std::numbers::pi / 180.0;
                g.alpha_F = aF;
                const double sa = std::sin(aF);
                g.G_rr = k.R1 * w[0] * pow(Fr + k.R2 * Fa / sa, 0.54);
                g.G_sl = k.S1 * w[2] * pow(pow(Fr, 5) + k.S2 * w[3] * pow(Fa, 4) / sa, 1.0 / 3.0);
            }
            break;
        case BearingType::angular_contact_ball:
        case BearingType::angular_contact_ball_double:
        case BearingType::four_point_contact:
        case BearingType::self_aligning_ball: {  // same form; their exponents differ (kDmExponents)
            const double Fg_r = k.R3 * w[0] * n * n;
            const double Fg_s = k.S3 * w[0] * n * n;
            g.G_rr = k.R1 * w[1] * pow(Fr + Fg_r + k.R2 * Fa, 0.54);
            g.G_sl = k.S1 * w[2] * (pow(Fr + Fg_s, 4.0 / 3.0) + k.S2 * pow(Fa, 4.0 / 3.0));
            break;
        }
        case BearingType::cylindrical_roller:
        case BearingType::cylindrical_roller_full:
        case BearingType::needle_roller:
            g.G_rr = k.R1 * w[0] * pow(Fr, 0.31);
            g.G_sl = k.S1 * w[1] * Fa + k.S2 * dm * Fr;
            break;
        case BearingType::tapered_roller:
            g.G_rr = k.R1 * w[0] * pow(Fr + k.R2 * b.Y * Fa, 0.31);
            g.G_sl = k.S1 * w[1] * (Fr + k.S2 * b.Y * Fa);
            break;
        case BearingType::spherical_roller: {
            const double rr_e = k.R1 * w[0] * pow(Fr + k.R2 * Fa, 0.54);
            const double rr_l = k.R3 * w[1] * pow(Fr + k.R4 * Fa, 0.31);
            if (rr_e < rr_l) {
                g.G_rr = rr_e;
                g.G_sl = k.S1 * w[2] * pow(pow(Fr, 4) + k.S2 * pow(Fa, 4), 1.0 / 3.0);
            } else {
                g.G_rr = rr_l;
                g.G_sl = k.S3 * w[3] * pow(pow(Fr, 3) + k.S4 * pow(Fa, 3), 1.0 / 3.0);
            }
            break;
        }
        case BearingType::thrust_ball:
            g.G_rr = k.R1 * w[0] * pow(Fa, 0.54);
            g.G_sl = k.S1 * w[1] * pow(Fa, 4.0 / 3.0);
            break;
        case BearingType::cylindrical_roller_thrust:
            g.G_rr = k.R1 * w[0] * pow(Fa, 0.31);
            g.G_sl = k.S1 * w[1] * Fa;
            break;
    }
    return g;
}

// Split of the SKF (2013) drag form into the nu-independent first term and the
// coefficient of nu^1.379 in the second.
void drag_terms(const BearingSpec& b, const Catalogue& c, const SkfGeometry& geo, double& first, double& second_coef) {
    first = second_coef = 0.0;
    const double n = c.n;
    if (!c.H || n <= 0.0) return;
    const double dm = c.dm;
    const double H = std::clamp(*c.H, 0.0, 1.2 * dm);
    if (H <= 0.0) return;
    const double t = 2.0 * std::acos((0.6 * dm - H) / (0.6 * dm));
    const double ft = t <= std::numbers::pi ? std::sin(0.5 * t) : 1.0;
    const double fA = 0.05 * b.k.K_Z * (c.D + c.d) / (c.D - c.d);
    const double Rs = 0.36 * dm * dm * (t - std::sin(t)) * fA;
    if (is_roller(b.type)) {
        const double K_roll = b.k.K_L * b.k.K_Z * (c.d + c.D) / (c.D - c.d) * 1e-12;
        const double lD = 5.0 * b.k.K_L * c.B / dm;
        const double Cw = 2.789e-10 * lD * lD * lD - 2.786e-4 * lD * lD + 0.0195 * lD + 0.6439;
        first = 4.0 * b.bath_VM * K_roll * Cw * c.B * geo.power[5] * n * n;  // d_m^4
    } else {
        const double K_ball = b.k.rows * b.k.K_Z * (c.d + c.D) / (c.D - c.d) * 1e-12;
        first = 0.4 * b.bath_VM * K_ball * geo.power[5] * n * n;  // d_m^5
    }
    // 1.093e-7 n^2 d_m^3 (n d_m^2 f_t / nu)^-1.379 R_s
    second_coef = 1.093e-7 * n * n * dm * dm * dm * std::pow(n * dm * dm * ft, -1.379) * Rs;
}

// SKF (2004) replenishment/starvation: phi_rs = exp(-K_rs nu n (d+D) sqrt(K_Z / (2 (D-d)))), the
// coefficient of nu (catalogue units) returned here; 0 where the bearing runs flooded (phi_rs = 1).
double starvation_coefficient(const BearingSpec& b, const Catalogue& c) {
    if (!b.starvation_applies()) return 0.0;
    return b.K_rs * c.n * (c.d + c.D) * std::sqrt(b.k.K_Z / (2.0 * (c.D - c.d)));
}

// The starvation limit [cSt]: the viscosity at which the starved rolling moment
// phi_ish phi_rs G_rr (nu n)^0.6 is largest at this speed. d ln M_rr / d ln nu
// = 0.6 - 0.64 s - a_rs nu with s = a_ish nu^0.64 / (1 + a_ish nu^0.64) (from SKF (2004) phi_ish and
// phi_rs) falls from 0.6 at nu -> 0 to -0.64 s at a_rs nu = 0.6: one root, found by bisection on
// ln nu. Past it SKF's exponential would make the loss fall as the oil thickens; holding the
// moment at its maximum over nu also keeps it rising with speed (d/dn of a maximum over nu is
// the partial derivative at the maximum, (1.6 - 1.28 s - a_rs nu) M_rr / n > 0 there).
double starvation_limit(double a_rs, double a_ish) {
    if (!(a_rs > 0.0)) return std::numeric_limits<double>::infinity();
    const auto slope = [&](double nu) {
        const double x = a_ish * std::pow(nu, 0.64);
        return 0.6 - 0.64 * x / (1.0 + x) - a_rs * nu;
    };
    double hi = 0.6 / a_rs;  // slope <= 0
    double lo = 0.5 * hi;
    while (!(slope(lo) > 0.0) && lo > 1e-12 * hi) lo *= 0.5;  // slope -> 0.6 as nu -> 0
    for (int i = 0; i < 48; ++i) {
        const double mid = std::sqrt(lo * hi);
        (slope(mid) > 0.0 ? lo : hi) = mid;
    }
    return std::sqrt(lo * hi);
}
}  // namespace

double skf_starvation_limit_nu(const BearingSpec& b, double omega) {
    const SkfAtPoint p = SkfAtPoint::make(b, 0.0, 0.0, omega);
    return p.nu_rs_limit / kCStPerM2s;
}

namespace {
// The rolling moment phi_ish phi_rs G_rr (nu n)^0.6 [N*mm] given the shared powers of nu; past
// the starvation limit, the same at the limit viscosity (powers computed here, only then).
double rolling_moment(const SkfAtPoint& p, double nu, double nu06, double nu064, double* phi_ish,
                      double* phi_rs, bool* held) {
    if (nu > p.nu_rs_limit) {
        nu = p.nu_rs_limit;
        nu06 = std::pow(nu, 0.6);
        nu064 = std::pow(nu, 0.64);
        if (held) *held = true;
    }
    const double ish = 1.0 / (1.0 + p.a_ish * nu064);  // SKF (2004) inlet shear heating
    const double rs = std::exp(-p.a_rs * nu);           // SKF (2004) replenishment/starvation
    if (phi_ish) *phi_ish = ish;
    if (phi_rs) *phi_rs = rs;
    return ish * rs * p.rr * nu06;
}
}  // namespace

SkfLoadTerms skf_load_terms(const BearingSpec& b, double Fr, double Fa, double omega) {
    return load_terms(b, Catalogue::of(b, omega), SkfGeometry::of(b), Fr, Fa);
}

double skf_drag_moment(const BearingSpec& b, double omega, double nu_m2s) {
    double first, coef;
    drag_terms(b, Catalogue::of(b, omega), SkfGeometry::of(b), first, coef);
    return (first + coef * std::pow(nu_m2s * kCStPerM2s, 1.379)) * kNmPerNmm;
}

double palmgren_drag_coef(const BearingSpec& b, double f0, double omega, double exponent) {
    const Catalogue c = Catalogue::of(b, omega);
    const double nr = c.n, dm = c.dm;
    const double speed = exponent == 2.0 / 3.0 ? std::cbrt(nr * nr)
                                                : std::cbrt(2000.0 * 2000.0) * std::pow(nr / 2000.0, exponent);
    return 1e-7 * f0 * speed * dm * dm * dm * kNmPerNmm * std::abs(omega);
}

SkfGeometry SkfGeometry::of(const BearingSpec& b) {
    const Catalogue c = Catalogue::of(b, 0.0);
    SkfGeometry g;
    const auto& e = kDmExponents[exponent_row(b.type)];
    for (size_t i = 0; i < e.size(); ++i) g.power[i] = std::pow(c.dm, e[i]);
    g.power[4] = std::pow(c.seal_ds, b.seal_beta);
    g.power[5] = std::pow(c.dm, is_roller(b.type) ? 4 : 5);
    g.made = true;
    g.type = b.type;
    g.d = b.d;
    g.D = b.D;
    g.seal_beta = b.seal_beta;
    g.seal_ds = b.seal_ds.value_or(-1.0);
    return g;
}

SkfAtPoint SkfAtPoint::make(const BearingSpec& b, double Fr, double Fa, double omega) {
    return make(b, SkfGeometry::of(b), Fr, Fa, omega);
}

SkfAtPoint SkfAtPoint::make(const BearingSpec& b, const SkfGeometry& geo, double Fr, double Fa, double omega) {
    const Catalogue c = Catalogue::of(b, omega);
    SkfAtPoint p;
    p.n = c.n;
    const SkfLoadTerms g = load_terms(b, c, geo, Fr, Fa);
    const double dm = c.dm;
    p.rr = g.G_rr * std::pow(p.n, 0.6);
    p.a_ish = 1.84e-9 * std::pow(p.n * dm, 1.28);
    p.a_rs = starvation_coefficient(b, c);
    p.nu_rs_limit = starvation_limit(p.a_rs, p.a_ish);
    p.a_bl = 2.6e-8 * std::pow(p.n, 1.4) * dm;
    p.G_sl = g.G_sl;
    p.alpha_F = g.alpha_F;
    p.mu_bl = b.mu_bl;
    p.mu_ehl = b.mu_ehl;
    p.M_seal = (b.seal_KS1 > 0 || b.seal_KS2 > 0) && p.n > 0
                   ? b.seal_KS1 * geo.power[4] + b.seal_KS2  // K_S1 d_s^beta + K_S2
                   : 0.0;
    drag_terms(b, c, geo, p.drag_a, p.drag_b);
    return p;
}

double SkfAtPoint::moment(double nu_cSt, double nu_cSt_06, double nu_cSt_064, double nu_cSt_14,
                          double nu_cSt_1379) const {
    if (n <= 0.0) return 0.0;
    const double M_rr = rolling_moment(*this, nu_cSt, nu_cSt_06, nu_cSt_064, nullptr, nullptr, nullptr);
    const double phi_bl = std::exp(-a_bl * nu_cSt_14);
    const double mu_sl = phi_bl * mu_bl + (1.0 - phi_bl) * mu_ehl;
    return (M_rr + G_sl * mu_sl + M_seal + drag_a + drag_b * nu_cSt_1379) * kNmPerNmm;
}

const char* SkfAtPoint::fault() const {
    // Once per bearing and point: one test of the sum (a NaN or infinity in any term makes it
    // non-finite), the term named only when it fails.
    if (alpha_F < 0.5 * std::numbers::pi &&
        std::isfinite(n + rr + a_ish + a_rs + G_sl + a_bl + mu_bl + mu_ehl + M_seal + drag_a + drag_b))
        return nullptr;
    if (!(alpha_F < 0.5 * std::numbers::pi)) return "contact angle";  // also NaN
    if (!std::isfinite(n)) return "speed";
    if (!std::isfinite(rr) || !std::isfinite(a_ish) || !std::isfinite(a_rs)) return "rolling moment";
    if (!std::isfinite(G_sl) || !std::isfinite(a_bl) || !std::isfinite(mu_bl) || !std::isfinite(mu_ehl))
        return "sliding moment";
    if (!std::isfinite(M_seal)) return "seal moment";
    if (!std::isfinite(drag_a) || !std::isfinite(drag_b)) return "drag moment";
    return nullptr;
}

SkfMoment skf_moment(const BearingSpec& b, double Fr, double Fa, double omega, double nu_m2s) {
    const SkfAtPoint p = SkfAtPoint::make(b, Fr, Fa, omega);
    SkfMoment m;
    if (p.n <= 0.0) return m;
    const double nu = nu_m2s * kCStPerM2s;
    m.rolling = rolling_moment(p, nu, std::pow(nu, 0.6), std::pow(nu, 0.64), &m.phi_ish, &m.phi_rs,
                               &m.starvation_held) * kNmPerNmm;
    m.phi_bl = std::exp(-p.a_bl * std::pow(nu, 1.4));
    m.sliding = p.G_sl * (m.phi_bl * p.mu_bl + (1.0 - m.phi_bl) * p.mu_ehl) * kNmPerNmm;
    m.seal = p.M_seal * kNmPerNmm;
    m.drag = (p.drag_a + p.drag_b * std::pow(nu, 1.379)) * kNmPerNmm;
    return m;
}

}  // namespace gearloss::bearings
