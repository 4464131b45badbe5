#pragma once
// The complete description of one gearbox case: topology and its derived
// layout, the oil, the loss mechanisms (with their forms, settings and on/off state) and the
// thermal settings.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "gearloss/core/source_index.hpp"
#include "gearloss/gearbox/gearbox.hpp"
#include "gearloss/losses/mechanism_set.hpp"
#include "gearloss/lubricant/oil.hpp"
#include "gearloss/thermal/cooler.hpp"
#include "gearloss/thermal/equilibrium.hpp"
#include "gearloss/thermal/heat_rejection.hpp"
#include "gearloss/thermal/network.hpp"

namespace gearloss::solver {

// Terms of a calibration (`gearloss diagnose`) outside the loss mechanisms: the oil and
// the heat path. (A mechanism's own calibration terms are its parameters:
// `calibration: {churning: {factor: 1.3}}`.) The neutral values leave the model unchanged.
struct Calibration {
    double viscosity_factor = 1;      // scales the kinematic viscosity at every temperature
    double heat_rejection_factor = 1; // scales the heat flow to ambient
    double cooling_per_1000rpm = 0;   // heat flow x (1 + a (n_in/1000 rpm)^q): forced convection from rotation
    // q: the power of speed in that forced convection. Nusselt numbers of forced convection
    // grow as Re^0.5 (laminar boundary layer) to Re^0.8 (turbulent) (Incropera et al. 2007,
    // ch. 7); 1 keeps the cooling linear in speed.
    double cooling_speed_exponent = 1;
    // s: the heat flow's change with the rise dT over ambient of the surface giving the heat away (the
    // oil, or a thermal network's housing node): heat flow x (1 + s (dT - 50 K)/50 K).
    // A housing's coefficient grows with the rise (free convection h ~ dT^0.25 to dT^0.33,
    // radiation; Incropera et al. 2007, ch. 9 and 12) and a rig bed warmed by the box carries
    // less away: a linear law, first order in the rise, with the factor fixed at a 50 K rise.
    double heat_rejection_rise_slope = 0;
    bool neutral() const;
};

enum class ThermalMode { stabilised, fixed };

struct ThermalSettings {
    ThermalMode mode = ThermalMode::stabilised;
    double oil_temperature = 353.15;  // K, fixed mode
    double ambient = 298.15;          // K
    thermal::HeatRejection rejection;
    // External cooler or injection lubrication: a heat path from the oil in parallel with the
    // housing, in the stabilised balance and in the transient alike (thermal.cooler).
    thermal::Cooler cooler;
    thermal::EquilibriumOptions equilibrium;
    double heat_capacity = 0;         // J/K of oil + housing (transient warm-up); 0 = not given
    // Lumped network for transients (a single oil node of heat_capacity unless a network is given).
    thermal::Network network;
};

struct Model {
    std::string name;
    gearbox::Gearbox gearbox;
    gearbox::Layout layout;
    lubricant::Oil oil;
    ThermalSettings thermal;
    Calibration calibration;
    // The loss mechanisms (registry order), with their parameters and forms.
    losses::MechanismSet mechanisms;
    // Where the case wrote each item and key (empty for a model built in code): errors found
    // after loading point at their line through it.
    std::shared_ptr<const SourceIndex> source;
    // Whether the calibration and every mechanism's calibration parameters are neutral.
    bool calibration_neutral() const;
    // Mean entrainment-independent data of each mesh computed once.
    std::vector<double> mesh_E_prime;  // Pa
    void finalise();  // derive layout and per-mesh constants; throws on bad topology
    // The selected one of gearbox.ratios ("" for a train without ratios).
    std::string ratio;
    // Selects a ratio at run time (engages its gears and derives the layout again), so a
    // drive cycle or one loss table per gear reuses one loaded case. The loader checks every
    // ratio; InputError (key gearbox.ratio) for a name that is not one of gearbox.ratios.
    void select_ratio(std::string_view name);
    Model with_ratio(std::string_view name) const;
    std::vector<std::string> ratio_names() const;
    // Oil state with the calibration's viscosity factor applied.
    lubricant::OilState oil_state(double T) const;
    // Steady heat flow out of the oil [W] at oil temperature T_oil: through the housing to
    // ambient (housing_heat_flow) plus the cooler's (cooler_heat_flow).
    double heat_flow(double T_oil, double T_amb, double omega_in) const;
    // Steady heat flow to ambient through the housing [W], with the calibration applied;
    // through the housing node's conductance in series when the network has one.
    double housing_heat_flow(double T_oil, double T_amb, double omega_in) const;
    // Heat removed by the external cooler [W] at oil temperature T_oil (0 without one).
    double cooler_heat_flow(double T_oil) const;
    // d(cooler_heat_flow)/dT at T_oil [W/K] (0 without a cooler or for a fixed duty).
    double cooler_conductance(double T_oil) const;
    // Heat flow [W] leaving the rejecting surface (housing node, or the oil) at T_surface.
    // `air_speed`: air flow over a housing surface imposed from outside (vehicle) [m/s].
    double surface_heat_flow(double T_surface, double T_amb, double omega_in, double air_speed = 0.0) const;
};

}  // namespace gearloss::solver
