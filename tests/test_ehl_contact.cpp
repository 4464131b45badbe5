#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "io/config.hpp"
#include "geometry/gear_geometry.hpp"
#include "mesh/ehl_contact.hpp"
#include "mesh/ehl_path.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

namespace {
lubricant::Oil oil() { return io::load_oil_file(test_support::source_path("configs/oils/75W90-A.yaml")); }
mesh::EhlContactInput contact(double w_N_per_mm, double u1, double u2) {
    mesh::EhlContactInput in;
    in.w_line = w_N_per_mm * 1e3;
    in.R = 10e-3;
    in.u1 = u1;
    in.u2 = u2;
    in.E_prime = 2 * 115.4e9;  // steel on steel
    in.sigma = 0.1e-6;
    in.T_bulk = 353.15;
    return in;
}
// FZG type C pair (z 16/24, m 4.5 mm, x 0.1817/0.1715, b 14 mm).
geometry::PairGeometry fzg_c() {
    geometry::GearSpec p, w;
    p.name = "pinion";
    p.z = 16;
    p.x = 0.1817;
    w.name = "wheel";
    w.z = 24;
    w.x = 0.1715;
    for (auto* g : {&p, &w}) {
        g->mn = 4.5e-3;
        g->b = 14e-3;
        g->alpha_n = 20 * std::numbers::pi / 180;
    }
    return geometry::pair_geometry(p, w);
}
}  // namespace

TEST_CASE("EHL contact: Hertz half-width and pressure against the hand values", "[ehl]") {
    // bearings-ehl-oil.md §3: E* 115.4 GPa, R' 10 mm, w 500 N/mm -> a = 234.9 um, p0 = 1.355 GPa.
    const auto r = mesh::ehl_contact(contact(500, 5, 5), oil(), {}, {}, false);
    CHECK(r.a == Approx(234.9e-6).epsilon(1e-3));
    CHECK(r.p0 == Approx(1.355e9).epsilon(1e-3));
    // Pure rolling: no sliding, no traction.
    CHECK(r.mu_ehl == 0.0);
}

TEST_CASE("EHL contact: Newtonian limit at low stress (traction proportional to sliding)", "[ehl]") {
    // Light load and tiny slide: eta * shear rate << tau_E, so tau = eta gamma_dot.
    const auto o = oil();
    const auto r1 = mesh::ehl_contact(contact(20, 5.0005, 4.9995), o, {}, {}, false);
    const auto r2 = mesh::ehl_contact(contact(20, 5.001, 4.999), o, {}, {}, false);
    REQUIRE(r1.mu_ehl > 0);
    CHECK(r2.mu_ehl / r1.mu_ehl == Approx(2.0).epsilon(1e-3));
}

TEST_CASE("EHL contact: limiting shear plateau mu = Lambda_L", "[ehl]") {
    // Heavy load, large slide, cold oil, no heating, tau_L = Lambda_L p (tau_L0 = 0) low enough
    // that every Gauss point is limited: the mean traction is then Lambda_L times the mean pressure.
    mesh::Rheology rh;
    rh.eyring_stress = 50e6;
    rh.limiting_shear_0 = 0;
    rh.limiting_shear_slope = 0.02;
    auto in = contact(500, 9, 1);
    in.T_bulk = 313.15;  // 40 degC: thick, viscous film
    const auto r = mesh::ehl_contact(in, oil(), rh, {}, false);
    CHECK(r.mu_ehl == Approx(0.02).epsilon(1e-12));
    // Raising the plateau above the Eyring stress lowers traction below the plateau.
    rh.limiting_shear_slope = 0.2;
    CHECK(mesh::ehl_contact(in, oil(), rh, {}, false).mu_ehl < 0.2);
}

TEST_CASE("EHL contact: the thermal loop converges and heating lowers traction", "[ehl]") {
    const auto o = oil();
    const auto hot = mesh::ehl_contact(contact(500, 6, 4), o, {}, {}, true);
    const auto iso = mesh::ehl_contact(contact(500, 6, 4), o, {}, {}, false);
    CHECK(hot.residual < 0.05);
    CHECK(hot.T_film > iso.T_film + 1.0);
    CHECK(iso.T_film == 353.15);
    CHECK(hot.mu_ehl < iso.mu_ehl);
    // The film temperature is the bulk plus the flash and shear rises it reports.
    CHECK(hot.T_film == Approx(353.15 + hot.dT_flash + hot.dT_shear).epsilon(1e-12));
    // Typical gear contact: friction 0.01-0.1.
    CHECK(hot.mu > 0.01);
    CHECK(hot.mu < 0.1);
}

TEST_CASE("EHL contact: boundary friction when the film is thin against roughness", "[ehl]") {
    auto in = contact(500, 6, 4);
    in.sigma = 50e-6;  // Lambda -> 0
    const auto r = mesh::ehl_contact(in, oil(), {}, {}, true);
    CHECK(r.f_c == Approx(1.0).margin(1e-3));
    CHECK(r.mu == Approx(0.11).margin(1e-3));
}

TEST_CASE("EHL path: with a constant friction the path integral reproduces mu H_V P", "[ehl]") {
    // Roughness far above the film makes mu = mu_boundary everywhere; then the integral of
    // mu F v_slide over one base pitch must equal mu H_V F_bt v_tb (H_V by Ohlendorf for a
    // spur pair with rigid load sharing). FZG type C geometry, 302 N m, 1500 rpm.
    const auto geo = fzg_c();
    const double w1 = 1500 * std::numbers::pi / 30, T1 = 302;
    const double F_bt = T1 / (0.5 * geo.db[0]);
    mesh::Rheology rh;
    rh.mu_boundary = 0.08;
    const auto prof = mesh::ehl_path(geo, 14e-3, w1, F_bt, 1, 2 * 115.4e9, 1e-3, 353.15, oil(), rh, 2000);
    const double H_V = 0.1950;  // published test-vector value (gear-losses.md §1)
    CHECK(prof.loss == Approx(0.08 * H_V * T1 * w1).epsilon(2e-3));
    // Sliding vanishes at the pitch point: the local efficiency is highest there.
    double best = 0, at = 1e9;
    for (const auto& pt : prof.points)
        if (pt.local_efficiency > best) {
            best = pt.local_efficiency;
            at = std::abs(pt.from_pitch);
        }
    CHECK(at < geo.p_bt / 100);
}

TEST_CASE("EHL path: the 12-point piecewise Gauss loss equals the converged profile integral", "[ehl]") {
    // Spur FZG C pair at 302 N m / 1500 rpm, real traction: the Gauss rule on the smooth
    // segments A-B, B-C, C-D, D-E against 4000 midpoints of the profile.
    const auto geo = fzg_c();
    const double w1 = 1500 * std::numbers::pi / 30, F_bt = 302 / (0.5 * geo.db[0]);
    const auto o = oil();
    const mesh::Rheology rh;
    const double fine = mesh::ehl_path(geo, 14e-3, w1, F_bt, 1, 2 * 115.4e9, 0.3e-6, 353.15, o, rh, 4000).loss;
    const double gauss = mesh::ehl_mesh_loss(geo, 14e-3, w1, F_bt, 1, 2 * 115.4e9, 0.3e-6, 353.15, o, rh);
    CHECK(gauss == Approx(fine).epsilon(2e-3));
}

TEST_CASE("Roelands law from a given pressure index and from alpha", "[ehl]") {
    // eta0 10 mPa s, Z 0.6, p 1 GPa: s = ln(0.01) + 9.67 = 5.06483, (1 + 1e9/1.96e8)^0.6 = 2.95995,
    // eta = 0.01 exp(5.06483 x 1.95995) = 204.72 Pa s (hand calculation).
    CHECK(mesh::RoelandsLaw::with_index(0.01, 0.6).viscosity(1e9) == Approx(204.72).epsilon(1e-4));
    // From alpha: Z = alpha p_r / s, so the initial slope d ln(eta)/dp at p = 0 equals alpha.
    const mesh::RoelandsLaw law(0.01, 15e-9);
    const double dp = 1e3;
    CHECK(std::log(law.viscosity(dp) / law.viscosity(0)) / dp == Approx(15e-9).epsilon(1e-4));
}

TEST_CASE("Traction defaults by base oil and the roelands_index key", "[ehl][config]") {
    const auto pao = lubricant::default_traction(lubricant::BaseOil::pao);
    const auto tf = lubricant::default_traction(lubricant::BaseOil::traction_fluid);
    CHECK(tf.limiting_shear_slope > pao.limiting_shear_slope);
    // Oil A of seed 000 gives Z; a higher Z raises the in-contact viscosity and so the traction.
    auto a = io::load_oil_file(test_support::source_path("configs/oils/75W90-syn-A.yaml"));
    CHECK(a.traction.roelands_Z == Approx(0.70));
    auto in = contact(500, 6, 4);
    const double mu_z = mesh::ehl_contact(in, a, a.traction, {}, false).mu_ehl;
    auto rh = a.traction;
    rh.roelands_Z = 0.5;
    CHECK(mesh::ehl_contact(in, a, rh, {}, false).mu_ehl < mu_z);
}
