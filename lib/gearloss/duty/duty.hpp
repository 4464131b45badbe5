#pragma once
// What a gearbox loses over its duty (gearloss duty): a time-at-level spectrum solved bin by bin
// at each bin's stabilised oil temperature (or the fixed one of the case or --oil-temp), or a time
// series integrated in time from a start temperature with the thermal network of the drive-cycle
// warm-up (gearloss/cycle/transient.hpp). Energies per mechanism, the energy-weighted efficiency,
// and what runs above the oil's permissible temperature.
//
// Power flow and efficiency: a positive input power (drive) enters at the input, P_in - P_loss
// leaves at the output; a negative one (the gearbox driven from its output: recuperation, a
// motoring generator) enters at the output as |P_in| + P_loss and |P_in| leaves at the input,
// as the map's efficiency column counts it (docs/tables.md). Losses are positive either way. The
// energy-weighted efficiency is the energy delivered over the energy supplied, summed over
// both directions: eta = sum(E_delivered) / sum(E_supplied) = 1 - E_loss / sum(E_supplied).
#include <string>
#include <vector>

#include "gearloss/duty/spectrum.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::duty {

// One bin (time at level) or one interval between samples (time series, the load of its first
// sample held over it).
struct DutyRow {
    int line = 0;                      // of the bin or of the interval's first sample
    double time = 0;                   // s, start of the interval (series)
    double speed = 0, torque = 0;      // rad/s, N m (input)
    double duration = 0;               // s
    double oil_temperature = 0;        // K: stabilised or fixed (bins), at the interval's start (series)
    std::vector<double> power;         // W per mechanism (bins: at the bin's oil; series: at the interval's start)
    std::vector<double> energy;        // J per mechanism over the row
    double efficiency = 0;             // in the power flow's direction; NaN at no power
    bool above_oil_limit = false;      // bins: stabilised above the limit; series: the oil above it during the row
    double E_supplied = 0, E_delivered = 0;  // J
};

struct DutyResult {
    SpectrumKind kind = SpectrumKind::time_at_level;
    bool transient = false;            // series integrated in time (false: at a fixed oil temperature)
    std::vector<std::string> mechanisms;  // names, the model's order
    std::vector<std::string> power_columns;  // their CSV columns in a map ("P_mesh_W")
    std::vector<DutyRow> rows;
    std::vector<double> E_mech;        // J per mechanism
    double duration = 0;               // s
    double E_supplied = 0, E_delivered = 0;  // J
    double oil_limit = 0;              // K, the oil's permissible temperature
    int bins_above_limit = 0;
    double time_above_limit = 0;       // s
    double T_oil_min = 0, T_oil_max = 0, T_oil_end = 0;  // K
    double ambient = 0, start_temperature = 0;           // K
    double E_ambient = 0;              // J, heat to the ambient (transient series)
    double stored_change = 0;          // J, heat stored in the network at the end less at the start
    double loss() const {
        double e = 0;
        for (double x : E_mech) e += x;
        return e;
    }
    double efficiency() const;         // energy-weighted, NaN without energy supplied
};

// The largest |speed| of the case's operating grid [rad/s]: a spectrum faster than the case was
// set up for is refused at its row (the case's grid states the range its author checked).
double grid_max_speed(const io::OperatingGrid& g);

// Time at level: each bin solved as `gearloss map` solves a point (solver::solve_point); a bin
// with no stable oil temperature or out of the model's range is an InputError at its line.
DutyResult run_time_at_level(const io::Case& k, const Spectrum& s);
// Time series: the oil from `start_temperature` (every node) integrated in time at `ambient`;
// with a fixed oil temperature (the case's or --oil-temp) the losses at that temperature.
DutyResult run_time_series(const io::Case& k, const Spectrum& s, double start_temperature, double ambient);

}  // namespace gearloss::duty
