#pragma once
// The gearbox loss form of CO2MPAS (JRC 2019, CO2MPAS-TA, co2mpas/core/model/physical/
// gear_box/thermal.py: _evaluate_gear_box_torque_in, calculate_gear_box_torque_in) fitted to a
// loss map (`gearloss map --format co2mpas`; docs/tables.md). CO2MPAS computes the engine-side
// torque from the gearbox's output, speeds in rpm, torques in N m:
//   drive   (T_gb >= 0, T_gb = P_out / omega_in):  T_in = (T_gb - gbp10 n_in - gbp00) / gbp01
//   overrun (T_gb <  0, T_gb = P_out / omega_out): T_in = (gbp01 T_gb - gbp10 n_out - gbp00) n_out / n_in
// so gbp00 [N m] and gbp10 [N m/rpm] are negative for a loss and gbp01 [-] is an efficiency.
// One set for the hot and one for the cold reference temperature (JRC 2019, defaults.py:
// gear_box_temperature_references = (40, 80) degC); between them CO2MPAS interpolates the
// input torque linearly in the oil temperature, above the hot one it uses the hot set.
#include <string>
#include <vector>

#include "gearloss/map/loss_table.hpp"

namespace gearloss::map {

struct Co2mpasParameters {
    double gbp00 = 0;  // N m
    double gbp10 = 0;  // N m / rpm
    double gbp01 = 1;  // -
};

// One point of a map: input speed and torque, the loss, and the speed ratio.
struct Co2mpasSample {
    double speed_in_rpm = 0;  // > 0
    double torque_in = 0;     // N m, signed (< 0: overrun)
    double loss = 0;          // W, P_in - P_out
    double speed_ratio = 1;   // |omega_out / omega_in|
};

// CO2MPAS's input torque for the map's output side of `s` (the branch by the sign of P_out).
double co2mpas_torque_in(const Co2mpasParameters& p, const Co2mpasSample& s);

// Error of the form over samples: e = co2mpas_torque_in - torque_in [N m], relative to the
// map's loss torque P_loss / omega_in of each point.
struct Co2mpasFitError {
    size_t points = 0;
    double rms_Nm = 0, max_Nm = 0;      // of |e|
    double rms_rel = 0, max_rel = 0;    // of |e| / T_loss
};
Co2mpasFitError co2mpas_fit_error(const Co2mpasParameters& p, const std::vector<Co2mpasSample>& samples);

// Least squares (Eigen, column-pivoting QR) on the form made linear in (gbp00, gbp10, gbp01):
// overrun rows are the input-torque error itself, drive rows that error times gbp01, so the
// drive rows are weighted once more by 1/gbp01 of a first solution. Exact on samples of the
// form. InputError (key `what`) when the samples do not determine the three coefficients
// (fewer than two speeds or two torques).
Co2mpasParameters fit_co2mpas(const std::vector<Co2mpasSample>& samples, const char* what = "--format co2mpas");

// The samples of ratio `r` at oil temperature index `iT` of a table (points with values).
std::vector<Co2mpasSample> co2mpas_samples(const LossTable& t, size_t r, size_t iT);

// The fits of a table solved at the cold and hot reference temperatures (axes
// oil_temperatures = {cold, hot}): per gear, and one set for the whole gearbox (CO2MPAS takes
// one per vehicle), with the error of each set on each gear. The JSON of docs/tables.md.
std::string co2mpas_json(const LossTable& t);

}  // namespace gearloss::map
