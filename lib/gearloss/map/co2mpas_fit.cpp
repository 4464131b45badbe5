#include "gearloss/map/co2mpas_fit.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <numbers>

#include "gearloss/core/errors.hpp"

namespace gearloss::map {

namespace {
constexpr double kRadPerRpm = std::numbers::pi / 30.0;
constexpr double kZeroCelsius = 273.15;  // K

// The map's output side of a sample: CO2MPAS's gear_box_torque (JRC 2019, thermal.py,
// calculate_gear_box_torque: P_out over the input speed in drive, over the output speed in
// overrun) and whether it is the drive branch.
struct OutputSide {
    bool drive = true;
    double torque = 0;  // N m
};
OutputSide output_side(const Co2mpasSample& s) {
    const double w_in = s.speed_in_rpm * kRadPerRpm;
    const double P_out = s.torque_in * w_in - s.loss;
    if (P_out >= 0.0) return {true, P_out / w_in};
    return {false, P_out / (s.speed_ratio * w_in)};
}
}  // namespace

double co2mpas_torque_in(const Co2mpasParameters& p, const Co2mpasSample& s) {
    const OutputSide o = output_side(s);
    if (o.drive) return (o.torque - p.gbp10 * s.speed_in_rpm - p.gbp00) / p.gbp01;
    const double n_out = s.speed_ratio * s.speed_in_rpm;
    return (p.gbp01 * o.torque - p.gbp10 * n_out - p.gbp00) * n_out / s.speed_in_rpm;
}

Co2mpasFitError co2mpas_fit_error(const Co2mpasParameters& p, const std::vector<Co2mpasSample>& samples) {
    Co2mpasFitError e;
    double sum2 = 0, sum2_rel = 0;
    for (const auto& s : samples) {
        const double err = std::abs(co2mpas_torque_in(p, s) - s.torque_in);
        const double loss_torque = s.loss / (s.speed_in_rpm * kRadPerRpm);
        const double rel = err / loss_torque;
        sum2 += err * err;
        sum2_rel += rel * rel;
        e.max_Nm = std::max(e.max_Nm, err);
        e.max_rel = std::max(e.max_rel, rel);
    }
    e.points = samples.size();
    if (e.points) {
        e.rms_Nm = std::sqrt(sum2 / e.points);
        e.rms_rel = std::sqrt(sum2_rel / e.points);
    }
    return e;
}

Co2mpasParameters fit_co2mpas(const std::vector<Co2mpasSample>& samples, const char* what) {
    const Eigen::Index n = static_cast<Eigen::Index>(samples.size());
    if (n < 3) throw InputError("", 0, 0, what, fmt::format("{} points with values: the fit needs at least 3", n));
    Eigen::MatrixXd A(n, 3);
    Eigen::VectorXd b(n);
    // Unknowns x = (gbp00, gbp10, gbp01); rows scaled by `drive_weight` in the drive branch.
    auto solve = [&](double drive_weight) {
        for (Eigen::Index i = 0; i < n; ++i) {
            const auto& s = samples[static_cast<size_t>(i)];
            const OutputSide o = output_side(s);
            if (o.drive) {
                // gbp01 T_in + gbp10 n_in + gbp00 = T_gb  (residual: -gbp01 x the input-torque error)
                A.row(i) << drive_weight, drive_weight * s.speed_in_rpm, drive_weight * s.torque_in;
                b(i) = drive_weight * o.torque;
            } else {
                // k (gbp01 T_gb - gbp10 n_out - gbp00) = T_in, k = n_out / n_in (residual: the error itself)
                const double k = s.speed_ratio, n_out = k * s.speed_in_rpm;
                A.row(i) << -k, -k * n_out, k * o.torque;
                b(i) = s.torque_in;
            }
        }
        // Columns of unit norm: the speed column is ~10^3 times the others.
        const Eigen::Vector3d scale = A.colwise().norm().transpose().cwiseMax(1e-300);
        const Eigen::MatrixXd As = A * scale.cwiseInverse().asDiagonal();
        const auto qr = As.colPivHouseholderQr();
        if (qr.rank() < 3)
            throw InputError("", 0, 0, what,
                             "the points do not determine gbp00, gbp10 and gbp01: give at least two speeds and two torques");
        const Eigen::Vector3d x = qr.solve(b).cwiseQuotient(scale);
        return Co2mpasParameters{x(0), x(1), x(2)};
    };
    const Co2mpasParameters first = solve(1.0);
    if (!(first.gbp01 > 0)) return first;
    return solve(1.0 / first.gbp01);
}

std::vector<Co2mpasSample> co2mpas_samples(const LossTable& t, size_t r, size_t iT) {
    std::vector<Co2mpasSample> out;
    const auto& a = t.axes;
    for (size_t s = 0; s < a.speeds.size(); ++s)
        for (size_t q = 0; q < a.torques.size(); ++q) {
            const double P = t.total[t.index(r, s, q, iT)];
            if (std::isfinite(P)) out.push_back({a.speeds[s] / kRadPerRpm, a.torques[q], P, std::abs(t.ratio_values[r])});
        }
    return out;
}

namespace {
using J = nlohmann::ordered_json;
J parameters_json(const Co2mpasParameters& p) { return {{"gbp00", p.gbp00}, {"gbp10", p.gbp10}, {"gbp01", p.gbp01}}; }
J error_json(const Co2mpasFitError& e) {
    return {{"points", e.points}, {"rms_Nm", e.rms_Nm}, {"max_Nm", e.max_Nm}, {"rms_rel", e.rms_rel}, {"max_rel", e.max_rel}};
}
const char* kPhases[2] = {"cold", "hot"};
}  // namespace

std::string co2mpas_json(const LossTable& t) {
    const auto& a = t.axes;
    if (a.oil_temperatures.size() != 2)
        throw InputError("", 0, 0, "--oil-temps", "the CO2MPAS form takes two reference temperatures (cold, hot)");
    // Per gear and phase, and the whole gearbox per phase.
    std::vector<std::vector<Co2mpasSample>> samples[2];
    std::vector<Co2mpasSample> all[2];
    for (int ph = 0; ph < 2; ++ph)
        for (size_t r = 0; r < a.ratios.size(); ++r) {
            samples[ph].push_back(co2mpas_samples(t, r, static_cast<size_t>(ph)));
            all[ph].insert(all[ph].end(), samples[ph][r].begin(), samples[ph][r].end());
        }
    J j;
    j["format"] = "gearloss-co2mpas/1";
    j["model"] = "CO2MPAS gearbox torque-loss form, CO2MPAS-TA gear_box/thermal.py (_evaluate_gear_box_torque_in)";
    j["units"] = {{"gbp00", "N m"}, {"gbp10", "N m/rpm"}, {"gbp01", "-"}, {"gear_box_temperature_references", "degC"},
                  {"rms_Nm", "N m at the input"}, {"rms_rel", "of the map's loss torque P_loss/omega_in"}};
    j["gear_box_temperature_references"] = {a.oil_temperatures[0] - kZeroCelsius, a.oil_temperatures[1] - kZeroCelsius};
    J whole, whole_error;
    Co2mpasParameters whole_p[2];
    for (int ph = 0; ph < 2; ++ph) {
        whole_p[ph] = fit_co2mpas(all[ph]);
        whole[kPhases[ph]] = parameters_json(whole_p[ph]);
        J e;
        e["all"] = error_json(co2mpas_fit_error(whole_p[ph], all[ph]));
        for (size_t r = 0; r < a.ratios.size(); ++r)
            e[a.ratios[r].empty() ? std::string("ratio") : a.ratios[r]] = error_json(co2mpas_fit_error(whole_p[ph], samples[ph][r]));
        whole_error[kPhases[ph]] = std::move(e);
    }
    j["gear_box_efficiency_parameters_cold_hot"] = std::move(whole);
    j["fit_error"] = std::move(whole_error);
    J gears = J::array();
    for (size_t r = 0; r < a.ratios.size(); ++r) {
        J g;
        g["ratio"] = a.ratios[r];
        g["ratio_value"] = t.ratio_values[r];
        g["gear_box_ratio"] = 1.0 / std::abs(t.ratio_values[r]);  // n_in / n_out, CO2MPAS's gear_box_ratios
        J par, err;
        for (int ph = 0; ph < 2; ++ph) {
            const Co2mpasParameters p = fit_co2mpas(samples[ph][r]);
            par[kPhases[ph]] = parameters_json(p);
            err[kPhases[ph]] = error_json(co2mpas_fit_error(p, samples[ph][r]));
        }
        g["gear_box_efficiency_parameters_cold_hot"] = std::move(par);
        g["fit_error"] = std::move(err);
        gears.push_back(std::move(g));
    }
    j["gears"] = std::move(gears);
    J speeds = J::array();
    for (double w : a.speeds) speeds.push_back(std::round(w / kRadPerRpm * 1e6) / 1e6);
    j["domain"] = {{"speed_in_rpm", speeds}, {"torque_in_Nm", a.torques}, {"points", all[0].size() + all[1].size()},
                   {"points_without_values", t.holes()}};
    return j.dump(2) + "\n";
}

}  // namespace gearloss::map
