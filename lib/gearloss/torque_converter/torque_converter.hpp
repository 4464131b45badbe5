#pragma once
// Hydrodynamic torque converter from its steady characteristic (speed ratio ->
// torque ratio and capacity factor) with a lock-up clutch, and the viscous-fluid
// correction of its efficiency by ANSI/HI 9.6.7 as used for the impeller in seed 003 §3.2.
#include <vector>

namespace gearloss::torque_converter {

// ANSI/HI 9.6.7 (2010) viscosity parameter in its US-unit form (the form verified in
// public code; ANSI/HI 9.6.7-2010, US units): B = 16.5 nu^0.5 H^0.0625 / (Q^0.375 N^0.25), nu [cSt],
// H [ft], Q [gpm], N [rpm]. Inputs here are SI-ish: H [m], Q [m^3/s], N [rad/s].
double hi_viscosity_parameter(double nu_cSt, double head_m, double flow_m3s, double speed_rad_s);
// Efficiency correction C_eta = B^(-0.0547 B^0.69); 1 for B <= 1, B capped at 40 (range of the method).
double hi_efficiency_correction(double B);

struct Characteristic {
    std::vector<double> speed_ratio;   // SR = omega_turbine / omega_pump, ascending, from 0
    std::vector<double> torque_ratio;  // TR = T_turbine / T_pump
    std::vector<double> capacity;      // K = omega_pump / sqrt(T_pump) [rad/s / sqrt(N m)]
};

struct TorqueConverter {
    Characteristic curve;
    double impeller_head = 0;   // best-efficiency head of the impeller as a pump [m]; 0 = no viscous correction
    double impeller_flow = 0;   // best-efficiency flow [m^3/s]
    int lockup_from_gear = 0;   // lock-up clutch closed in this gear and above (1-based; 0 = never)
    double lockup_min_speed = 0;  // and above this turbine speed [rad/s]
};

struct TcState {
    double pump_speed = 0, pump_torque = 0;       // engine side
    double turbine_speed = 0, turbine_torque = 0; // gearbox side (turbine_torque = demand)
    double speed_ratio = 1, torque_ratio = 1, C_eta = 1;
    double loss = 0;        // W, heat into the transmission oil
    bool locked = false;
};

// Operating state for a turbine speed and torque demand (drive: torque > 0). The pump
// does not fall below `idle_speed`: at a standstill (or creeping) it turns at idle, the
// turbine torque exceeding the demand is held by the brakes, and the whole pump power
// that does not reach the turbine heats the oil. In overrun above idle (torque <= 0) the
// converter is taken as coupled (SR 1, no loss); locked, it has no loss.
TcState operate(const TorqueConverter& tc, double turbine_speed, double turbine_torque, double idle_speed,
                double nu_cSt, bool lockup);

}  // namespace gearloss::torque_converter
