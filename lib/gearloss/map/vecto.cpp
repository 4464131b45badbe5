#include "gearloss/map/vecto.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/interrupt.hpp"

namespace gearloss::map {

std::vector<double> vecto_torque_axis(const std::vector<double>& torques) {
    std::vector<double> axis = {0.0};
    for (double t : torques)
        if (t != 0.0) {
            axis.push_back(std::abs(t));
            axis.push_back(-std::abs(t));
        }
    std::sort(axis.begin(), axis.end());
    axis.erase(std::unique(axis.begin(), axis.end()), axis.end());
    return axis;
}

std::vector<VectoRow> vecto_loss_map(const solver::Model& m, const std::vector<double>& speeds,
                                     const std::vector<double>& torques, const MapOptions& opt) {
    io::OperatingGrid grid;
    for (double w : speeds) grid.speeds.push_back(w == 0.0 ? kVectoZeroSpeed : std::abs(w));
    grid.torques = vecto_torque_axis(torques);
    const auto results = run_map(m, grid, opt);
    io::throw_if_interrupted();  // the points run_map skipped are not holes
    std::vector<VectoRow> rows;
    for (size_t i = 0; i < results.size(); ++i) {
        const auto& r = results[i];
        const auto [w, T] = grid.at(i);
        if (!solver::has_values(r.status))
            throw InputError("", 0, 0, "--format vecto",
                             fmt::format("{} at {:.0f} rpm, {:.1f} N m: a VECTO map cannot have holes{}",
                                         solver::status_text(r), w * 30 / std::numbers::pi, T,
                                         r.status == solver::PointStatus::no_equilibrium
                                             ? " (give --oil-temp for a temperature-controlled map)"
                                             : ""));
        VectoRow v;
        v.speed = speeds[i / grid.torques.size()];
        v.torque = T;
        v.loss_torque = r.losses.total() / w;
        rows.push_back(v);
    }
    return rows;
}

std::string vecto_csv(const std::vector<VectoRow>& rows) {
    std::string s = "Input Speed [rpm],Input Torque [Nm],Torque Loss [Nm]\n";
    for (const auto& r : rows) {
        if ((&r - rows.data()) % 4096 == 0) io::throw_if_interrupted();
        const double T = r.torque == 0.0 ? 0.0 : r.torque;
        s += fmt::format("{:.2f},{:.2f},{:.4f}\n", std::abs(r.speed) * 30 / 3.14159265358979323846, T, r.loss_torque);
    }
    return s;
}

}  // namespace gearloss::map
