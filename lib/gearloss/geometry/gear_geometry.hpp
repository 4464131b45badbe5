#pragma once
// Involute helical gear pair geometry with profile shift (ISO 21771 / DIN 3960,
// as in MAAG (1990), the Gear Book). All lengths in metres, angles in rad.
#include <cmath>
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

// How a mesh's centre distance fits its profile shifts (ISO 21771:2007, gear pair geometry):
// the shifts give one centre distance at which the flanks mesh without backlash, a_w(x1 + x2);
// a centre distance given by the case implies its own x1 + x2 and, if larger (smaller for an
// internal pair), a backlash j_wt; if the given a_w pushes the flanks into each other, j_wt < 0.
// Lengths are magnitudes (a_w of an internal pair as well); backlash keeps its sign.
struct CentreDistanceFit {
    bool given = false;        // the case gives the centre distance
    double a = 0;              // reference centre distance m_n (z1 + z2) / (2 cos beta)
    double a_w = 0;            // working centre distance: the given one, else a_w_shifts
    double a_w_shifts = 0;     // the zero-backlash centre distance of the given shifts
    double sum_x = 0;          // x1 + x2 as given
    double sum_x_implied = 0;  // x1 + x2 that meshes without backlash at a_w
    double alpha_wt = 0;       // working transverse pressure angle at a_w
    double alpha_wt_shifts = 0;  // the same at a_w_shifts
    double j_wt = 0;           // circumferential backlash on the working pitch circle the centre distance adds (< 0: overlap)
    double j_bn = 0;           // the same along the line of action, normal to the flanks
    double tolerance = 0;      // centre-distance tolerance +/- of a gearbox housing at a_w (centre_distance_tolerance)
    double excess() const { return a_w - a_w_shifts; }  // magnitudes: > 0 moves an external pair apart
    bool beyond_tolerance() const { return given && std::abs(excess()) > tolerance; }
    bool overlaps() const { return beyond_tolerance() && j_wt < 0; }  // flanks would overlap: an error
    bool slack() const { return beyond_tolerance() && j_wt > 0; }     // backlash beyond the housing tolerance: a warning
};

// Standard tolerance IT`grade` (5..11) of a size [m], in m: ISO 286-1:2010 (clause 5, Annex A),
// with the size itself in place of the geometric mean of its size step (a smooth value).
double iso286_tolerance(double size, int grade);
// Tolerance +/- of a working centre distance [m]: the ISO 286-1 field js7 (half IT7), the
// centre-distance allowance DIN 3964 gives gearbox housings of ordinary quality. Within it a
// centre distance and the shifts agree; the backlash that remains is the tooth-thickness
// allowances' business (DIN 3967), which a case does not describe.
double centre_distance_tolerance(double a_w);

// The fit of `a_w` (the given centre distance, else none) to the shifts of g1 and g2 (gear 2
// internal with ISO 21771's signed convention). Throws GeometryError (key "centre_distance")
// when no working pressure angle exists at a_w.
CentreDistanceFit centre_distance_fit(const GearSpec& g1, const GearSpec& g2, std::optional<double> a_w = std::nullopt);
// "centre distance 88.000 mm is 3.500 mm below ..." naming a_w, a_w of the shifts, both sums x1 + x2 and the backlash.
std::string describe_fit(const CentreDistanceFit& f);

struct PairGeometry {
    CentreDistanceFit fit;   // the centre distance against the profile shifts
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

// An impossible gear pair. `key` names the mesh's key at fault ("centre_distance") when it is one of
// the mesh's own keys, else it is empty (the gears' data).
struct GeometryError : InputError {
    using InputError::InputError;
    GeometryError(std::string key_, std::string message_) : InputError({}, 0, 0, std::move(key_), std::move(message_)) {}
};

// Computes the pair geometry (gear 1 external; gear 2 external or internal,
// internal gears with the ISO 21771 signed convention: z, d and a < 0 inside
// the formulas, so that one set of formulas serves both). With `a_w` given, the working pressure angle
// follows from it (the profile shifts stay as given and the tip alteration k
// absorbs the difference). Throws GeometryError for an impossible pair, and for a given a_w
// at which the flanks of the given shifts would overlap beyond the housing tolerance (p.fit).
PairGeometry pair_geometry(const GearSpec& g1, const GearSpec& g2, std::optional<double> a_w = std::nullopt);

}  // namespace gearloss::geometry
