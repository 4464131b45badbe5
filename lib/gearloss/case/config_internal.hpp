#pragma once
// Internals of the case loader shared by config.cpp and config_*.cpp: the Loader of the gearbox sections.
#include <Eigen/Core>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "gearloss/bearings/skf_model.hpp"
#include "gearloss/case/config.hpp"
#include <vector>

namespace gearloss::io::detail {

constexpr double deg = std::numbers::pi / 180.0;

// "file:line:col" of a place in a case, empty when unknown.
std::string located_at(const SourceLocation& at);
// Notes in `out` (when given) that `key` was assumed: `value` (with its unit) because `parent`
// does not give it; `reason` says where the value comes from.
void assume(std::vector<AssumedValue>* out, const YamlNode& parent, std::string key, std::string value,
            std::string reason);
// A number as a case would write it ("0.65", "6.5e-04"): %g.
std::string number_text(double v);
// The bearings' full-film friction mu_ehl the oil does not give (SKF defaults by type and
// base oil): one assumed value per bearing, replacing earlier ones ("bearings.B1.mu_ehl").
void note_bearing_friction(Case& c);

// The settings of the selected forms the case and the oil leave at their defaults
// ("mechanisms.windage.pressure" of free_disk): one assumed value each, replacing earlier ones
// (an oil replaced by --oil may give the mesh's friction pair).
void note_mechanism_settings(Case& c);

// SKF sliding friction pair of a bearing from the oil (or the SKF defaults by type and base oil).
void set_bearing_friction(bearings::BearingSpec& s, const lubricant::Oil& oil);

// Reads the gearbox sections of a case into `model`, resolving names to indices.
struct Loader {
    const YamlNode& root;
    solver::Model& model;
    std::map<std::string, int> shaft_index, gear_index;
    std::map<std::string, geometry::Material> materials;
    std::string base_dir;                              // the case file's folder (bearing_catalogue)
    std::vector<BearingResolution>* resolved = nullptr;  // what `check` prints per bearing
    std::vector<AssumedValue>* assumed = nullptr;  // the values the sections assume (Case::assumed)

    // config_gears.cpp
    int shaft_ref(const YamlNode& n);
    int gear_ref(const YamlNode& n);
    geometry::Material material(const YamlNode& n);
    void load_materials();
    void load_shafts();
    void load_gears();
    void load_meshes();
    // config_bearings.cpp
    void load_bearings();
    void load_seals();
    void load_clutches();
};

// The direction of gravity of `housing.gravity` (docs/config.md): a vector [x, y, z] in the
// housing frame, or an angle in the plane of the mesh angles; a unit vector (config_gears.cpp).
Eigen::Vector3d load_gravity(const YamlNode& n);

// The masses of gears and shafts the case does not give, as derived by the layout (after
// Model::finalise): one assumed value each ("gears.w1.mass", "shafts.II.mass").
void note_weights(Case& c);

// config_options.cpp
void load_options(const YamlNode& n, solver::Model& m);
void load_thermal(const YamlNode& n, solver::ThermalSettings& t, std::vector<AssumedValue>* assumed = nullptr);

}  // namespace gearloss::io::detail
