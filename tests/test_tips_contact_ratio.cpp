// Tips, contact ratios and the helical gear loss factor (black-box, from the specification).
//
// Independent values: every contact ratio and closed-form H_V below is computed in this
// file from ISO 21771 (involute, working pressure angle from the profile shifts, tip
// alteration k = min(0, y - (x1 + x2)), eps_i = z_i (tan alpha_a,i - tan alpha_wt)/(2 pi),
// eps_beta = b sin(beta)/(pi m_n)), never from the library's PairGeometry; the library's
// numbers are only compared against them.
//
// Why H_V(Wimmer) = uniform-load form when eps_beta is whole: with rigid load sharing the
// line load is w = F_bn / L(t). When eps_beta is an integer the contact lines (inclined at
// beta_b, transverse spacing p_bt) always cover the rectangle g_alpha x b with the same total
// length L = eps_alpha b / cos(beta_b), so w is constant. The friction power is then
// mu w \int v_g dl, and over a mesh cycle the lines sweep the rectangle uniformly, so the
// mean of the sliding speed v_g = omega1 (u+1)/u |xi| over the path is
// omega1 (u+1)/u (g_f^2 + g_a^2)/(2 g_alpha). Dividing by P = F_bn cos(beta_b) r_b1 omega1 and
// using g = eps p_bt, p_bt = 2 pi r_b1 / z1:
//   H_V = pi (u+1)/(z1 u cos beta_b) (eps1^2 + eps2^2)/eps_alpha        ("Buckingham" form).
// Ohlendorf (1958): pi (u+1)/(z1 u cos beta_b) (1 - eps_alpha + eps1^2 + eps2^2).
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>

#include "gearloss/core/errors.hpp"
#include "gearloss/geometry/gear_geometry.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/mechanisms/mesh_friction_mechanism.hpp"
#include "gearloss/mesh/loss_factor.hpp"
#include "test_support.hpp"

using namespace gearloss;
using test_support::TempConfig;

namespace {
constexpr double kPi = 3.14159265358979323846;
double deg(double d) { return d * kPi / 180.0; }
double inv(double a) { return std::tan(a) - a; }
double inv_inverse(double v) {  // Newton on tan(a) - a = v
    double a = 0.5;
    for (int i = 0; i < 60; ++i) a -= (std::tan(a) - a - v) / (std::tan(a) * std::tan(a));
    return a;
}

// ISO 21771 hand calculation of an external pair (lengths in mm, angles in rad).
struct Hand {
    double alpha_t, alpha_wt, beta_b, a_w, y, k, d1, d2, da1, da2, eps1, eps2, eps_alpha, eps_beta, u;
    double common(int z1) const { return kPi * (u + 1) / (z1 * u * std::cos(beta_b)); }
    double buckingham(int z1) const { return common(z1) * (eps1 * eps1 + eps2 * eps2) / eps_alpha; }
    double ohlendorf(int z1) const { return common(z1) * (1 - eps_alpha + eps1 * eps1 + eps2 * eps2); }
};
struct HandIn {
    int z1, z2;
    double mn, x1, x2, beta_deg, b;
    std::optional<double> a_w;
    double ha = 1.0;
    std::optional<double> k1, k2;    // given tip alteration factors
    std::optional<double> da1, da2;  // given tip diameters
};
Hand hand(const HandIn& in) {
    Hand h{};
    const double an = deg(20), beta = deg(in.beta_deg);
    h.alpha_t = std::atan(std::tan(an) / std::cos(beta));
    h.d1 = in.z1 * in.mn / std::cos(beta);
    h.d2 = in.z2 * in.mn / std::cos(beta);
    const double db1 = h.d1 * std::cos(h.alpha_t), db2 = h.d2 * std::cos(h.alpha_t);
    const double a = 0.5 * (h.d1 + h.d2);
    if (in.a_w) {
        h.a_w = *in.a_w;
        h.alpha_wt = std::acos(a * std::cos(h.alpha_t) / h.a_w);
    } else {
        h.alpha_wt = inv_inverse(inv(h.alpha_t) + 2 * std::tan(an) * (in.x1 + in.x2) / (in.z1 + in.z2));
        h.a_w = a * std::cos(h.alpha_t) / std::cos(h.alpha_wt);
    }
    h.y = (h.a_w - a) / in.mn;
    h.k = std::min(0.0, h.y - (in.x1 + in.x2));
    h.da1 = in.da1 ? *in.da1 : h.d1 + 2 * in.mn * (in.ha + in.x1 + in.k1.value_or(h.k));
    h.da2 = in.da2 ? *in.da2 : h.d2 + 2 * in.mn * (in.ha + in.x2 + in.k2.value_or(h.k));
    h.eps1 = in.z1 * (std::tan(std::acos(db1 / h.da1)) - std::tan(h.alpha_wt)) / (2 * kPi);
    h.eps2 = in.z2 * (std::tan(std::acos(db2 / h.da2)) - std::tan(h.alpha_wt)) / (2 * kPi);
    h.eps_alpha = h.eps1 + h.eps2;
    h.eps_beta = in.b * std::sin(beta) / (kPi * in.mn);
    h.beta_b = std::atan(std::tan(beta) * std::cos(h.alpha_t));
    h.u = double(in.z2) / in.z1;
    return h;
}

geometry::GearSpec spec(const char* name, int z, double mn_mm, double x, double b_mm, double beta_deg,
                        geometry::Hand hd, double ha = 1.0) {
    geometry::GearSpec g;
    g.name = name;
    g.z = z;
    g.mn = mn_mm * 1e-3;
    g.x = x;
    g.b = b_mm * 1e-3;
    g.beta = deg(beta_deg);
    g.hand = beta_deg == 0 ? geometry::Hand::spur : hd;
    g.ha_star = ha;
    return g;
}

std::string fzg() { return test_support::read_file(test_support::source_path("configs/fzg-c40-paor.yaml")); }
const std::string pinion_tail = "profile_shift: 0.1817, face_width: 40 mm";
const std::string wheel_tail = "profile_shift: 0.1715, face_width: 40 mm";

// FZG C40 made helical (beta 25 deg, hands opposite) with short teeth, centre distance free.
std::string fzg_helical(const std::string& pinion_extra, const std::string& wheel_extra,
                        const std::string& face = "40 mm") {
    std::string t = fzg();
    t = test_support::replace_once(t, pinion_tail,
                                   "profile_shift: 0.1817, face_width: " + face +
                                       ", helix_angle: 25 deg, hand: right" + pinion_extra);
    t = test_support::replace_once(t, wheel_tail,
                                   "profile_shift: 0.1715, face_width: " + face +
                                       ", helix_angle: 25 deg, hand: left" + wheel_extra);
    t = test_support::replace_once(t, ", centre_distance: 91.5 mm", "");
    return t;
}

template <class F>
InputError expect_input_error(const std::string& text, F&& more_checks) {
    TempConfig cfg(text);
    try {
        (void)io::load_case(cfg.path);
    } catch (const InputError& e) {
        INFO(e.what());
        CHECK(e.file == cfg.path);
        CHECK(e.line > 0);
        more_checks(e);
        return e;
    }
    FAIL("no InputError raised");
    throw std::logic_error("unreachable");
}
}  // namespace

// ---------------------------------------------------------------- 2. helical H_V (Wimmer)

TEST_CASE("Wimmer H_V equals the uniform-load form when eps_beta is whole", "[loss_factor][helical]") {
    // Pair A: z 19/47, m_n 3 mm, x 0/0, beta 15 deg; b = pi m_n / sin(beta) = 36.4145 mm gives eps_beta = 1.
    //   Hand: alpha_wt = alpha_t = 20.6468 deg, beta_b = 14.0761 deg, d_a = 65.011 / 151.974 mm,
    //   eps1 = 0.73933, eps2 = 0.82905, eps_alpha = 1.56838; uniform-load H_V = 0.1883315,
    //   Ohlendorf 0.159318.
    // Pair B (transfer box m12): z 23/32, m_n 3.5 mm, x 0.415/0.381, beta 20 deg, b = 32.1489 mm.
    //   Hand: a_w = 105.0114 mm, k = -0.05762, d_a = 95.168 / 128.452 mm, eps1 = 0.69765,
    //   eps2 = 0.62386, eps_alpha = 1.32152; uniform-load H_V = 0.164325, Ohlendorf 0.137448.
    struct P {
        int z1, z2;
        double mn, x1, x2, beta;
        double ref_buck;  // the hand values quoted above
    };
    for (const P& p : {P{19, 47, 3.0, 0.0, 0.0, 15.0, 0.1883315}, P{23, 32, 3.5, 0.415, 0.381, 20.0, 0.164325}}) {
        for (int n_beta : {1, 2}) {
            const double b = n_beta * kPi * p.mn / std::sin(deg(p.beta));
            INFO("z " << p.z1 << "/" << p.z2 << ", eps_beta = " << n_beta << ", b = " << b << " mm");
            const Hand h = hand({p.z1, p.z2, p.mn, p.x1, p.x2, p.beta, b});
            CHECK(h.buckingham(p.z1) == Approx(p.ref_buck).epsilon(2e-6));  // this file's arithmetic
            const auto g = geometry::pair_geometry(spec("p", p.z1, p.mn, p.x1, b, p.beta, geometry::Hand::right),
                                                   spec("w", p.z2, p.mn, p.x2, b, p.beta, geometry::Hand::left));
            CHECK(g.eps_beta == Approx(double(n_beta)).epsilon(1e-9));
            CHECK(g.eps_alpha == Approx(h.eps_alpha).epsilon(1e-6));
            const double hv = mesh::sweep_contact_lines(g).H_V;
            CHECK(hv == Approx(h.buckingham(p.z1)).epsilon(0.002));
            // And the library's closed forms agree with the hand formulas.
            CHECK(mesh::loss_factor_buckingham(g, p.z1) == Approx(h.buckingham(p.z1)).epsilon(1e-6));
            CHECK(mesh::loss_factor_ohlendorf(g, p.z1) == Approx(h.ohlendorf(p.z1)).epsilon(1e-6));
        }
    }
}

TEST_CASE("Wimmer H_V at eps_beta = 0.5 lies between Ohlendorf and the uniform-load form", "[loss_factor][helical]") {
    // Pair B at half the eps_beta = 1 face width (16.074 mm): the line load varies over the
    // cycle, so neither closed form holds; rigid sharing lies between the spur-like
    // Ohlendorf sharing (0.137448) and the uniform load (0.164325).
    const double b = 0.5 * kPi * 3.5 / std::sin(deg(20));
    const Hand h = hand({23, 32, 3.5, 0.415, 0.381, 20.0, b});
    const auto g = geometry::pair_geometry(spec("p", 23, 3.5, 0.415, b, 20, geometry::Hand::right),
                                           spec("w", 32, 3.5, 0.381, b, 20, geometry::Hand::left));
    CHECK(g.eps_beta == Approx(0.5).epsilon(1e-9));
    const double hv = mesh::sweep_contact_lines(g).H_V;
    const double lo = h.ohlendorf(23), hi = h.buckingham(23);
    INFO("Ohlendorf " << lo << ", Wimmer " << hv << ", uniform-load " << hi);
    // Strictly inside, by at least 2 % of the gap on either side (not just a copy of one form).
    CHECK(hv > lo + 0.02 * (hi - lo));
    CHECK(hv < hi - 0.02 * (hi - lo));
}

TEST_CASE("Wimmer H_V with eps_alpha < 1 and eps_beta = 1 still equals the uniform-load form",
          "[loss_factor][helical][contact_ratio]") {
    // FZG C40 made helical: beta 25 deg, h*_a 0.7, b = pi 4.5 / sin 25 = 33.4514 mm.
    // Hand: a_w = 100.8244 mm, k = -0.01534, d_a = 87.2405 / 126.8703 mm, eps1 = 0.48082,
    // eps2 = 0.45244, eps_alpha = 0.93326 (< 1), beta_b = 23.399 deg; uniform-load H_V = 0.166542.
    const double b = kPi * 4.5 / std::sin(deg(25));
    const Hand h = hand({16, 24, 4.5, 0.1817, 0.1715, 25.0, b, std::nullopt, 0.7});
    CHECK(h.eps_alpha == Approx(0.93326).epsilon(1e-4));
    CHECK(h.buckingham(16) == Approx(0.166542).epsilon(2e-5));
    const auto g = geometry::pair_geometry(spec("p", 16, 4.5, 0.1817, b, 25, geometry::Hand::right, 0.7),
                                           spec("w", 24, 4.5, 0.1715, b, 25, geometry::Hand::left, 0.7));
    CHECK(g.eps_alpha == Approx(h.eps_alpha).epsilon(1e-6));
    CHECK(g.eps_gamma == Approx(h.eps_alpha + 1.0).epsilon(1e-6));
    CHECK(g.transverse_gap);
    CHECK(mesh::sweep_contact_lines(g).H_V == Approx(h.buckingham(16)).epsilon(0.002));
}

TEST_CASE("spur pair: Wimmer H_V equals Ohlendorf", "[loss_factor]") {
    // FZG C40 (spur): published H_V = 0.1950 (Ohlendorf, eps1 0.7224, eps2 0.7153).
    geometry::GearSpec p = spec("pinion", 16, 4.5, 0.1817, 40, 0, geometry::Hand::spur);
    geometry::GearSpec w = spec("wheel", 24, 4.5, 0.1715, 40, 0, geometry::Hand::spur);
    const auto g = geometry::pair_geometry(p, w, 91.5e-3);
    const Hand h = hand({16, 24, 4.5, 0.1817, 0.1715, 0.0, 40, 91.5});
    CHECK(h.ohlendorf(16) == Approx(0.1950).margin(5e-5));
    CHECK(mesh::sweep_contact_lines(g).H_V == Approx(h.ohlendorf(16)).epsilon(0.002));
}

TEST_CASE("transfer box: default loss factor is wimmer, 12-20 % above Ohlendorf", "[loss_factor][helical][config]") {
    auto c = io::load_case(test_support::source_path("configs/transfer-box.yaml"));
    CHECK(mesh::mesh_forms(c.model).loss_factor == mesh::LossFactorModel::wimmer);
    // Independent Ohlendorf per mesh (gear data of the shipped file; m24 and m35 at a_w = 95 mm):
    //   m12 w2/w1 23/32 m 3.5 x 0.415/0.381, a_w from the shifts: 0.137448
    //   m24 w4/w2 27/23 m 3.5 x 0.161/0.415, a_w 95 mm
    //   m35 w5/w3 17/28 m 4   x 0.051/-0.240, a_w 95 mm
    struct M {
        const char* name;
        HandIn in;
    };
    const M ms[] = {{"m12", {23, 32, 3.5, 0.415, 0.381, 20, 35}},
                    {"m24", {27, 23, 3.5, 0.161, 0.415, 20, 35, 95.0}},
                    {"m35", {17, 28, 4.0, 0.051, -0.240, 20, 33.5, 95.0}}};
    const auto& gb = c.model.gearbox;
    int found = 0;
    for (size_t i = 0; i < gb.meshes.size(); ++i) {
        for (const M& m : ms) {
            if (gb.meshes[i].name != m.name) continue;
            ++found;
            const Hand h = hand(m.in);
            const double ohl = h.ohlendorf(m.in.z1);
            const auto& md = c.model.layout.meshes[i];
            INFO(m.name << ": Ohlendorf (hand) " << ohl << ", library " << md.H_V_ohlendorf << ", Wimmer "
                        << md.H_V_wimmer);
            CHECK(md.H_V_ohlendorf == Approx(ohl).epsilon(1e-5));
            CHECK(md.loss_factor(mesh::mesh_forms(c.model).loss_factor) == md.H_V_wimmer);
            const double excess = md.H_V_wimmer / ohl - 1.0;
            CHECK(excess >= 0.12);
            CHECK(excess <= 0.20);
        }
    }
    CHECK(found == 3);

    // Without the key the default is still wimmer; ohlendorf and buckingham stay selectable.
    const std::string text = test_support::read_file(test_support::source_path("configs/transfer-box.yaml"));
    const std::string key = "  gear_loss_factor: wimmer";
    {
        const auto p = text.find(key);
        REQUIRE(p != std::string::npos);
        const auto e = text.find('\n', p);
        TempConfig cfg(text.substr(0, p) + text.substr(e + 1));
        CHECK(mesh::mesh_forms(io::load_case(cfg.path).model).loss_factor == mesh::LossFactorModel::wimmer);
    }
    {
        TempConfig cfg(test_support::replace_once(text, key, "  gear_loss_factor: ohlendorf"));
        CHECK(mesh::mesh_forms(io::load_case(cfg.path).model).loss_factor == mesh::LossFactorModel::ohlendorf);
    }
    {
        TempConfig cfg(test_support::replace_once(text, key, "  gear_loss_factor: buckingham"));
        CHECK(mesh::mesh_forms(io::load_case(cfg.path).model).loss_factor == mesh::LossFactorModel::buckingham);
    }
}

// ---------------------------------------------------------------- 3. contact ratios

TEST_CASE("helical pair with eps_alpha < 1 but eps_gamma >= 1 is accepted", "[contact_ratio][config]") {
    // beta 25 deg, h*_a 0.7, b 40 mm: eps_alpha = 0.93326 (hand, above), eps_beta = 40 sin 25/(pi 4.5)
    // = 1.19577, eps_gamma = 2.12903.
    const Hand h = hand({16, 24, 4.5, 0.1817, 0.1715, 25.0, 40.0, std::nullopt, 0.7});
    {
        TempConfig cfg(fzg_helical(", addendum_coefficient: 0.7", ", addendum_coefficient: 0.7"));
        auto c = io::load_case(cfg.path);
        const auto& g = c.model.layout.meshes.at(0).geom;
        CHECK(g.eps_alpha == Approx(h.eps_alpha).epsilon(1e-6));
        CHECK(g.eps_beta == Approx(1.19577).epsilon(1e-5));
        CHECK(g.eps_gamma == Approx(h.eps_alpha + 1.19577).epsilon(1e-5));
        CHECK(g.da[0] == Approx(87.2405e-3).epsilon(1e-6));
        CHECK(g.da[1] == Approx(126.8703e-3).epsilon(1e-6));
    }
    {
        // The same short teeth given as the drawing's tip diameters.
        TempConfig cfg(fzg_helical(", tip_diameter: 87.2405 mm", ", tip_diameter: 126.8703 mm"));
        auto c = io::load_case(cfg.path);
        const auto& g = c.model.layout.meshes.at(0).geom;
        CHECK(g.eps_alpha == Approx(h.eps_alpha).epsilon(1e-5));
        CHECK(g.tip_source[0] == geometry::TipSource::given_tip_diameter);
        CHECK(g.tip_source[1] == geometry::TipSource::given_tip_diameter);
    }
}

TEST_CASE("spur pair with eps_alpha < 1 is an error naming the mesh", "[contact_ratio][config]") {
    // Spur C40 at a_w 91.5 mm with h*_a 0.6: d_a = 78.857 / 114.765 mm, eps_alpha = 0.91237 (hand).
    const Hand h = hand({16, 24, 4.5, 0.1817, 0.1715, 0.0, 40, 91.5, 0.6});
    REQUIRE(h.eps_alpha == Approx(0.91237).epsilon(1e-4));
    std::string t = fzg();
    t = test_support::replace_once(t, pinion_tail, pinion_tail + ", addendum_coefficient: 0.6");
    t = test_support::replace_once(t, wheel_tail, wheel_tail + ", addendum_coefficient: 0.6");
    expect_input_error(t, [](const InputError& e) {
        const std::string all = e.what();
        CHECK((all.find("C40") != std::string::npos || e.key.find("meshes[0]") != std::string::npos));
        CHECK_THAT(all, Catch::Contains("eps") || Catch::Contains("contact ratio"));
    });
}

TEST_CASE("helical pair with eps_gamma < 1 is an error naming the mesh", "[contact_ratio][config]") {
    // beta 25 deg, h*_a 0.6, b 4 mm: eps_alpha = 0.81020, eps_beta = 4 sin 25/(pi 4.5) = 0.11958,
    // eps_gamma = 0.92977 < 1.
    const Hand h = hand({16, 24, 4.5, 0.1817, 0.1715, 25.0, 4.0, std::nullopt, 0.6});
    REQUIRE(h.eps_alpha + h.eps_beta == Approx(0.92977).epsilon(1e-4));
    expect_input_error(fzg_helical(", addendum_coefficient: 0.6", ", addendum_coefficient: 0.6", "4 mm"),
                       [](const InputError& e) {
                           const std::string all = e.what();
                           CHECK((all.find("C40") != std::string::npos ||
                                  e.key.find("meshes[0]") != std::string::npos));
                       });
}

TEST_CASE("ohlendorf with eps_alpha < 1 is an error at options.gear_loss_factor", "[contact_ratio][config]") {
    std::string t = fzg_helical(", addendum_coefficient: 0.7", ", addendum_coefficient: 0.7");
    t = test_support::replace_once(t, "gear_loss_factor: wimmer", "gear_loss_factor: ohlendorf");
    expect_input_error(t, [&](const InputError& e) {
        CHECK_THAT(e.key, Catch::Contains("options.gear_loss_factor"));
        CHECK(e.line == test_support::line_of(t, "gear_loss_factor: ohlendorf"));
    });
    // Chosen in the mechanisms block (which the loader reads after `options:`, so it wins), the
    // error points at that line.
    const std::string block = t + "mechanisms:\n  mesh: {loss_factor: buckingham}\n";
    expect_input_error(test_support::replace_once(block, "gear_loss_factor: ohlendorf", "gear_loss_factor: wimmer"),
                       [&](const InputError& e) {
                           CHECK(e.key == "mechanisms.mesh.loss_factor");
                           CHECK(e.line == test_support::line_of(block, "  mesh: {loss_factor: buckingham}"));
                           CHECK_THAT(e.message, Catch::Contains("outside the 1..2 that this closed form assumes"));
                       });
    // The same pair with full-depth teeth (eps_alpha = 1.286 > 1) takes ohlendorf.
    std::string ok = fzg_helical("", "");
    ok = test_support::replace_once(ok, "gear_loss_factor: wimmer", "gear_loss_factor: ohlendorf");
    TempConfig cfg(ok);
    auto c = io::load_case(cfg.path);
    CHECK(c.model.layout.meshes.at(0).geom.eps_alpha == Approx(1.2860).epsilon(1e-4));
}

// ---------------------------------------------------------------- 4. tips

TEST_CASE("FZG C40 tips: ISO default, tip_alteration_factor 0, tip_diameter", "[tips][config]") {
    // Default (ISO 21771): y = (91.5 - 90)/4.5 = 0.33333, k = y - (x1 + x2) = -0.019867,
    // d_a = 72 + 9 (1 + 0.1817 - 0.019867) = 82.4565 mm, 108 + 9 (1 + 0.1715 - 0.019867) = 118.3647 mm
    // (the FZG drawing's 82.46 / 118.36 mm).
    {
        auto c = io::load_case(test_support::source_path("configs/fzg-c40-paor.yaml"));
        const auto& g = c.model.layout.meshes.at(0).geom;
        CHECK(g.da[0] * 1e3 == Approx(82.4565).margin(5e-4));
        CHECK(g.da[1] * 1e3 == Approx(118.3647).margin(5e-4));
        CHECK(g.tip_source[0] == geometry::TipSource::iso_tip_alteration);
        CHECK(g.tip_source[1] == geometry::TipSource::iso_tip_alteration);
        CHECK(g.k_applied[0] == Approx(-0.0198667).margin(1e-6));
        CHECK(g.k_applied[1] == Approx(-0.0198667).margin(1e-6));
        CHECK(g.eps_alpha == Approx(1.43765).epsilon(1e-5));
    }
    // tip_alteration_factor 0 on both (FZG type A practice): d_a = d + 2 m_n (1 + x)
    // = 72 + 9 * 1.1817 = 82.6353 mm and 108 + 9 * 1.1715 = 118.5435 mm;
    // eps1 = 0.73411, eps2 = 0.72834, eps_alpha = 1.46245.
    {
        std::string t = fzg();
        t = test_support::replace_once(t, pinion_tail, pinion_tail + ", tip_alteration_factor: 0");
        t = test_support::replace_once(t, wheel_tail, wheel_tail + ", tip_alteration_factor: 0");
        TempConfig cfg(t);
        auto c = io::load_case(cfg.path);
        const auto& g = c.model.layout.meshes.at(0).geom;
        const Hand h = hand({16, 24, 4.5, 0.1817, 0.1715, 0.0, 40, 91.5, 1.0, 0.0, 0.0});
        CHECK(h.eps_alpha == Approx(1.4624).margin(1e-4));
        CHECK(g.da[0] * 1e3 == Approx(82.6353).margin(1e-6));
        CHECK(g.da[1] * 1e3 == Approx(118.5435).margin(1e-6));
        CHECK(g.eps_alpha == Approx(h.eps_alpha).epsilon(1e-6));
        CHECK(g.tip_source[0] == geometry::TipSource::given_tip_alteration);
        CHECK(g.tip_source[1] == geometry::TipSource::given_tip_alteration);
        CHECK(g.k_applied[0] == Approx(0.0).margin(1e-9));
        CHECK(g.k_applied[1] == Approx(0.0).margin(1e-9));
    }
    // tip_diameter 82.635 mm on the pinion only; the wheel keeps the ISO tip (118.3647 mm).
    // k_applied(pinion) = (82.635 - 72 - 9 * 1.1817)/9 = -0.0000333; eps1 = 0.73409, eps_alpha = 1.44938.
    {
        std::string t = fzg();
        t = test_support::replace_once(t, pinion_tail, pinion_tail + ", tip_diameter: 82.635 mm");
        TempConfig cfg(t);
        auto c = io::load_case(cfg.path);
        const auto& g = c.model.layout.meshes.at(0).geom;
        const Hand h = hand({16, 24, 4.5, 0.1817, 0.1715, 0.0, 40, 91.5, 1.0, {}, {}, 82.635, 118.3647});
        CHECK(g.da[0] * 1e3 == Approx(82.635).margin(1e-9));
        CHECK(g.da[1] * 1e3 == Approx(118.3647).margin(5e-4));
        CHECK(g.tip_source[0] == geometry::TipSource::given_tip_diameter);
        CHECK(g.tip_source[1] == geometry::TipSource::iso_tip_alteration);
        CHECK(g.k_applied[0] == Approx(-0.0003 / 9).margin(1e-7));
        CHECK(g.eps_alpha == Approx(h.eps_alpha).epsilon(1e-5));
        CHECK(g.eps_alpha == Approx(1.44938).epsilon(1e-5));
    }
}

TEST_CASE("a gear giving both tip_diameter and tip_alteration_factor is an error", "[tips][config]") {
    std::string t = fzg();
    t = test_support::replace_once(t, pinion_tail, pinion_tail + ", tip_diameter: 82.635 mm, tip_alteration_factor: 0");
    expect_input_error(t, [&](const InputError& e) {
        CHECK_THAT(e.key, Catch::Contains("gears[0]"));
        CHECK(e.line == test_support::line_of(t, "name: pinion"));
        const std::string all = e.what();
        CHECK_THAT(all, Catch::Contains("tip_diameter"));
        CHECK_THAT(all, Catch::Contains("tip_alteration_factor"));
    });
}
