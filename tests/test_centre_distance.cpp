// The centre distance of a mesh against its profile shifts (ISO 21771): the zero-backlash
// centre distance of the shifts, the sum of shifts a given centre distance implies, the
// backlash it adds, overlapping flanks as an error, for external and internal pairs.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "gearloss/geometry/gear_geometry.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/solver/plausibility.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

namespace {
constexpr double deg = std::numbers::pi / 180;

geometry::GearSpec gear(const char* name, int z, double mn_mm, double x, double beta_deg = 0,
                        geometry::Hand hand = geometry::Hand::spur, bool internal = false) {
    geometry::GearSpec g;
    g.name = name;
    g.z = z;
    g.mn = mn_mm * 1e-3;
    g.x = x;
    g.b = 30e-3;
    g.alpha_n = 20 * deg;
    g.beta = beta_deg * deg;
    g.hand = hand;
    g.internal = internal;
    return g;
}

// The message of the GeometryError a pair throws (empty: none), with its key.
std::pair<std::string, std::string> geometry_error(const geometry::GearSpec& a, const geometry::GearSpec& b, double a_w) {
    try {
        (void)geometry::pair_geometry(a, b, a_w);
    } catch (const geometry::GeometryError& e) {
        return {e.key, e.message};
    }
    return {};
}
}  // namespace

TEST_CASE("FZG C gears at a centre distance their shifts do not give: the flanks overlap", "[geometry][centre_distance]") {
    // FZG type C: z 16/24, m 4.5 mm, x 0.1817/0.1715 mesh without backlash at a_w = 91.5 mm
    // (published rig centre distance). At 87..90 mm the teeth would have to pass through each
    // other: inv alpha_wt(88 mm) = inv(acos(90 cos 20 deg / 88)) implies x1 + x2 = -0.404, not 0.353.
    const auto p = gear("pinion", 16, 4.5, 0.1817), w = gear("wheel", 24, 4.5, 0.1715);
    for (double a_w : {87e-3, 88e-3, 89e-3, 90e-3}) {
        INFO("a_w = " << a_w * 1e3 << " mm");
        CHECK_THROWS_AS(geometry::pair_geometry(p, w, a_w), geometry::GeometryError);
    }
    // The published centre distance is accepted.
    CHECK_NOTHROW(geometry::pair_geometry(p, w, 91.5e-3));
}

TEST_CASE("centre distance fit: FZG C published shifts and centre distance", "[geometry][centre_distance]") {
    const auto p = gear("pinion", 16, 4.5, 0.1817), w = gear("wheel", 24, 4.5, 0.1715);
    // Published: a = 4.5 (16 + 24) / 2 = 90 mm; the shifts give a_w = 91.5 mm (FZG rig).
    const auto free = geometry::centre_distance_fit(p, w);
    CHECK(free.a * 1e3 == Approx(90.0).margin(1e-9));
    CHECK(free.a_w_shifts * 1e3 == Approx(91.5).margin(0.05));
    CHECK_FALSE(free.given);
    CHECK(free.j_wt == 0.0);
    // Inverse: 91.5 mm implies the published x1 + x2 = 0.1817 + 0.1715 = 0.3532.
    const auto at = geometry::centre_distance_fit(p, w, 91.5e-3);
    CHECK(at.sum_x_implied == Approx(0.3532).margin(1e-3));
    CHECK(at.alpha_wt / deg == Approx(22.439).margin(0.001));
    CHECK_FALSE(at.beyond_tolerance());
    // 88 mm: x1 + x2 = -0.4038 (hand: alpha_wt = acos(90 cos 20 deg / 88) = 16.044 deg,
    // (inv 16.044 deg - inv 20 deg) 40 / (2 tan 20 deg) = -0.4038); the error names the key,
    // both centre distances and both sums.
    const auto [key, message] = geometry_error(p, w, 88e-3);
    CHECK(key == "centre_distance");
    CHECK_THAT(message, Catch::Contains("centre distance 88.000 mm") && Catch::Contains("91.500 mm") &&
                            Catch::Contains("x1 + x2 = 0.3532") && Catch::Contains("x1 + x2 = -0.4038") &&
                            Catch::Contains("overlap"));
}

TEST_CASE("centre distance fit: helical 23/67 without shifts at 140 mm", "[geometry][centre_distance]") {
    // Hand calculation: m_n 3 mm, beta 15 deg, z 23/67, x1 = x2 = 0:
    //   a = 3 * 90 / (2 cos 15 deg) = 139.7623 mm; alpha_t = atan(tan 20 deg / cos 15 deg) = 20.6469 deg.
    //   a_w = 140 mm: alpha_wt = acos(139.7623 cos 20.6469 deg / 140) = 20.9036 deg;
    //   x1 + x2 = (inv 20.9036 deg - inv 20.6469 deg) 90 / (2 tan 20 deg) = 0.0797;
    //   j_wt = 2 a_w (inv alpha_wt - inv alpha_t) = 0.1805 mm, DIN 3967's first-order
    //   2 (a_w - a) tan alpha_wt = 2 * 0.2377 * 0.3820 = 0.1816 mm;
    //   j_bn = j_wt cos alpha_wt cos beta_b, beta_b = asin(sin 15 deg cos 20 deg) = 14.076 deg: 0.1636 mm.
    const auto p = gear("p", 23, 3, 0, 15, geometry::Hand::left), w = gear("w", 67, 3, 0, 15, geometry::Hand::right);
    const auto free = geometry::centre_distance_fit(p, w);
    CHECK(free.a * 1e3 == Approx(139.7623).margin(1e-4));
    CHECK(free.a_w_shifts * 1e3 == Approx(139.7623).margin(1e-4));
    const auto f = geometry::pair_geometry(p, w, 140e-3).fit;  // accepted: backlash, not an overlap
    CHECK(f.given);
    CHECK(f.alpha_wt / deg == Approx(20.9036).margin(1e-4));
    CHECK(f.sum_x_implied == Approx(0.0797).margin(1e-4));
    CHECK(f.j_wt * 1e3 == Approx(0.1805).margin(1e-4));
    CHECK(f.j_wt == Approx(2 * (140e-3 - free.a) * std::tan(f.alpha_wt)).epsilon(0.01));
    CHECK(f.j_bn * 1e3 == Approx(0.1636).margin(1e-4));
    CHECK(f.slack());  // 0.238 mm beyond the +/-0.020 mm of js7 at 140 mm: a warning
    CHECK_FALSE(f.overlaps());
}

TEST_CASE("centre distance tolerance is ISO 286-1 js7", "[geometry][centre_distance]") {
    // ISO 286-1 table values of IT7: 35 um for 80..120 mm, 40 um for 120..180 mm, 72 um for
    // 400..500 mm; js7 = +/- IT7 / 2 (the formula at the size itself stays within 1 um of the table).
    CHECK(geometry::centre_distance_tolerance(95e-3) * 1e6 == Approx(17.5).margin(0.5));
    CHECK(geometry::centre_distance_tolerance(140e-3) * 1e6 == Approx(20.0).margin(0.5));
    CHECK(geometry::centre_distance_tolerance(450e-3) * 1e6 == Approx(31.5).margin(1.0));
    // IT11 of 100 mm (80..120 mm step): 220 um.
    CHECK(geometry::iso286_tolerance(100e-3, 11) * 1e6 == Approx(220).margin(5));
}

TEST_CASE("centre distance fit: published transfer gearbox meshes stay within the tolerance",
          "[geometry][centre_distance]") {
    // Pereira (2017) transfer gearbox, m 3.5 mm, beta 20 deg: w4/w2 z 27/23, x 0.161/0.415 at
    // 95 mm. The shifts give 95.0106 mm (10.6 um tighter than 95 mm), within js7 (+/-17.2 um).
    const auto w4 = gear("w4", 27, 3.5, 0.161, 20, geometry::Hand::right);
    const auto w2 = gear("w2", 23, 3.5, 0.415, 20, geometry::Hand::left);
    const auto f = geometry::pair_geometry(w4, w2, 95e-3).fit;
    CHECK(f.a_w_shifts * 1e3 == Approx(95.0106).margin(1e-3));
    CHECK(f.j_wt < 0);
    CHECK_FALSE(f.beyond_tolerance());
}

TEST_CASE("centre distance fit: internal pair, ISO 21771 signed convention", "[geometry][centre_distance]") {
    // Planet z 23 in ring z 62, m 2.5 mm, no shifts: a = 2.5 (62 - 23) / 2 = 48.75 mm.
    // Moving an internal pair apart pushes the planet's teeth into the ring's: at 48.80 mm
    // the flanks overlap (j_wt = 2 a_w (inv alpha_wt - inv alpha_t) with a_w < 0: -0.0366 mm);
    // at 48.70 mm the pair has backlash +0.0362 mm = 2 * 0.05 * tan 19.838 deg (first order).
    const auto planet = gear("planet", 23, 2.5, 0), ring = gear("ring", 62, 2.5, 0, 0, geometry::Hand::spur, true);
    const auto free = geometry::centre_distance_fit(planet, ring);
    CHECK(free.a_w_shifts * 1e3 == Approx(48.75).margin(1e-9));
    const auto [key, message] = geometry_error(planet, ring, 48.80e-3);
    CHECK(key == "centre_distance");
    CHECK_THAT(message, Catch::Contains("overlap"));
    const auto f = geometry::pair_geometry(planet, ring, 48.70e-3).fit;
    CHECK(f.j_wt * 1e3 == Approx(0.0362).margin(1e-4));
    CHECK(f.j_wt == Approx(2 * 0.05e-3 * std::tan(f.alpha_wt)).epsilon(0.01));
    CHECK(f.sum_x_implied == Approx(0.0199).margin(1e-4));
    CHECK(f.slack());
    // Shifts of an internal pair: x1 + x2 = 0.3 (ISO 21771 sign) brings the pair closer
    // (inv alpha_wt = inv 20 deg + 2 * 0.3 tan 20 deg / (23 - 62) < inv 20 deg), and the fit
    // at that centre distance returns the shifts.
    const auto ps = gear("planet", 23, 2.5, 0.1), rs = gear("ring", 62, 2.5, 0.2, 0, geometry::Hand::spur, true);
    const auto shifted = geometry::centre_distance_fit(ps, rs);
    CHECK(shifted.a_w_shifts < 48.75e-3);
    const auto back = geometry::centre_distance_fit(ps, rs, shifted.a_w_shifts);
    CHECK(back.sum_x_implied == Approx(0.3).margin(1e-9));
    CHECK(std::abs(back.j_wt) < 1e-12);
}

TEST_CASE("a given tip longer than the full-depth tip of its shift is a warning", "[geometry][centre_distance]") {
    // FZG C40 wheel: d = 108 mm, x = 0.1715: full-depth tip d + 2 m (1 + x) = 108 + 9 * 1.1715
    // = 118.5435 mm. A tip diameter of 119.5 mm is 0.957 mm longer (beyond IT11 = 0.22 mm).
    std::string t = test_support::read_file(test_support::source_path("configs/fzg-c40-paor.yaml"));
    t = test_support::replace_once(t, "profile_shift: 0.1715,", "profile_shift: 0.1715, tip_diameter: 119.5 mm,");
    const test_support::TempConfig cfg(t);
    const auto c = io::load_case(cfg.path);
    const auto findings = solver::check_mesh_geometry(c.model);
    REQUIRE(findings.size() == 1);
    CHECK(findings[0].subject == solver::PlausibilityFinding::Subject::tip);
    CHECK_THAT(findings[0].message, Catch::Contains("119.500 mm") && Catch::Contains("118.54"));
    bool located = false;
    for (const auto& w : c.warnings) located = located || w.find(".yaml:12:") != std::string::npos;
    CHECK(located);
}
