// The viscoelastic (Maxwell-Eyring) traction of the local EHL friction: the Johnson &
// Tevaarwerk (1977) law against its closed-form limits, a numerical integration of the same
// ODE, the Eyring form it must reduce to, and the seed-000 friction curve along the path.
#include <catch2/catch.hpp>
#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <fstream>
#include <numbers>
#include <vector>

#include "gearloss/core/errors.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/mechanisms/mesh_friction_mechanism.hpp"
#include "gearloss/mesh/ehl_contact.hpp"
#include "gearloss/mesh/ehl_path.hpp"
#include "gearloss/mesh/viscoelastic.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

namespace {
std::vector<mesh::MaxwellCell> uniform(int n, double length, double eta, double G, double tau_L) {
    return std::vector<mesh::MaxwellCell>(n, mesh::MaxwellCell{length / n, eta, G, tau_L});
}
}  // namespace

TEST_CASE("Maxwell-Eyring: De -> 0 gives the Eyring stress", "[viscoelastic]") {
    // eta 1 Pa s, G 1 GPa, u_e 1 m/s, 2a = 1 mm: De = eta u_e / (G a) = 2e-6. gamma_dot 1e7 1/s,
    // tau_E 5 MPa: S = eta gamma_dot / tau_E = 2 and tau = tau_E asinh(2) = 5 MPa x 1.443635 =
    // 7.21818 MPa through the whole zone (the inlet transient lasts ~ u_e eta / G = 1 nm).
    const auto cells = uniform(32, 1e-3, 1.0, 1e9, 1e12);
    CHECK(mesh::maxwell_eyring_mean_stress(cells, 1e7, 1.0, 5e6) == Approx(7.21818e6).epsilon(1e-4));
}

TEST_CASE("Maxwell-Eyring: De -> infinity gives the elastic stress G gamma capped by tau_L", "[viscoelastic]") {
    // eta 1e15 Pa s (De = 2e3 ... the viscous term (tau_E/eta) sinh(tau/tau_E) is 1e-4 of
    // gamma_dot at the outlet), G 0.1 GPa, u_e 10 m/s, 2a = 1 mm, gamma_dot 1e4 1/s:
    // tau(x) = G gamma_dot (x + a) / u_e rises linearly to 0.1 GPa at the outlet; its mean is
    // G gamma_dot a / u_e = 1e8 x 1e4 x 5e-4 / 10 = 50 MPa.
    CHECK(mesh::maxwell_eyring_mean_stress(uniform(32, 1e-3, 1e15, 1e8, 1e12), 1e4, 10.0, 5e6) ==
          Approx(50e6).epsilon(2e-4));
    // Capped at tau_L = 60 MPa: reached after l = tau_L u_e / (G gamma_dot) = 0.6 mm, so the
    // mean is tau_L (l/2 + (2a - l)) / 2a = 60 MPa x (0.3 + 0.4) / 1 = 42 MPa.
    CHECK(mesh::maxwell_eyring_mean_stress(uniform(400, 1e-3, 1e15, 1e8, 60e6), 1e4, 10.0, 5e6) ==
          Approx(42e6).epsilon(1e-3));
    // An overflowing viscosity (eta = inf) is the purely elastic film, not a NaN.
    CHECK(mesh::maxwell_eyring_mean_stress(uniform(32, 1e-3, HUGE_VAL, 1e8, 1e12), 1e4, 10.0, 5e6) ==
          Approx(50e6).epsilon(2e-4));
}

TEST_CASE("Maxwell-Eyring: a viscous film follows the Eyring stress of each slice, down as well as up, and is held at tau_L",
          "[viscoelastic]") {
    // Every slice stiff (De ~ 1e-6: the stress reaches each slice's Eyring value within nm).
    // G 1 GPa, u_e 1 m/s, 2a = 1 mm, gamma_dot 1e7 1/s, tau_E 5 MPa. First half eta 10 Pa s:
    // S = 20, tau = 5 MPa x asinh(20) = 5 MPa x ln(20 + sqrt(401)) = 5 x 3.689504 = 18.4475 MPa;
    // second half eta 1 Pa s: S = 2, 7.21818 MPa (the stress falls into it). Mean of the two:
    // 12.8328 MPa.
    std::vector<mesh::MaxwellCell> cells = uniform(16, 0.5e-3, 10.0, 1e9, 1e12);
    const auto thin = uniform(16, 0.5e-3, 1.0, 1e9, 1e12);
    cells.insert(cells.end(), thin.begin(), thin.end());
    CHECK(mesh::maxwell_eyring_mean_stress(cells, 1e7, 1.0, 5e6) == Approx(12.8328e6).epsilon(1e-4));
    // The same film with tau_L = 10 MPa in the first half: held there, then 7.21818 MPa:
    // mean 8.60909 MPa.
    for (size_t i = 0; i < 16; ++i) cells[i].tau_L = 10e6;
    CHECK(mesh::maxwell_eyring_mean_stress(cells, 1e7, 1.0, 5e6) == Approx(8.60909e6).epsilon(1e-4));
    // tau_L = 6 MPa everywhere, below both Eyring values: 6 MPa.
    for (auto& c : cells) c.tau_L = 6e6;
    CHECK(mesh::maxwell_eyring_mean_stress(cells, 1e7, 1.0, 5e6) == Approx(6e6).epsilon(1e-4));
}

TEST_CASE("Maxwell-Eyring: the exact slice step agrees with a numerical integration at De ~ 1", "[viscoelastic]") {
    // u_e d tau/dx = G [gamma_dot - (tau_E/eta) sinh(tau/tau_E)] integrated by Dormand-Prince
    // (Boost.Odeint, tolerance 1e-10) with the mean stress as a second state; eta 100 Pa s,
    // G 1e6 Pa, u_e 5 m/s, 2a = 1 mm: De = eta u_e / (G a) = 1, S = 100 x 2e5 / 5e6 = 4.
    const double eta = 100, G = 1e6, u = 5, gd = 2e5, tE = 5e6, L = 1e-3;
    using State = std::vector<double>;
    State y = {0.0, 0.0};
    boost::numeric::odeint::integrate_adaptive(
        boost::numeric::odeint::make_controlled<boost::numeric::odeint::runge_kutta_dopri5<State>>(1e-10, 1e-10),
        [&](const State& s, State& d, double) {
            d[0] = G / u * (gd - tE / eta * std::sinh(s[0] / tE));
            d[1] = s[0] / L;
        },
        y, 0.0, L, L / 1000);
    CHECK(mesh::maxwell_eyring_step(0.0, L, gd, u, eta, G, tE) == Approx(y[0]).epsilon(1e-6));
    CHECK(mesh::maxwell_eyring_mean_stress(uniform(64, L, eta, G, 1e12), gd, u, tE) == Approx(y[1]).epsilon(1e-5));
    // Half way, the stress is below the Eyring value (still building up): viscoelastic.
    CHECK(y[0] < tE * std::asinh(eta * gd / tE));
}

namespace {
lubricant::Oil seed_oil() { return io::load_oil_file(test_support::source_path("configs/oils/75W90-syn-A.yaml")); }
mesh::EhlContactInput gear_contact(double u1, double u2) {
    mesh::EhlContactInput in;
    in.w_line = 1000e3;  // 1000 N/mm
    in.R = 8e-3;
    in.u1 = u1;
    in.u2 = u2;
    in.E_prime = 2 * 115.4e9;
    in.sigma = 0.2e-6;
    in.T_bulk = 343.15;
    return in;
}
}  // namespace

TEST_CASE("Maxwell-Eyring contact: a stiff film gives the Eyring form, a soft one less traction", "[viscoelastic][ehl]") {
    auto oil = seed_oil();
    for (double slide : {0.05, 0.5, 2.0}) {
        mesh::EhlContactInput in = gear_contact(5 + 0.5 * slide, 5 - 0.5 * slide);
        const double eyring = mesh::ehl_contact(in, oil, oil.traction, {}, false).mu_ehl;
        in.law = mesh::TractionLaw::maxwell_eyring;
        auto rh = oil.traction;
        rh.shear_modulus_0 = 1e20;  // De -> 0 everywhere: the stress is the Eyring one at each x
        const double stiff = mesh::ehl_contact(in, oil, rh, {}, false).mu_ehl;
        CHECK(stiff == Approx(eyring).epsilon(0.02));  // 32 slices against the 5-point Gauss rule
        rh.shear_modulus_0 = 1e7;  // 10 MPa: a soft film (De >> 1 inside)
        const auto soft = mesh::ehl_contact(in, oil, rh, {}, false);
        CHECK(soft.mu_ehl < eyring);
        CHECK(soft.deborah > 1);
    }
}

namespace {
struct Peak {
    double mu = 0, from_pitch = 0;
};
// Peak friction along the path of contact of the seed-000 case (oil A, 90 % of 800 N m at
// 1600 rpm, oil at 70 degC, not thermally coupled: seed 000 Figure 6), with the oil's shear
// modulus replaced by G [Pa] (0: the oil's own).
Peak seed000_peak(double G, mesh::TractionLaw law) {
    auto c = io::load_case(test_support::source_path("configs/spur-seed000.yaml"));
    auto& m = c.model;
    if (G > 0) m.oil.traction.shear_modulus_0 = G;
    const double w = 1600 * std::numbers::pi / 30, T = 720;
    const auto p = solver::prepare_point(m, w, T);
    const auto& md = m.layout.meshes[0];
    const auto& ms = mesh::mesh_friction_point(m, p.data).meshes[0];
    const auto prof = mesh::ehl_path(md.geom, md.L_mean, ms.omega_rel, ms.F_bn, 1, ms.contact.E_prime, ms.sigma,
                                     273.15 + 70, m.oil, m.oil.traction, 401, true, law);
    Peak pk;
    for (const auto& pt : prof.points)
        if (pt.c.mu > pk.mu) pk = {pt.c.mu, std::abs(pt.from_pitch)};
    return pk;
}
}  // namespace

TEST_CASE("seed 000: the friction peak along the path of contact, and its sensitivity to G", "[viscoelastic][seed000]") {
    // Seed 000 (Figure 6, oil A): "Friction reaches a maximum value of 0.0593 at around 6 mm
    // along the contact path and is minimized at the pitch point." The seed's text gives no
    // module, face width (Table 2), viscosities (Table 1), fitted tau_E and Z_R, nor any value or
    // law for its shear modulus (text at its Figure 1): the case assumes m 4 mm, b 20 mm and G 1 GPa.
    const auto c = io::load_case(test_support::source_path("configs/spur-seed000.yaml"));
    REQUIRE(mesh::mesh_forms(c.model).friction == mesh::FrictionModel::ehl_maxwell);
    const auto& g = c.model.layout.meshes[0].geom;
    // The path of the assumed geometry: 23/23 teeth, m 4 mm, alpha 20 deg: approach
    // sqrt(50^2 - 43.22^2) - 43.22 tan 20 = 25.14 - 15.73 = 9.41 mm (hand value), so "6 mm
    // along the path" from its start is 3.4 mm before the pitch point.
    REQUIRE(g.T1C - g.T1A == Approx(9.41e-3).epsilon(5e-3));
    const double seed_from_pitch = (g.T1C - g.T1A) - 6e-3;

    const Peak own = seed000_peak(0, mesh::TractionLaw::maxwell_eyring);
    CHECK(own.mu == Approx(0.0593).epsilon(0.15));  // peak value: within 15 % (-9 %)
    // The peak position is not reproduced: at G = 1 GPa the film's elastic strain SRR 2a/h
    // reaches tau_L / G within a slide-to-roll ratio of ~1e-4 of the pitch point, so the
    // viscoelastic law gives the Eyring / limiting-shear curve (peak 0.47 mm from the pitch).
    const Peak eyring = seed000_peak(0, mesh::TractionLaw::eyring);
    CHECK(own.mu == Approx(eyring.mu).epsilon(0.01));
    CHECK(own.from_pitch == Approx(eyring.from_pitch).margin(0.1e-3));
    CHECK(own.from_pitch < 0.2 * seed_from_pitch);
    // Sensitivity: the peak leaves the pitch point only when G falls to ~1 MPa, three orders of
    // magnitude below measured limiting elastic moduli (Bair & Winer 1979); the seed's position
    // (3.4 mm) needs G ~ 0.5 MPa, and the peak value then falls to ~0.049 (-18 %).
    double last = 0;
    for (double G : {1e9, 1e7, 1e6, 5e5, 2e5}) {
        const Peak pk = seed000_peak(G, mesh::TractionLaw::maxwell_eyring);
        INFO("G " << G << " Pa: peak " << pk.mu << " at " << pk.from_pitch * 1e3 << " mm from the pitch point");
        CHECK(pk.from_pitch >= last);  // softer film, peak further from the pitch point
        last = pk.from_pitch;
        if (G == 5e5) {
            CHECK(pk.from_pitch == Approx(seed_from_pitch).epsilon(0.15));
            CHECK(pk.mu < 0.85 * 0.0593);
        }
    }
}

TEST_CASE("oil file: the rheology block with units, and its errors at the key", "[viscoelastic][config]") {
    const std::string dir = test_support::source_path("configs/oils/");
    const auto oil = io::load_oil_file(dir + "75W90-syn-A.yaml");
    CHECK(oil.traction.shear_modulus_0 == Approx(1e9));
    const std::string base = test_support::read_file(dir + "75W90-syn-A.yaml");
    const test_support::TempDir tmp;
    const std::string path = (tmp.path / "rheology-oil.yaml").string();
    auto write = [&](const std::string& text) { std::ofstream(path) << text; };
    write(test_support::replace_once(base, "shear_modulus: 1 GPa", "shear_modulus: 500 MPa\n  shear_modulus_pressure_slope: 1.5\n"
                                                                   "  shear_modulus_temperature_coefficient: 0.01 1/K\n"
                                                                   "  reference_temperature: 40 degC"));
    const auto o2 = io::load_oil_file(path);
    CHECK(o2.traction.shear_modulus_0 == Approx(5e8));
    // G = (G0 + G_p p) exp(-beta (T - T_ref)): at 1 GPa and 80 degC, (0.5 + 1.5) GPa x exp(-0.4) = 1.3406 GPa.
    CHECK(mesh::shear_modulus(o2.traction, 1e9, 353.15) == Approx(1.3406e9).epsilon(1e-4));
    write(test_support::replace_once(base, "shear_modulus: 1 GPa", "shear_modulus: 1 mm"));
    try {
        (void)io::load_oil_file(path);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.key.find("shear_modulus") != std::string::npos);
        CHECK(e.line == test_support::line_of(test_support::read_file(path), "shear_modulus: 1 mm"));
    }
    write(test_support::replace_once(base, "shear_modulus: 1 GPa", "shear_modulus: 1 GPa\n  shear_modulus_temperature_coefficient: 0.01 1/K"));
    CHECK_THROWS_AS(io::load_oil_file(path), InputError);  // a temperature law needs its reference temperature
    write(test_support::replace_once(base, "shear_modulus: 1 GPa", "shear_modulus: 1 GPa\n  shear_mod: 2 GPa"));
    CHECK_THROWS_AS(io::load_oil_file(path), InputError);  // unknown key
}
