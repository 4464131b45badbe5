#pragma once
// Transient warm-up of a transmission over a drive cycle: road load -> gear ->
// gearbox input speed and torque (the gearbox losses included by iteration) ->
// torque converter and engine; the lumped thermal network integrated in time with
// Boost.Odeint, every loss evaluated at the current oil temperature. Also the
// pre-warming of the transmission by a heater before the cycle.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/cycle/drive_cycle.hpp"
#include "gearloss/model/model.hpp"
#include "gearloss/thermal/network.hpp"
#include "gearloss/torque_converter/torque_converter.hpp"
#include "gearloss/vehicle/vehicle.hpp"

namespace gearloss::cycle {

struct Powertrain {
    vehicle::Vehicle vehicle;
    std::vector<solver::Model> gears;  // gearbox model of each vehicle gear (first gear first)
    std::optional<torque_converter::TorqueConverter> torque_converter;
    // The oil, thermal network and heat rejection are those of the first gear's model.
    const solver::Model& thermal_model() const { return gears.front(); }
};

struct TraceRow {
    double time = 0, speed = 0, accel = 0;     // s, m/s, m/s^2
    int gear = 0;                              // 0: gearbox at rest (standstill)
    double input_speed = 0, input_torque = 0;  // gearbox input (turbine) [rad/s, N m]
    double engine_speed = 0, engine_torque = 0;
    double T_oil = 0, T_housing = 0, T_clutch = 0;  // K, at the start of the step
    std::vector<double> P_mech;                // W per loss mechanism (the models' order), at T_oil
    double P_gearbox = 0, P_tc = 0;            // W
    double tc_speed_ratio = 1;
    bool lockup = false;
    double fuel_rate = 0;                      // kg/s (0 without a fuel map)
};

struct CycleTotals {
    double duration = 0, distance = 0;         // s, m
    double E_wheel = 0;                        // J, positive tractive energy at the wheels
    double E_gearbox_in = 0, E_gearbox_out = 0;  // J, in drive (positive input power)
    // J, driven from the output (negative input power): what reaches the input (recuperated by a
    // motor) and what the output supplies (that plus the gearbox loss of those rows).
    double E_input_recovered = 0, E_output_supplied = 0;
    std::vector<double> E_mech;                // J per loss mechanism (the models' order)
    double E_tc = 0;                           // J, torque converter
    double E_ambient = 0, E_heater = 0;        // J, heat to the ambient, heater energy
    double stored_start = 0, stored_end = 0;   // J, network heat content relative to ambient
    double fuel = 0;                           // kg
    bool has_fuel = false;
    // Rows whose engine torque lies beyond the engine's fuel map (no `max_torque` given, so not an
    // error): the vehicle could not follow the cycle there and the fuel read at the map's edge is
    // too low. Counted so that the summary can say so; empty without a fuel map.
    struct EngineBeyondData {
        int rows = 0;
        double peak_torque = 0;        // N m, the largest engine torque asked
        double map_torque = 0;         // N m, the fuel map's largest torque
        double peak_time = 0;          // s
        double first_time = 0;         // s, the first such row
        int first_line = 0;            // its line in the cycle file (0: not read from one file)
    } engine_beyond_map;
    thermal::NodeTemperatures start{}, end{};
    double gearbox_loss() const {
        double e = 0.0;
        for (double x : E_mech) e += x;
        return e;
    }
    double mean_efficiency() const { return E_gearbox_in > 0 ? E_gearbox_out / E_gearbox_in : 0.0; }
};

struct CycleResult {
    std::vector<TraceRow> trace;
    CycleTotals totals;
};

// All nodes of the network at temperature T.
thermal::NodeTemperatures uniform(double T);

// With `on_row` the trace's rows are handed to it as they are made, in time order, instead of
// being kept in the result (memory then does not grow with the cycle's length).
CycleResult simulate_cycle(const Powertrain& pt, const DriveCycle& cycle, const thermal::NodeTemperatures& start,
                           double ambient, bool keep_trace = true,
                           const std::function<void(const TraceRow&)>& on_row = {});

struct PrewarmResult {
    bool reached = false;
    double time = 0;           // s to bring the oil to the target
    double energy = 0;         // J of heater energy
    double heat_lost = 0;      // J to the ambient meanwhile
    double max_oil_temperature = 0;  // K, steady value at this heater power (when not reached)
    thermal::NodeTemperatures state{};
};

// Heater of `power` [W] into the oil of the transmission at rest, from `start`, until the
// oil reaches `target` (or `max_time` passes).
PrewarmResult prewarm(const Powertrain& pt, const thermal::NodeTemperatures& start, double target, double power,
                      double ambient, double max_time = 6 * 3600.0);

}  // namespace gearloss::cycle
