#pragma once
// Loss tables for system simulation (`gearloss map --format table`): the losses of every
// ratio x input speed x input torque x oil temperature, each at a FIXED oil temperature (no
// thermal solve), with both torque signs (drive and overrun, as the VECTO table:
// vecto_torque_axis). One long CSV streamed as the map is solved (row order: ratio, oil
// temperature, speed, torque), and the same values as N-D arrays for Simscape-style lookup
// tables (index order [ratio][speed][torque][oil temperature]); docs/tables.md.
#include <string>
#include <vector>

#include "gearloss/case/config.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/map/map_stream.hpp"

namespace gearloss::map {

struct LossTableAxes {
    std::vector<std::string> ratios;        // names of gearbox.ratios ("" for a train without ratios)
    std::vector<double> speeds;             // rad/s, each > 0 (the loss torque is P / omega)
    std::vector<double> torques;            // N m, ascending, both signs and 0
    std::vector<double> oil_temperatures;   // K, ascending
    size_t size() const { return ratios.size() * speeds.size() * torques.size() * oil_temperatures.size(); }
};

// "20,40,60degC" or "293.15 K, 313.15 K": absolute temperatures [K], a unit on the last item
// applying to the items without one; strictly ascending. InputError naming `what` otherwise.
std::vector<double> parse_temperature_list(const std::string& text, const char* what);

// The oil-temperature axis when none is given: 20 degC up to the oil's permissible sump
// temperature (Oil::max_temperature) in steps of 20 K, that temperature last
// (mineral oil, 95 degC: 20, 40, 60, 80, 95 degC).
std::vector<double> default_table_temperatures(const solver::Model& m);

// The axes of a case's table: `ratios` (empty: every ratio of gearbox.ratios, or the case's
// own train), the case's grid speeds (every speed > 0) and its torques with both signs.
// InputError for a point list, a speed <= 0 or an oil temperature outside the oil's validity.
LossTableAxes loss_table_axes(const io::Case& k, std::vector<std::string> ratios, std::vector<double> oil_temperatures);

// The solved table: values in index order [ratio][speed][torque][oil temperature], NaN
// where a point has no value (its status says why).
struct LossTable {
    LossTableAxes axes;
    std::vector<double> ratio_values;          // omega_out / omega_in per ratio (signed)
    std::vector<std::string> columns;          // each mechanism's column ("P_mesh_W"), model order
    std::vector<double> total;                 // W
    std::vector<std::vector<double>> power;    // W, per mechanism
    std::vector<std::string> status;           // "ok", "out_of_range: ..."
    size_t index(size_t ratio, size_t speed, size_t torque, size_t temperature) const {
        return ((ratio * axes.speeds.size() + speed) * axes.torques.size() + torque) * axes.oil_temperatures.size() +
               temperature;
    }
    size_t holes() const;  // points without values
};

// Largest table held for its arrays (the CSV alone would stream any size).
inline constexpr size_t kMaxTablePoints = 10'000'000;

std::string loss_table_csv_header(const solver::Model& m);

// Solves the table on opt.threads (map_stream's blocks, one ratio and oil temperature at a
// time) and streams its CSV rows (no header) to `write` when given.
LossTable run_loss_table(const solver::Model& m, const LossTableAxes& axes, const MapOptions& opt,
                         const TextSink& write = {});

// The table as JSON arrays for N-D lookup tables (docs/tables.md): breakpoints, and per
// quantity (torque_loss_Nm, P_total_W, each P_<mechanism>_W) nested arrays
// [ratio][speed][torque][oil temperature]; null where the point has no value.
std::string loss_table_json(const LossTable& t);

}  // namespace gearloss::map
