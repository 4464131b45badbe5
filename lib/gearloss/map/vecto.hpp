#pragma once
// Torque-loss maps in the VECTO format (EU heavy-duty CO2 tool, .vtlm): per gear, rows
// `Input Speed [rpm],Input Torque [Nm],Torque Loss [Nm]` at the engine side, negative
// input torques (motoring, the gearbox driven from its output) included; VECTO computes
// T_out = (T_in - T_loss) r_gear, so T_loss = P_loss / omega_in > 0 in both directions.
#include <string>
#include <vector>

#include "gearloss/map/map_runner.hpp"
#include "gearloss/map/map_stream.hpp"

namespace gearloss::map {

// The torque axis of a VECTO map: every |T| of `torques` with both signs, and 0, ascending.
std::vector<double> vecto_torque_axis(const std::vector<double>& torques);

// Speed used for a 0 rpm row (the loss torque is its limit there): 1 rpm.
constexpr double kVectoZeroSpeed = 3.14159265358979323846 / 30.0;

struct VectoRow {
    double speed = 0, torque = 0, loss_torque = 0;  // rad/s, N m, N m
};

// Loss torque over speeds x vecto_torque_axis(torques). Throws InputError (naming the point)
// when a point has no thermal equilibrium: a VECTO map cannot have holes.
std::vector<VectoRow> vecto_loss_map(const solver::Model& m, const std::vector<double>& speeds,
                                     const std::vector<double>& torques, const MapOptions& opt);
std::string vecto_csv(const std::vector<VectoRow>& rows);

// The table of vecto_csv(vecto_loss_map(...)) streamed to `write` a block at a time (memory
// does not grow with the table); the same InputError at the first hole in row order.
void write_vecto_table(const solver::Model& m, const std::vector<double>& speeds, const std::vector<double>& torques,
                       const MapOptions& opt, const TextSink& write);

}  // namespace gearloss::map
