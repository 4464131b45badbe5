#pragma once
// Checks of a built model that no single key can make: the oil level against the
// gears and shafts, the oil volume against the housing and the level. Run before
// any computation; the loader turns each finding into a located warning or error.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gearloss/model/model.hpp"

namespace gearloss::solver {

enum class Lubrication { dip, injection };

// Outer envelope of the housing [m], when the case describes it.
struct HousingBox {
    double length = 0, width = 0, height = 0;
    double volume() const { return length * width * height; }
};

struct PlausibilityFinding {
    enum class Severity { note, warning, error };
    // centre_distance: the mesh's centre_distance key; tip: the gear's tip_diameter or tip_alteration_factor.
    enum class Subject { oil_level, oil_volume, gear, lubrication, centre_distance, tip, clutch, mesh_film };
    Severity severity = Severity::warning;
    Subject subject = Subject::oil_level;
    int gear = -1;  // index into gearbox.gears for Subject::gear and Subject::tip, into gearbox.clutches for Subject::clutch
    std::string message;
    int mesh = -1;  // index into gearbox.meshes for Subject::centre_distance and Subject::mesh_film
};

// The mesh geometry against itself (after finalise()): a given centre distance beyond the
// housing tolerance above the one the profile shifts give (backlash; the overlap below is an
// error of geometry::pair_geometry), a given tip longer than the full-depth tip of its shift.
std::vector<PlausibilityFinding> check_mesh_geometry(const Model& m);

// `box`: the housing's outer envelope when known; `housing_height` [m] when known
// (the oil level cannot stand higher above the lowest gear tip).
std::vector<PlausibilityFinding> check_plausibility(const Model& m, Lubrication lubrication,
                                                    const std::optional<HousingBox>& box,
                                                    std::optional<double> housing_height);

// The open clutch packs whose oil film, at one of the input speeds [rad/s] and some oil temperature
// within the oil's validity, heats beyond the range of the heated-film drag model (Nahme number at
// the outer radius above clutch::film_heating_nahme_limit while the film is not broken): one note
// per pack with the oil temperature below which its drag is extrapolated; and one note per open
// pack without an oil_supply (its gap is taken as always full: no breakup, no peak).
std::vector<PlausibilityFinding> check_clutch_film_range(const Model& m, const std::vector<double>& input_speeds);

// The selected churning form against the speed limits of its range (a pitch-line speed, e.g.
// mauz_1987 up to 60 m/s), over the case's input speeds [rad/s]: one note per dipping gear
// outside it, with the span of its pitch-line speed and the range's provenance.
std::vector<PlausibilityFinding> check_churning_speed_range(const Model& m, const std::vector<double>& input_speeds);

// Bearings past SKF's starvation limit (gearloss/bearings/skf_model.hpp, skf_starvation_limit_nu)
// at the model's fixed oil temperature and the input speed omega_in [rad/s] (the case's largest):
// one note for all of them, naming each with its nu n and the limit, and saying that the rolling
// moment is held at its value at the limit. Empty in stabilised mode (the oil temperature is
// known only after the solve) or when no bearing is past the limit.
std::vector<PlausibilityFinding> check_bearing_starvation(const Model& m, double omega_in);

// The meshes whose pitch-point film, at one of the case's (input speed [rad/s], torque [N m])
// points and some oil temperature within the oil's validity and not below the case's coldest oil
// (its fixed oil temperature, else the ambient), is past the turning point of the
// thermal film correction of Gupta et al. (1992) (mesh::gupta_turning_point; a cold, viscous oil
// at speed): one note per mesh with the oil temperature below which its film is extrapolated.
std::vector<PlausibilityFinding> check_mesh_film_range(const Model& m,
                                                       const std::vector<std::pair<double, double>>& points);

// Box of a rectangular housing from its outer surface A = 2(LH + LW + HW), height H
// and length L; nullopt when no positive width fits.
std::optional<HousingBox> housing_box(double area, double height, double length);

}  // namespace gearloss::solver
