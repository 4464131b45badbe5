#pragma once
// Internals of the case loader shared by config.cpp and config_*.cpp: the Loader of the gearbox sections.
#include <map>
#include <numbers>
#include <string>

#include "gearloss/bearings/skf_model.hpp"
#include "gearloss/io/config.hpp"
#include <vector>

namespace gearloss::io::detail {

constexpr double deg = std::numbers::pi / 180.0;

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

// config_options.cpp
void load_options(const YamlNode& n, solver::Model& m);
void load_thermal(const YamlNode& n, solver::ThermalSettings& t);

}  // namespace gearloss::io::detail
