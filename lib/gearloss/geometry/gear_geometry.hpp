#pragma once
// Involute helical gear pair geometry with profile shift (ISO 21771 / DIN 3960,
// as in MAAG (1990), the Gear Book). All lengths in metres, angles in rad.
#include <optional>
#include <string>
#include "gearloss/core/errors.hpp"

namespace gearloss::geometry {

struct Material {
    double E = 210e9;      // Pa
    double poisson = 0.3;
    double density = 7850; // kg/m^3
};

enum class Hand { right, left, spur };

struct GearSpec {
    std::string name;
    int z = 0;              // teeth
    double mn = 0;          // normal module
    double x = 0;           // profile shift coefficient
    double b = 0;           // face width
    double alpha_n = 0.349065850398866; // normal pressure angle (20 deg)
    double beta = 0;        // helix angle magnitude
    Hand hand = Hand::spur;
    double ha_star = 1.0;   // addendum coefficient of the basic rack
    double hf_star = 1.25;  // dedendum coefficient
    bool internal = false;  // internal (ring) gear: tip inside, mates turn the same way
    double Ra = 0.5e-6;     // arithmetic mean roughness of the flanks
    std::optional<double> Rq;  // rms roughness; ~1.25 Ra when absent (Gaussian)
    Material material;
    // Tip: by default d_a = d + 2 m_n (h*_a + x + k) with the pair's ISO 21771 tip
    // alteration k = min(0, y - (x1 + x2)). A gear may give its own tip alteration
    // factor k (FZG type A gears: tips not shortened, k = 0) or its tip diameter.
    std::optional<double> tip_alteration_factor;
    std::optional<double> tip_diameter;

    double mt() const;
    double alpha_t() const;
    double d() const;   // reference diameter
    double db() const;  // base diameter
    double signed_beta() const { return hand == Hand::left ? -beta : beta; }
};

double involute(double a);
// Inverse of the involute function on [0, 1.5) rad.
double inverse_involute(double inv);

// Derived data of a gear pair; index 0 = first gear named in the mesh, which
// is external; gear 1 may be internal (a ring). Lengths are magnitudes; the
// path of contact uses ISO 21771's signed convention (T1T2 < 0 for internal).
// Where a gear's tip diameter came from (shown by `check`).
enum class TipSource { iso_tip_alteration, given_tip_alteration, given_tip_diameter };
const char* to_string(TipSource s);

struct PairGeometry {
    bool internal = false;   // gear 1 is an internal gear
    double u = 0;            // z2/z1 (>0)
    double sign = 1;         // +1 external pair, -1 internal pair (u + sign appears in H_V)
    double alpha_t = 0, alpha_wt = 0, beta_b = 0;
    double a = 0, a_w = 0;   // reference and working centre distance
    double y = 0, k = 0;     // centre-distance modification and ISO 21771 tip alteration coefficients
    double k_applied[2]{};   // tip alteration factor of each gear as used: (d_a - d - 2 m_n (h*_a + x)) / (2 m_n)
    TipSource tip_source[2]{TipSource::iso_tip_alteration, TipSource::iso_tip_alteration};
    double d[2]{}, db[2]{}, dw[2]{}, da[2]{}, df[2]{};
    double p_bt = 0;         // transverse base pitch
    double eps1 = 0, eps2 = 0, eps_alpha = 0, eps_beta = 0, eps_gamma = 0;
    // eps_alpha < 1 with eps_gamma >= 1: continuous contact through the overlap
    // only (a valid low-loss helical design, e.g. FZG H951); T1B > T1D then.
    bool transverse_gap = false;
    // Path of contact measured from T1 (pinion base tangent point) along the line of action.
    double T1T2 = 0, T1A = 0, T1B = 0, T1C = 0, T1D = 0, T1E = 0;
    double rho_redC = 0;     // reduced normal radius of curvature at the pitch point
    double tip_clearance[2]{};   // c = a_w - r_a,i - r_f,other
    double tip_thickness[2]{};   // transverse tooth thickness at the tip circle
    double b_eff = 0;        // common face width
};

struct GeometryError : InputError {
    using InputError::InputError;
};

// Computes the pair geometry (gear 1 external; gear 2 external or internal,
// internal gears with the ISO 21771 signed convention: z, d and a < 0 inside
// the formulas, so that one set of formulas serves both). With `a_w` given, the working pressure angle
// follows from it (the profile shifts stay as given and the tip alteration k
// absorbs the difference). Throws GeometryError for an impossible pair.
PairGeometry pair_geometry(const GearSpec& g1, const GearSpec& g2, std::optional<double> a_w = std::nullopt);

}  // namespace gearloss::geometry
