#pragma once
// External cooling of the oil: an oil-water or oil-air cooler in a circulation loop, or injection
// lubrication fed from a conditioned tank. A heat path from the oil node in parallel with the
// housing (ISO/TR 14179-2: the heat carried off by an external oil cooler adds to the heat
// dissipated by the housing in the thermal balance). Forms:
//   duty:                  Q = Q_duty (fixed heat removal, e.g. a cooler rated at 20 kW);
//   oil flow, inlet T:     Q = rho c_p V (T_oil - T_inlet) (injection: the oil leaves at the sump
//                          temperature and comes back at T_inlet);
//   UA, coolant T:         Q = UA (T_oil - T_coolant) (a cooler of given conductance);
//   UA, coolant T, flow:   Q = eps rho c_p V (T_oil - T_coolant), eps = 1 - exp(-NTU),
//                          NTU = UA / (rho c_p V): the effectiveness of any exchanger whose other
//                          stream has a far larger capacity rate, C_r -> 0 (Incropera et al. 2007,
//                          Table 11.3, the row C_r = 0);
//   ... and coolant C_c:   a counterflow exchanger with a coolant of capacity rate C_c = m c_p
//                          (T_coolant its inlet): Q = eps C_min (T_oil - T_coolant), C_min and
//                          C_max the smaller and larger of the oil's rho c_p V and C_c, C_r =
//                          C_min/C_max, NTU = UA/C_min, eps = (1 - e^(-NTU(1-C_r))) /
//                          (1 - C_r e^(-NTU(1-C_r))), eps = NTU/(1 + NTU) at C_r = 1 (Incropera et
//                          al. 2007, Table 11.3, counterflow); C_c -> infinity gives the form above.
// An optional thermostatic bypass valve (wax element) sends the oil past the cooler when cold: the
// share through the cooler rises linearly from 0 at `opens` to 1 at `full` (a proportional band,
// assumed linear), so Q is continuous in T_oil and the heat balance keeps a root.
namespace gearloss::thermal {

struct Cooler {
    enum class Kind { none, duty, injection, conductance, exchanger };
    Kind kind = Kind::none;
    double duty = 0;                 // W (Kind::duty)
    double oil_flow = 0;             // m^3/s (injection, exchanger)
    double inlet_temperature = 0;    // K (injection)
    double ua = 0;                   // W/K (conductance, exchanger)
    double coolant_temperature = 0;  // K (conductance, exchanger): the coolant's inlet
    double coolant_capacity_rate = 0;  // W/K (exchanger): the coolant's m c_p; 0: far larger than the oil's
    double valve_opens = 0, valve_full = 0;  // K; valve_full > valve_opens: a thermostatic bypass

    bool present() const { return kind != Kind::none; }
    // Heat removed from the oil [W] at oil temperature T_oil; rho_cp: the oil's volumetric heat
    // capacity rho c_p at T_oil [J/(m^3 K)]. Negative when the return is warmer than the oil.
    double heat_flow(double T_oil, double rho_cp) const;
    // dQ/dT_oil at fixed rho c_p [W/K] (0 for a fixed duty): the conductance the heat-balance
    // bracketing steps with.
    double conductance(double rho_cp) const;
    // Temperature the cooler draws the oil towards (inlet or coolant) [K]; +infinity for none
    // or a fixed duty.
    double cold_side_temperature() const;
    // Share of the oil through the cooler at T_oil: 1 without a thermostat.
    double valve_share(double T_oil) const;
};

}  // namespace gearloss::thermal
