#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gearloss/bearings/skf_model.hpp"
#include "gearloss/churning/changenet_velex.hpp"
#include "gearloss/seals/radial_lip_seal.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

namespace {
// The SKF reference values are in the catalogue's units; the bearing model takes SI.
constexpr double mm = 1e-3;                      // m
constexpr double rpm = std::numbers::pi / 30.0;  // rad/s
constexpr double cSt = 1e-6;                     // m^2/s
constexpr double Nmm = 1e-3;                     // N*m

bearings::BearingSpec dgbb_6205() {
    bearings::BearingSpec b;
    b.type = bearings::BearingType::deep_groove_ball;
    b.d = 25 * mm;
    b.D = 52 * mm;
    b.B = 15 * mm;
    b.C0 = 7800;
    b.k = *bearings::skf_constants(b.type, "62");
    b.K_rs = 3e-8;
    b.mu_bl = 0.15;
    b.mu_ehl = 0.05;  // mineral oil
    return b;
}
}  // namespace

TEST_CASE("SKF model: 6205 worked values of the reference", "[bearings]") {
    // Hand calculation with the SKF (2004) equations: n 3000, nu 20, Fr 1000 N, Fa 0, K_rs 3e-8, mineral:
    // G_rr 0.02082, G_sl 125.02, phi_ish 0.9636, phi_rs 0.9673, M_rr 15.33, phi_bl 0.00748, M_sl 6.34, M 20.63 N mm.
    const auto b = dgbb_6205();
    const auto g = bearings::skf_load_terms(b, 1000, 0, 3000 * rpm);
    CHECK(g.G_rr == Approx(0.02082).epsilon(1e-3));  // catalogue units (M_rr in N mm)
    CHECK(g.G_sl == Approx(125.02).epsilon(1e-3));
    const auto m = bearings::skf_moment(b, 1000, 0, 3000 * rpm, 20 * cSt);
    CHECK(m.phi_ish == Approx(0.9636).epsilon(1e-3));
    CHECK(m.phi_rs == Approx(0.9673).epsilon(1e-3));
    CHECK(m.phi_bl == Approx(0.00748).epsilon(5e-3));
    CHECK(m.rolling / (m.phi_ish * m.phi_rs) == Approx(15.33 * Nmm).epsilon(1e-3));
    CHECK(m.sliding == Approx(6.34 * Nmm).epsilon(2e-3));
    CHECK(m.total() == Approx(20.63 * Nmm).epsilon(1e-3));
    // With an axial load of 500 N: M = 48.17 N mm.
    CHECK(bearings::skf_moment(b, 1000, 500, 3000 * rpm, 20 * cSt).total() == Approx(48.17 * Nmm).epsilon(1e-3));
}

TEST_CASE("SKF model: tapered roller 302 worked value", "[bearings]") {
    // Same size, Y 1.6, Fr 2000 N, Fa 500 N, n 3000, nu 20 -> M = 129.4 N mm.
    bearings::BearingSpec b;
    b.type = bearings::BearingType::tapered_roller;
    b.d = 25 * mm;
    b.D = 52 * mm;
    b.Y = 1.6;
    b.k = *bearings::skf_constants(b.type, "302");
    b.K_rs = 3e-8;
    b.mu_bl = 0.15;
    b.mu_ehl = 0.002;
    CHECK(bearings::skf_moment(b, 2000, 500, 3000 * rpm, 20 * cSt).total() == Approx(129.4 * Nmm).epsilon(1e-3));
}

TEST_CASE("SKF drag terms for the 6205 half submerged", "[bearings]") {
    // Reference: H = 0.5 d_m -> second term 1.42 N mm, first term = V_M * 2692 N mm.
    auto b = dgbb_6205();
    b.bath_H = 0.5 * b.dm();
    b.bath_VM = 0.0;
    CHECK(bearings::skf_drag_moment(b, 3000 * rpm, 20 * cSt) == Approx(1.42 * Nmm).epsilon(5e-3));
    b.bath_VM = 1e-3;
    CHECK(bearings::skf_drag_moment(b, 3000 * rpm, 20 * cSt) == Approx((1.42 + 2.692) * Nmm).epsilon(5e-3));
}

TEST_CASE("SKF precomputed form equals the direct evaluation", "[bearings]") {
    const auto b = dgbb_6205();
    const auto p = bearings::SkfAtPoint::make(b, 1000, 300, 2500 * rpm);
    const double nu = 35;  // cSt: the folded form takes the powers of nu in cSt
    const double fast = p.moment(nu, std::pow(nu, 0.6), std::pow(nu, 0.64), std::pow(nu, 1.4), std::pow(nu, 1.379));
    CHECK(fast == Approx(bearings::skf_moment(b, 1000, 300, 2500 * rpm, nu * cSt).total()).epsilon(1e-12));
    CHECK(bearings::SkfAtPoint::make(b, 1000, 0, 0).moment(nu, 1, 1, 1, 1) == 0.0);  // standstill
}

TEST_CASE("constants table lookups", "[bearings]") {
    CHECK(bearings::skf_constants(bearings::BearingType::cylindrical_roller, "NJ 3")->R1 == 1.09e-6);
    CHECK(bearings::skf_constants(bearings::BearingType::tapered_roller, "323")->R1 == 2.38e-6);
    CHECK_FALSE(bearings::skf_constants(bearings::BearingType::deep_groove_ball, "99").has_value());
}

TEST_CASE("radial lip seal loss", "[seals]") {
    // ISO/TR 14179-2: 7.69e-6 * 50^2 * 3000 = 57.7 W.
    CHECK(seals::radial_seal_power(0.050, 3000 * std::numbers::pi / 30) == Approx(57.675).epsilon(1e-9));
}

TEST_CASE("Changenet-Velex churning against a hand calculation", "[churning]") {
    // Rp 50 mm, b 20 mm, z 20, tooth height 6.75 mm, alpha 20 deg, h 20 mm, V0 1 L,
    // Omega 100 rad/s, rho 850 kg/m^3. Hand (python): theta = acos(1 - 0.4) = 0.92730,
    // S_m = 5.78726e-3 m^2; nu = 50 cSt -> Re_c = 2000, C_m = 1.04631e-2, C_ch = 3.21687e-2 N m;
    // nu = 0.5 cSt -> Re_c = 2e5, C_m = 2.48314e-2, C_ch = 7.63438e-2 N m.
    churning::DippingGear g{0.05, 0.02, 20, 6.75e-3, 20 * std::numbers::pi / 180, 0.02};
    CHECK(churning::submerged_surface(g) == Approx(5.787263e-3).epsilon(1e-6));
    churning::Regime r;
    CHECK(churning::dimensionless_torque(g, 100, 50e-6, 1e-3, &r) == Approx(1.046311e-2).epsilon(1e-6));
    CHECK(r == churning::Regime::low_reynolds);
    CHECK(churning::churning_torque(g, 100, 850, 50e-6, 1e-3) == Approx(3.216867e-2).epsilon(1e-6));
    CHECK(churning::published_torque(g, 100, 850, 0.5e-6, 1e-3, &r) == Approx(7.634377e-2).epsilon(1e-6));
    CHECK(r == churning::Regime::high_reynolds);
}

TEST_CASE("churning regime limits and the transition band", "[churning]") {
    churning::DippingGear g{0.05, 0.02, 20, 6.75e-3, 0.35, 0.02};
    const double w = 100;  // Re_c = w Rp b / nu = 0.1 / nu
    auto at = [&](double ReC, churning::Regime* r = nullptr) {
        return churning::published_torque(g, w, 850, 0.1 / ReC, 1e-3, r);
    };
    churning::Regime r;
    at(5999, &r);
    CHECK(r == churning::Regime::low_reynolds);
    at(6001, &r);
    CHECK(r == churning::Regime::transition);
    at(8999, &r);
    CHECK(r == churning::Regime::transition);
    at(9001, &r);
    CHECK(r == churning::Regime::high_reynolds);
    // Linear interpolation on Re_c makes the torque continuous at both limits.
    CHECK(at(6000 - 1e-6) == Approx(at(6000 + 1e-6)).epsilon(1e-6));
    CHECK(at(9000 - 1e-6) == Approx(at(9000 + 1e-6)).epsilon(1e-6));
    // Not immersed: no churning.
    g.h = 0;
    CHECK(churning::churning_torque(g, w, 850, 1e-5, 1e-3) == 0.0);
}

TEST_CASE("SKF load functions of every bearing type follow SKF (2004) Table 2a", "[bearings]") {
    // Each type's G_rr and G_sl written out here from the catalogue's table (d_m = 60 mm,
    // Fr 2000 N, Fa 500 N, n 1500 r/min, unit constants so the exponents show), against the
    // model, whose exponents of d_m come from a table computed once per bearing.
    using T = bearings::BearingType;
    using std::pow;
    const double dm = 60, Fr = 2000, Fa = 500, n = 1500;
    bearings::BearingSpec b;
    b.d = 40 * mm;
    b.D = 80 * mm;
    b.B = 18 * mm;
    b.C0 = 20000;
    b.Y = 1.7;
    b.k = {1.1e-6, 1.3, 2.1e-10, 3.5, 0.02, 0.7, 1.9e-12, 0.04, 3.1, 0.65, 1};
    const auto& k = b.k;
    struct Row {
        T type;
        double G_rr, G_sl;
    };
    const double Fgr4 = k.R3 * pow(dm, 4) * n * n, Fgs4 = k.S3 * pow(dm, 4) * n * n;
    const double Fgr35 = k.R3 * pow(dm, 3.5) * n * n, Fgs35 = k.S3 * pow(dm, 3.5) * n * n;
    const double rr_e = k.R1 * pow(dm, 1.85) * pow(Fr + k.R2 * Fa, 0.54);
    const double rr_l = k.R3 * pow(dm, 2.3) * pow(Fr + k.R4 * Fa, 0.31);
    const Row rows[] = {
        {T::angular_contact_ball, k.R1 * pow(dm, 1.97) * pow(Fr + Fgr4 + k.R2 * Fa, 0.54),
         k.S1 * pow(dm, 0.26) * (pow(Fr + Fgs4, 4.0 / 3) + k.S2 * pow(Fa, 4.0 / 3))},
        {T::self_aligning_ball, k.R1 * pow(dm, 2) * pow(Fr + Fgr35 + k.R2 * Fa, 0.54),
         k.S1 * pow(dm, -0.12) * (pow(Fr + Fgs35, 4.0 / 3) + k.S2 * pow(Fa, 4.0 / 3))},
        {T::cylindrical_roller, k.R1 * pow(dm, 2.41) * pow(Fr, 0.31), k.S1 * pow(dm, 0.9) * Fa + k.S2 * dm * Fr},
        {T::needle_roller, k.R1 * pow(dm, 2.41) * pow(Fr, 0.31), k.S1 * pow(dm, 0.9) * Fa + k.S2 * dm * Fr},
        {T::tapered_roller, k.R1 * pow(dm, 2.38) * pow(Fr + k.R2 * b.Y * Fa, 0.31),
         k.S1 * pow(dm, 0.82) * (Fr + k.S2 * b.Y * Fa)},
        {T::spherical_roller, std::min(rr_e, rr_l),
         rr_e < rr_l ? k.S1 * pow(dm, 0.25) * pow(pow(Fr, 4) + k.S2 * pow(Fa, 4), 1.0 / 3)
                     : k.S3 * pow(dm, 0.94) * pow(pow(Fr, 3) + k.S4 * pow(Fa, 3), 1.0 / 3)},
        {T::thrust_ball, k.R1 * pow(dm, 1.83) * pow(Fa, 0.54), k.S1 * pow(dm, 0.05) * pow(Fa, 4.0 / 3)},
        {T::cylindrical_roller_thrust, k.R1 * pow(dm, 2.38) * pow(Fa, 0.31), k.S1 * pow(dm, 0.62) * Fa},
    };
    for (const auto& r : rows) {
        b.type = r.type;
        INFO(bearings::to_string(r.type));
        const auto g = bearings::skf_load_terms(b, Fr, Fa, n * rpm);
        CHECK(g.G_rr == Approx(r.G_rr).epsilon(1e-12));
        CHECK(g.G_sl == Approx(r.G_sl).epsilon(1e-12));
    }
    // Deep groove ball, radial only and with the axial load's contact angle.
    b.type = T::deep_groove_ball;
    auto g = bearings::skf_load_terms(b, Fr, 0, n * rpm);
    CHECK(g.G_rr == Approx(k.R1 * pow(dm, 1.96) * pow(Fr, 0.54)).epsilon(1e-12));
    CHECK(g.G_sl == Approx(k.S1 * pow(dm, -0.26) * pow(Fr, 5.0 / 3)).epsilon(1e-12));
    const double aF = 24.6 * pow(Fa / b.C0, 0.24) * std::numbers::pi / 180, sa = std::sin(aF);
    g = bearings::skf_load_terms(b, Fr, Fa, n * rpm);
    CHECK(g.G_rr == Approx(k.R1 * pow(dm, 1.96) * pow(Fr + k.R2 * Fa / sa, 0.54)).epsilon(1e-12));
    CHECK(g.G_sl == Approx(k.S1 * pow(dm, -0.145) * pow(pow(Fr, 5) + k.S2 * pow(dm, 1.5) * pow(Fa, 4) / sa, 1.0 / 3))
                        .epsilon(1e-12));
}

TEST_CASE("SKF geometry powers kept between points are made again when the bearing changes", "[bearings]") {
    auto b = dgbb_6205();
    const auto g = bearings::SkfGeometry::of(b);
    CHECK(g.matches(b));
    const auto with = [&](auto change) {
        auto c = b;
        change(c);
        return g.matches(c);
    };
    CHECK_FALSE(with([](auto& c) { c.d *= 1.01; }));
    CHECK_FALSE(with([](auto& c) { c.D *= 1.01; }));
    CHECK_FALSE(with([](auto& c) { c.type = bearings::BearingType::cylindrical_roller; }));
    CHECK_FALSE(with([](auto& c) { c.seal_beta = 2.1; }));
    CHECK_FALSE(with([](auto& c) { c.seal_ds = 30 * mm; }));
    CHECK_FALSE(bearings::SkfGeometry{}.matches(b));  // never made
    // The cached form equals the one that computes the powers itself.
    b.seal_KS1 = 0.02;
    b.bath_H = 8 * mm;
    b.bath_VM = 1e-3;
    const auto direct = bearings::SkfAtPoint::make(b, 1000, 300, 2500 * rpm);
    const auto cached = bearings::SkfAtPoint::make(b, bearings::SkfGeometry::of(b), 1000, 300, 2500 * rpm);
    CHECK(cached.moment(35, 8, 9, 140, 135) == direct.moment(35, 8, 9, 140, 135));
}
