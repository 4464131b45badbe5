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

namespace {
// The grid of a VECTO table: 0 rpm solved at kVectoZeroSpeed, speeds by magnitude.
io::OperatingGrid vecto_grid(const std::vector<double>& speeds, const std::vector<double>& torques) {
    io::OperatingGrid grid;
    for (double w : speeds) grid.speeds.push_back(w == 0.0 ? kVectoZeroSpeed : std::abs(w));
    grid.torques = vecto_torque_axis(torques);
    return grid;
}

// The row of grid point i, or the InputError of a hole there.
VectoRow vecto_row(const solver::PointResult& r, const io::OperatingGrid& grid, const std::vector<double>& speeds, size_t i) {
    const auto [w, T] = grid.at(i);
    if (!solver::has_values(r.status))
        throw InputError("", 0, 0, "--format vecto",
                         fmt::format("{} at {:.0f} rpm, {:.1f} N m: a VECTO map cannot have holes{}", solver::status_text(r),
                                     w * 30 / std::numbers::pi, T,
                                     r.status == solver::PointStatus::no_equilibrium
                                         ? " (give --oil-temp for a temperature-controlled map)"
                                         : ""));
    VectoRow v;
    v.speed = speeds[i / grid.torques.size()];
    v.torque = T;
    v.loss_torque = r.losses.total() / w;
    return v;
}

void append_row(std::string& s, const VectoRow& r) {
    const double T = r.torque == 0.0 ? 0.0 : r.torque;
    s += fmt::format("{:.2f},{:.2f},{:.4f}\n", std::abs(r.speed) * 30 / 3.14159265358979323846, T, r.loss_torque);
}

constexpr const char* kVectoHeader = "Input Speed [rpm],Input Torque [Nm],Torque Loss [Nm]\n";
}  // namespace

std::vector<VectoRow> vecto_loss_map(const solver::Model& m, const std::vector<double>& speeds,
                                     const std::vector<double>& torques, const MapOptions& opt) {
    const io::OperatingGrid grid = vecto_grid(speeds, torques);
    const auto results = run_map(m, grid, opt);
    io::throw_if_interrupted();  // the points run_map skipped are not holes
    std::vector<VectoRow> rows;
    for (size_t i = 0; i < results.size(); ++i) rows.push_back(vecto_row(results[i], grid, speeds, i));
    return rows;
}

void write_vecto_table(const solver::Model& m, const std::vector<double>& speeds, const std::vector<double>& torques,
                       const MapOptions& opt, const TextSink& write) {
    const io::OperatingGrid grid = vecto_grid(speeds, torques);
    write(kVectoHeader);
    stream_rows(m, grid, 0, grid.size(), opt,
                [&](const solver::PointResult& r, size_t i, std::string& out) { append_row(out, vecto_row(r, grid, speeds, i)); },
                write, nullptr);
}

std::string vecto_csv(const std::vector<VectoRow>& rows) {
    std::string s = kVectoHeader;
    for (const auto& r : rows) {
        if ((&r - rows.data()) % 4096 == 0) io::throw_if_interrupted();
        append_row(s, r);
    }
    return s;
}

}  // namespace gearloss::map
