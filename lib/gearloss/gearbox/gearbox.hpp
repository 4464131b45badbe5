#pragma once
// Gearbox topology (shafts, gears, meshes, bearings, seals), its kinematics
// (speed of every rotating body from the input speed) and the shaft statics
// that turn gear forces into bearing loads.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/bearings/skf_model.hpp"
#include "gearloss/clutch/wet_clutch.hpp"
#include "gearloss/geometry/gear_geometry.hpp"
#include "gearloss/mesh/loss_factor.hpp"
#include "gearloss/core/errors.hpp"

namespace gearloss::gearbox {

struct Shaft {
    std::string name;
    bool fixed = false;         // held by the housing (e.g. a fixed ring gear's mounting)
    // Weight of the shaft (a steel cylinder between its bearings, see shaft_mass in gearbox.cpp):
    // an explicit mass overrides; else diameter and length (both optional) and density.
    std::optional<double> mass;      // kg
    std::optional<double> diameter;  // m; else the largest bore of its support bearings
    std::optional<double> length;    // m; else the span of its support bearings
    double density = 7850;           // kg/m^3
};

struct Gear {
    geometry::GearSpec spec;
    int shaft = -1;
    double position = 0;        // axial position along the shaft [m]
    bool free = false;          // runs on its own bearings, locked only when engaged
    std::optional<double> immersion;  // depth below the oil level [m]; else from the oil level
    int carrier = -1;           // planet gear: the shaft (carrier) its pins sit on
    int planets = 1;            // planet gear: number of identical, equally spaced planets
    // Weight: an explicit mass overrides the disc of the gear's geometry (gear_mass in gearbox.cpp),
    // a bore (or the bearings under a free gear or planet) hollows it; density from spec.material.
    std::optional<double> mass;  // kg, one gear (one planet)
    std::optional<double> bore;  // m
    bool is_planet() const { return carrier >= 0; }
};

struct Mesh {
    std::string name;
    int gear[2] = {-1, -1};
    double angle = 0;           // direction of the line of centres gear0 -> gear1 [rad], y up
    std::optional<double> centre_distance;  // working centre distance when the design fixes it [m]
};

struct Bearing {
    std::string name;
    bearings::BearingSpec spec;  // SI (m); see gearloss/bearings/skf_model.hpp
    int shaft = -1;
    double position = 0;        // axial [m]
    int under_gear = -1;        // >= 0: between this free (or planet) gear and its shaft (or carrier)
    // >= 0: a pilot bearing between two shafts, its outer ring in this shaft (the input shaft's end
    // in the output shaft's hub of a coaxial gearbox): it turns at the difference of the two shafts'
    // speeds. It supports `shaft` in the statics, and its reaction acts with the opposite sign on
    // this shaft at `outer_position`, carried on to this shaft's bearings. -1: the outer ring is in
    // the housing.
    int outer_shaft = -1;
    double outer_position = 0;  // axial position along the outer shaft (each shaft has its own axial frame) [m]
    bool locating = false;      // takes the shaft's axial load
    int multiplicity = 1;       // identical copies running alike (one per planet)
};

struct Seal {
    std::string name;
    int shaft = -1;
    double diameter = 0;        // m
};

// Wet multi-plate clutch that locks a free gear to its shaft; open (dragging) in every
// ratio that does not engage that gear.
struct ClutchPack {
    clutch::WetClutchPack pack;
    int gear = -1;
};

// A ratio of a multi-speed gearbox: its name and the free gears it locks to their shafts.
struct Ratio {
    std::string name;
    std::vector<int> engaged;
};

struct Gearbox {
    std::vector<Shaft> shafts;
    std::vector<Gear> gears;
    std::vector<Mesh> meshes;
    std::vector<Bearing> bearings;
    std::vector<Seal> seals;
    std::vector<ClutchPack> clutches;
    int input_shaft = -1, output_shaft = -1;
    std::vector<int> engaged;   // free gears locked to their shaft in the selected ratio
    std::vector<Ratio> ratios;  // every ratio the case defines, in its order (empty: one fixed train)
    std::optional<double> oil_level;  // y of the oil surface in the housing frame [m]
    // Direction of gravity in the housing frame (x, y in the plane of the mesh angles, y up;
    // z along the shafts), a unit vector; default: down, shafts horizontal.
    Eigen::Vector3d gravity{0.0, -1.0, 0.0};
    double oil_volume = 0;      // m^3
};

// Where the error is in the case description, when one item is to blame: the section
// ("meshes", "bearings", "gears"), the item's name and the key, so a reader can point at
// its line (solver::Issue's convention); empty for the train as a whole.
// The key, when one is named, is the item's own key ("mount"); `where` is the item's place in
// the case file when the model kept it.
struct TopologyError : InputError {
    explicit TopologyError(std::string m, std::string section_ = {}, std::string item_ = {}, std::string key_ = {},
                           const SourceLocation& at = {})
        : InputError(at, std::move(key_), std::move(m)), section(std::move(section_)), item(std::move(item_)) {}
    std::string section, item;
};

// Immutable data derived from the topology: speeds per unit input speed,
// loaded path, geometry of every mesh, bearing loads per unit input torque.
struct Layout {
    struct MeshData {
        geometry::PairGeometry geom;
        double H_V_ohlendorf = 0, H_V_buckingham = 0, H_V_wimmer = 0;
        double L_min = 0, L_mean = 0;
        bool loaded = false;
        int carrier_body = -1;       // body the mesh turns with (planetary); -1 = housing
        int planets = 1;             // load shared by this many identical meshes
        double force_per_Nm = 0;     // tangential force at the working pitch circle, all planets, per N m input
        double rolling_per_W = 0;    // |rolling power| (relative to the carrier) per W of input power
        double relative_speed = 0;   // (omega_gear0 - omega_carrier) / omega_in
        double loss_factor(mesh::LossFactorModel model) const {
            switch (model) {
                case mesh::LossFactorModel::buckingham: return H_V_buckingham;
                case mesh::LossFactorModel::wimmer: return H_V_wimmer;
                case mesh::LossFactorModel::ohlendorf: break;
            }
            return H_V_ohlendorf;
        }
    };
    std::vector<int> body_of_gear, body_of_shaft;
    std::vector<double> body_speed_ratio;   // omega_body / omega_input (signed)
    std::vector<MeshData> meshes;
    std::vector<Eigen::Vector2d> shaft_centre;
    std::vector<double> gear_immersion;     // m (0 = not dipping)
    std::vector<double> bearing_speed_ratio;  // relative ring speed / omega_input (magnitude)
    std::vector<double> seal_speed_ratio;
    std::vector<double> clutch_slip_ratio;  // |omega_gear - omega_shaft| / omega_input of each pack
    // Bearing radial and axial load [N] per N*m of input torque, for positive
    // and negative input torque (the radial separating force does not reverse):
    // the gear forces alone, magnitudes.
    std::vector<double> bearing_Fr_pos, bearing_Fa_pos, bearing_Fr_neg, bearing_Fa_neg;
    // The same as vectors: radial reaction (x, y, housing frame) and signed axial reaction
    // per N*m; for a planet's bearing the vector is in the carrier's frame.
    std::vector<Eigen::Vector2d> bearing_R_pos, bearing_R_neg;
    std::vector<double> bearing_Z_pos, bearing_Z_neg;
    // Reactions to the weights of the gears and shafts [N] (housing frame), and for a planet's
    // bearing the magnitude of its planet's weight, which turns with the carrier.
    std::vector<Eigen::Vector2d> bearing_R_weight;
    std::vector<double> bearing_Z_weight;
    std::vector<double> bearing_W_orbiting;
    // Centrifugal load of planet bearings per (omega_in)^2 [N s^2].
    std::vector<double> bearing_Fcf_per_w2;
    std::vector<double> gear_mass, shaft_mass;  // kg (one planet of a set); shaft 0 without support bearings
    // Radial and axial load of bearing i at input torque T [N m] and input speed omega_in [rad/s]:
    // the gear forces vector-added to the weights, and the planets' centrifugal force.
    struct BearingLoad {
        double Fr = 0, Fa = 0;
    };
    BearingLoad bearing_load(size_t i, double T, double omega_in = 0.0) const;
    double ratio = 0;   // omega_out / omega_in (signed)
    double output_torque_per_Nm = 0;  // ideal (lossless) output torque per N m input, signed
};

Layout analyse(const Gearbox& gb);

}  // namespace gearloss::gearbox
