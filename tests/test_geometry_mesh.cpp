#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gearloss/geometry/gear_geometry.hpp"
#include "gearloss/mesh/friction.hpp"
#include "gearloss/mesh/loss_factor.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;
constexpr double deg = std::numbers::pi / 180;

namespace {
geometry::GearSpec fzg(int z, double x, double b_mm) {
    geometry::GearSpec g;
    g.name = z == 16 ? "pinion" : "wheel";
    g.z = z;
    g.mn = 4.5e-3;
    g.x = x;
    g.b = b_mm * 1e-3;
    g.alpha_n = 20 * deg;
    return g;
}
}  // namespace

TEST_CASE("FZG type C geometry matches the published test vector", "[geometry]") {
    // ISO 21771 hand calculation (FZG C: z 16/24, m 4.5, x 0.1817/0.1715, b 14);
    // tip diameters 82.46/118.36 mm match the FZG drawing, a_w = 91.5 mm is the rig's.
    const auto g = geometry::pair_geometry(fzg(16, 0.1817, 14), fzg(24, 0.1715, 14));
    CHECK(g.alpha_wt / deg == Approx(22.439).margin(0.001));
    CHECK(g.a_w * 1e3 == Approx(91.500).margin(0.001));
    CHECK(g.y == Approx(0.3334).margin(1e-4));
    CHECK(g.k == Approx(-0.0198).margin(1e-4));
    CHECK(g.da[0] * 1e3 == Approx(82.46).margin(0.01));
    CHECK(g.da[1] * 1e3 == Approx(118.36).margin(0.01));
    CHECK(g.eps1 == Approx(0.723).margin(0.001));
    CHECK(g.eps2 == Approx(0.715).margin(0.001));
    CHECK(g.eps_alpha == Approx(1.438).margin(0.001));
    CHECK(g.rho_redC * 1e3 == Approx(8.382).margin(0.001));
    CHECK(mesh::loss_factor_ohlendorf(g, 16) == Approx(0.1950).margin(1e-4));
}

TEST_CASE("given centre distance reproduces the shift-derived one", "[geometry]") {
    const auto g0 = geometry::pair_geometry(fzg(16, 0.1817, 14), fzg(24, 0.1715, 14));
    const auto g1 = geometry::pair_geometry(fzg(16, 0.1817, 14), fzg(24, 0.1715, 14), 91.5e-3);
    CHECK(g1.alpha_wt == Approx(g0.alpha_wt).epsilon(1e-5));
}

TEST_CASE("Wimmer numerical H_V equals Ohlendorf for spur gears with rigid load sharing", "[mesh]") {
    // Wimmer (2006) H_VL: beta = 0 + rigid sharing -> Ohlendorf (1958).
    const auto g = geometry::pair_geometry(fzg(16, 0.1817, 14), fzg(24, 0.1715, 14));
    const auto sweep = mesh::sweep_contact_lines(g, 4000);
    CHECK(sweep.H_V == Approx(mesh::loss_factor_ohlendorf(g, 16)).epsilon(2e-3));
    // Spur: the minimum contact length is one face width (single-pair zone).
    CHECK(sweep.L_min == Approx(14e-3).epsilon(1e-9));
    // Buckingham is ~20 % above Ohlendorf at eps_alpha ~ 1.45 (reference note).
    const double ratio = mesh::loss_factor_buckingham(g, 16) / mesh::loss_factor_ohlendorf(g, 16);
    CHECK(ratio > 1.1);
    CHECK(ratio < 1.3);
}

TEST_CASE("Schlenk mean friction: FZG C worked example", "[mesh]") {
    // Schlenk (1994) mu_mZ, hand calculation: T1 = 302 N m, n1 = 1500 rpm, eta = 50 mPa s, Ra = 0.3 um, X_L = 1
    // -> w = 637.7 N/mm, v_sumC = 4.389 m/s, mu = 0.0517, P_VZP = 478 W.
    const auto g = geometry::pair_geometry(fzg(16, 0.1817, 14), fzg(24, 0.1715, 14));
    const double T1 = 302, w1 = 1500 * 2 * std::numbers::pi / 60;
    const double F_bt = T1 / (0.5 * g.db[0]);
    const double w = F_bt / 14.0;
    const double v_sum = 2 * w1 * 0.5 * g.dw[0] * std::sin(g.alpha_wt);
    CHECK(w == Approx(637.7).margin(0.1));
    CHECK(v_sum == Approx(4.389).margin(0.001));
    const double mu = mesh::mean_friction_schlenk(w, v_sum, g.rho_redC * 1e3, 50, 0.3, 1.0);
    CHECK(mu == Approx(0.0517).margin(1e-4));
    CHECK(T1 * w1 * mu * mesh::loss_factor_ohlendorf(g, 16) == Approx(478).margin(1.0));
}

TEST_CASE("impossible gear pairs are rejected", "[geometry]") {
    // A 10-tooth pinion with x = 1.5: the tip becomes pointed.
    auto p = fzg(16, 0.1817, 14);
    p.z = 10;
    p.x = 1.5;
    CHECK_THROWS_WITH(geometry::pair_geometry(p, fzg(24, 0.1715, 14)), Catch::Contains("pointed tooth"));
    auto q = fzg(24, 0.1715, 14);
    q.mn = 4e-3;
    CHECK_THROWS_WITH(geometry::pair_geometry(fzg(16, 0, 14), q), Catch::Contains("modules differ"));
    // Pulling the wheels apart by 5 mm drops the contact ratio below 1.
    CHECK_THROWS_WITH(geometry::pair_geometry(fzg(16, 0.1817, 14), fzg(24, 0.1715, 14), 96.5e-3),
                      Catch::Contains("contact ratio"));
}

TEST_CASE("Hertz pressure and film thickness against hand values", "[mesh]") {
    // Hertz line contact (Johnson 1985, ch. 4): steel E* = 115.4 GPa, R' = 10 mm, w = 500 N/mm -> p0 = 1.355 GPa.
    CHECK(mesh::hertz_pressure(500e3, 10e-3, 2 * 115.4e9) == Approx(1.355e9).epsilon(1e-3));
    // Ertel-Grubin central film, hand calculation: eta0 = 0.05 Pa s, u_e = 5 m/s, E' = 230.8 GPa,
    // R = 10 mm, alpha = 2e-8 1/Pa, w = 500 N/mm: U = 1.0832e-10, G = 4616, W = 2.1664e-4,
    // H_c = 1.95 (GU)^(8/11) W^(-1/11) = 1.0979e-4 -> h_c = 1.0979 um (isothermal).
    mesh::LineContact c{500e3, 5.0, 10e-3, 230.8e9, 0.0};
    const auto f = mesh::line_contact_film(c, 0.05, 2e-8, 0.03, 0.14, mesh::ThermalFilmCorrection::none);
    CHECK(f.h_c == Approx(1.0979e-6).epsilon(1e-3));
    CHECK(f.phi_T == 1.0);
    // Thermal reduction lowers the film, never raises it.
    const auto ft = mesh::line_contact_film(c, 0.05, 2e-8, 0.03, 0.14, mesh::ThermalFilmCorrection::gupta);
    CHECK(ft.phi_T < 1.0);
    CHECK(ft.phi_T > 0.5);
}

TEST_CASE("Doleschel boundary share", "[mesh]") {
    CHECK(mesh::boundary_share_doleschel(0.0) == 1.0);
    CHECK(mesh::boundary_share_doleschel(1.0) == Approx(0.25));
    CHECK(mesh::boundary_share_doleschel(2.0) == 0.0);
    CHECK(mesh::boundary_share_doleschel(5.0) == 0.0);
    // With the onset moved to Lambda = 3: (1 - 1.5/3)^2 = 0.25, (1 - 0.6/3)^2 = 0.64, 0 from 3.
    CHECK(mesh::boundary_share_doleschel(1.5, 3.0) == Approx(0.25));
    CHECK(mesh::boundary_share_doleschel(0.6, 3.0) == Approx(0.64));
    CHECK(mesh::boundary_share_doleschel(3.0, 3.0) == 0.0);
    CHECK(mesh::boundary_share_doleschel(2.5, 3.0) > 0.0);  // beyond Doleschel's 2, still mixed
}
