#include "module_case.hpp"

#include <filesystem>

#include "gearloss/case/case_plausibility.hpp"
#include "gearloss/map/map_runner.hpp"

namespace gearloss::python {

std::string CaseSource::folder() const {
    return text ? base_dir : std::filesystem::path(path).parent_path().string();
}

io::Case read_case(const CaseSource& s) {
    if (s.text) return io::load_case_text(*s.text, s.name, s.base_dir, s.ratio);
    return io::load_case(s.path, s.ratio);
}

void check_loaded(io::Case& k, const std::string& oil_file, const std::string& oil_temp) {
    map::validate_case(k, {.oil_temp = oil_temp, .oil = oil_file, .grid = false});
    io::check_oil_temperature(k, oil_temp.empty() ? "" : "oil_temp_C");
}

io::Case at_oil_temperature(const PyCase& c, const std::optional<double>& oil_temp_C) {
    io::Case k = c.k;
    if (!oil_temp_C) return k;
    k.warnings.clear();
    k.model.thermal.mode = solver::ThermalMode::fixed;
    k.model.thermal.oil_temperature = *oil_temp_C + kZeroCelsius;
    renaming_keys({{"--oil-temp", "oil_temp_C"}}, [&] { check_loaded(k, c.oil_file, "oil_temp_C"); });
    return k;
}

namespace {
std::vector<double> to_si(const std::vector<double>& v, double factor) {
    std::vector<double> out;
    out.reserve(v.size());
    for (double x : v) out.push_back(x * factor);
    return out;
}
}  // namespace

// A point list with either axis given becomes the grid of its speeds x its torques first.
io::OperatingGrid grid_of(const io::Case& k, const std::optional<std::vector<double>>& speeds_rpm,
                          const std::optional<std::vector<double>>& torques_Nm) {
    io::OperatingGrid g = k.grid;
    if (!speeds_rpm && !torques_Nm) return g;
    if (!g.is_grid) {
        g.is_grid = true;
        for (const auto& [w, T] : g.points) {
            g.speeds.push_back(w);
            g.torques.push_back(T);
        }
        g.points.clear();
    }
    if (speeds_rpm) g.speeds = to_si(*speeds_rpm, kRadSPerRpm);
    if (torques_Nm) g.torques = *torques_Nm;
    return g;
}

void require_values(const std::optional<std::vector<double>>& speeds_rpm,
                    const std::optional<std::vector<double>>& torques_Nm) {
    if (speeds_rpm && speeds_rpm->empty()) throw InputError("", 0, 0, "speeds_rpm", "no speeds given");
    if (torques_Nm && torques_Nm->empty()) throw InputError("", 0, 0, "torques_Nm", "no torques given");
}

}  // namespace gearloss::python
