#pragma once
// The vehicle around the transmission: road load, final drive, gear ratios and
// shift schedule, engine idle/overrun behaviour and an optional fuel map
// (road load of UN GTR No. 15, F = f0 + f1 v + f2 v^2, plus m_eff a + m g sin(theta)).
#include <optional>
#include <string>
#include <vector>

namespace gearloss::vehicle {

// Bilinear fuel-flow map over engine speed x engine torque, clamped at the edges.
struct FuelMap {
    std::vector<double> speeds;              // rad/s, ascending
    std::vector<double> torques;             // N m, ascending
    std::vector<std::vector<double>> rate;   // kg/s, [speed][torque]
    double rate_at(double omega, double torque) const;
};

struct Engine {
    double idle_speed = 83.776;       // rad/s (800 rpm)
    double overrun_torque = 25.0;     // drag torque available for engine braking [N m] (fuel cut)
    // Limits a drive cycle may not exceed (a cycle beyond them is an error at its row):
    double max_speed = 733.04;        // rad/s (7000 rpm, a passenger-car petrol engine's red line)
    std::optional<double> max_torque; // N m; unchecked when not given
    std::optional<FuelMap> fuel_map;
    double fuel_density = 745.0;      // kg/m^3 (petrol)
    double lower_heating_value = 43e6;  // J/kg
};

// An electric traction motor in place of the engine (a battery-electric drive): no idle speed, no
// fuel; it drives up to its torque and power limits and recuperates (brakes electrically, the
// gearbox then driven from its output) up to its recuperation limits, the friction brakes taking
// the rest. The limits are the usual two-segment envelope of a permanent-magnet machine: constant
// torque up to the base speed max_power / max_torque, constant power above it.
struct Motor {
    double max_speed = 0;            // rad/s
    double max_torque = 0;           // N m, drive
    double max_power = 0;            // W, drive
    double recuperation_torque = 0;  // N m (a magnitude), braking
    double recuperation_power = 0;   // W (a magnitude), braking
    // Largest drive torque and recuperation torque magnitude at speed w [rad/s].
    double drive_limit(double w) const;
    double recuperation_limit(double w) const;
};

struct ShiftSchedule {
    double upshift_speed = 2500 * 3.14159265358979323846 / 30;    // gearbox input [rad/s]
    double downshift_speed = 1200 * 3.14159265358979323846 / 30;
};

struct Vehicle {
    double mass = 1500;               // kg, test mass
    double rotating_mass_factor = 0.03;  // m_eff = m (1 + e)
    double wheel_radius = 0.31;       // dynamic rolling radius [m]
    double f0 = 0, f1 = 0, f2 = 0;    // road load [N], [N s/m], [N s^2/m^2]
    double final_drive = 1.0;         // wheel speed x final_drive = gearbox output speed
    double final_drive_efficiency = 1.0;
    std::vector<std::string> gears;   // gearbox ratio names, first gear first
    ShiftSchedule shift;
    bool torque_converter = false;    // automatic: converter between engine and gearbox
    double underbody_air = 0.0;       // share of the vehicle speed that flows over the housing
    Engine engine;                    // with a motor: idle speed 0, max_speed the motor's, no fuel map
    std::optional<Motor> motor;       // an electric drive instead of the engine

    // Tractive force at the wheels for speed v [m/s] and acceleration a [m/s^2].
    double tractive_force(double v, double a, double grade = 0.0) const;
};

// Gear selection by gearbox input speed with hysteresis: up when the input would exceed
// upshift_speed, down when it falls below downshift_speed. `input_per_wheel` holds
// n_in/n_out of each gear (incl. the final drive) and `gear` the current gear (1-based).
int select_gear(const Vehicle& v, const std::vector<double>& input_per_wheel, double wheel_speed, int gear);

}  // namespace gearloss::vehicle
