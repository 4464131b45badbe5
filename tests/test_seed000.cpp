#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/config.hpp"
#include "mesh/ehl_path.hpp"
#include "solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;

TEST_CASE("seed 000 trends along the path of contact and for the gearbox", "[ehl][seed000]") {
    // Published trends (seed 000): friction zero-ish at the pitch point and peaking towards
    // the ends of the path; h_min nearly constant; temperature minimal at the pitch point;
    // local efficiency 98-100 %; overall efficiency ~99 %.
    const auto c = io::load_case(test_support::source_path("configs/spur-seed000.yaml"));
    const auto& m = c.model;
    const double w = 1600 * std::numbers::pi / 30, T = 720;
    const auto r = solver::solve_point(m, w, T);
    REQUIRE(r.status == solver::PointStatus::ok);
    const auto p = solver::prepare_point(m, w, T);
    const auto& md = m.layout.meshes[0];
    const auto prof = mesh::ehl_path(md.geom, md.L_mean, p.meshes[0].omega_rel, p.meshes[0].F_bn, 1,
                                     p.meshes[0].contact.E_prime, p.meshes[0].sigma, r.oil_temperature, m.oil,
                                     m.oil.traction, 41);
    const auto& pts = prof.points;
    const auto pitch = std::min_element(pts.begin(), pts.end(), [](const auto& a, const auto& b) {
        return std::abs(a.from_pitch) < std::abs(b.from_pitch);
    });
    double mu_max = 0, h_lo = 1, h_hi = 0, T_min = 1e9, eff_min = 1;
    for (const auto& pt : pts) {
        mu_max = std::max(mu_max, pt.c.mu);
        h_lo = std::min(h_lo, pt.c.h_min);
        h_hi = std::max(h_hi, pt.c.h_min);
        T_min = std::min(T_min, pt.c.T_film);
        eff_min = std::min(eff_min, pt.local_efficiency);
    }
    CHECK(pitch->c.mu < 0.2 * mu_max);                               // zero-ish at the pitch point
    CHECK((pts.front().c.mu > 0.5 * mu_max || pts.back().c.mu > 0.5 * mu_max));  // peaks towards the ends
    CHECK(mu_max < 0.1);
    CHECK(h_hi / h_lo < 1.6);                                        // nearly constant
    CHECK(pitch->c.T_film == Catch::Detail::Approx(T_min).margin(0.5));  // coolest at the pitch point
    CHECK(eff_min > 0.98);                                           // local efficiency 98-100 %
    CHECK(r.efficiency > 0.99);                                      // overall ~99 %
    CHECK(r.efficiency < 0.997);
    // Not asserted: seed 000's "coupled oil temperature well above the uncoupled one". With the
    // assumed traction data the losses here fall as the oil warms (viscous traction, churning and
    // bearing drag), so the coupled rise stays below the rise the cold-oil losses would cause;
    // reproducing that trend needs the oils' measured rheology.
}
