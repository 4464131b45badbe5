#include "gearloss/case/case_plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <mutex>
#include <set>
#include <variant>

namespace gearloss::io {

namespace {
// A shaft that carries a gear (not a planet: its pins sit on the carrier) but has no support
// bearing turns without bearing losses and with nothing to take its mesh forces: the case
// has left its bearings out. A warning at the shaft (or at 'gears' when no bearing is given).
void warn_unsupported_shafts(const YamlNode& root, Case& c) {
    const auto& gb = c.model.gearbox;
    const auto shaft_node = [&](size_t s) -> std::optional<YamlNode> {
        if (auto sh = root.get("shafts"); sh && sh->is_sequence()) {
            const auto items = sh->items();
            if (s < items.size()) return items[s];
        }
        return std::nullopt;
    };
    if (gb.bearings.empty() && !gb.gears.empty()) {
        c.warnings.push_back(root.at("gears").located(
            "warning: the case has no bearings: no bearing losses are counted and no shaft is supported (add a "
            "'bearings' list)"));
        return;
    }
    for (size_t s = 0; s < gb.shafts.size(); ++s) {
        if (gb.shafts[s].fixed) continue;
        std::string carried;
        for (const auto& g : gb.gears)
            if (g.shaft == static_cast<int>(s) && g.carrier < 0)
                carried += (carried.empty() ? "'" : ", '") + g.spec.name + "'";
        if (carried.empty()) continue;
        const bool supported = std::any_of(gb.bearings.begin(), gb.bearings.end(), [&](const gearbox::Bearing& b) {
            return b.shaft == static_cast<int>(s) && b.under_gear < 0;
        });
        if (supported) continue;
        const std::string what = fmt::format("warning: shaft '{}' carries gear(s) {} but no bearing: its bearing losses "
                                             "are not counted (add its bearings under 'bearings')",
                                             gb.shafts[s].name, carried);
        const auto n = shaft_node(s);
        c.warnings.push_back((n ? *n : root.at("bearings")).located(what));
    }
}
}  // namespace

void check_case_plausibility(const YamlNode& root, Case& c, solver::Lubrication lubrication) {
    const YamlNode housing = root.at("housing");
    // The housing box is known when the heat path is a housing surface with its height and length.
    std::optional<solver::HousingBox> box;
    if (auto hr = root.at("thermal").get("heat_rejection"))
        if (auto hs = hr->get("housing"); hs && hs->has("height") && hs->has("length"))
            if (const auto* s = std::get_if<thermal::HousingSurface>(&c.model.thermal.rejection.model))
                box = solver::housing_box(s->area, s->height, s->length);

    if (auto t = root.at("thermal").get("oil_temperature"))
        if (c.model.thermal.mode == solver::ThermalMode::fixed) {
            const std::string located = t->located("");
            c.oil_temperature_key = located.substr(0, located.size() - 2);  // without the trailing ": "
        }
    std::optional<double> housing_height;
    if (auto hr = root.at("thermal").get("heat_rejection"))
        if (auto hs = hr->get("housing"); hs && hs->has("height"))
            if (const auto* s = std::get_if<thermal::HousingSurface>(&c.model.thermal.rejection.model))
                housing_height = s->height;
    using J = solver::PlausibilityFinding::Subject;
    using S = solver::PlausibilityFinding::Severity;
    const auto gears = root.at("gears").items();
    const auto meshes = root.at("meshes").items();
    auto findings = solver::check_plausibility(c.model, lubrication, box, housing_height);
    std::vector<double> speeds;
    for (size_t i = 0; i < c.grid.size(); ++i) speeds.push_back(c.grid.at(i).first);
    std::sort(speeds.begin(), speeds.end());
    speeds.erase(std::unique(speeds.begin(), speeds.end()), speeds.end());
    for (auto& f : solver::check_clutch_film_range(c.model, speeds)) findings.push_back(std::move(f));
    for (auto& f : solver::check_churning_speed_range(c.model, speeds)) findings.push_back(std::move(f));
    std::vector<std::pair<double, double>> points;
    for (size_t i = 0; i < c.grid.size(); ++i) points.push_back(c.grid.at(i));
    for (auto& f : solver::check_mesh_film_range(c.model, points)) findings.push_back(std::move(f));
    std::vector<YamlNode> clutches;
    if (auto n = root.get("clutches")) clutches = n->items();
    for (const auto& f : findings) {
        // (YamlNode is never assigned: assigning a YAML::Node rebinds the document's data.)
        const auto locate = [&]() -> YamlNode {
            switch (f.subject) {
                case J::oil_level:
                    if (auto n = housing.get("oil_level")) return *n;
                    return housing;
                case J::oil_volume: return housing.at("oil_volume");
                case J::gear:
                    if (f.gear >= 0 && static_cast<size_t>(f.gear) < gears.size()) {
                        const YamlNode& g = gears[static_cast<size_t>(f.gear)];
                        if (auto im = g.get("immersion")) return *im;
                        if (auto lv = housing.get("oil_level")) return *lv;
                        return g;
                    }
                    return housing;
                case J::centre_distance:
                    if (f.mesh >= 0 && static_cast<size_t>(f.mesh) < meshes.size()) {
                        const YamlNode& me = meshes[static_cast<size_t>(f.mesh)];
                        if (auto cd = me.get("centre_distance")) return *cd;
                        return me;
                    }
                    return root.at("meshes");
                case J::tip:
                    if (f.gear >= 0 && static_cast<size_t>(f.gear) < gears.size()) {
                        const YamlNode& g = gears[static_cast<size_t>(f.gear)];
                        if (auto t = g.get("tip_diameter")) return *t;
                        if (auto t = g.get("tip_alteration_factor")) return *t;
                        return g;
                    }
                    return root.at("gears");
                case J::mesh_film:
                    if (f.mesh >= 0 && static_cast<size_t>(f.mesh) < meshes.size()) return meshes[static_cast<size_t>(f.mesh)];
                    return root.at("meshes");
                case J::clutch:
                    if (f.gear >= 0 && static_cast<size_t>(f.gear) < clutches.size()) return clutches[static_cast<size_t>(f.gear)];
                    return housing;
                case J::lubrication:
                    if (auto n = housing.get("lubrication")) return *n;
                    if (auto lv = housing.get("oil_level")) return *lv;
                    return housing;
            }
            return housing;
        };
        const YamlNode where = locate();
        if (f.severity == S::error) where.fail(f.message);
        c.warnings.push_back(where.located((f.severity == S::note ? "note: " : "warning: ") + f.message));
    }
    warn_unsupported_shafts(root, c);
    check_component_sizes(root, c);
}

void check_oil_temperature(Case& c, const std::string& option) {
    const auto& m = c.model;
    // Bearings past SKF's starvation limit at the fixed oil temperature and the grid's largest speed.
    double omega_max = 0;
    for (double w : c.grid.speeds) omega_max = std::max(omega_max, std::abs(w));
    for (const auto& f : solver::check_bearing_starvation(m, omega_max)) {
        const std::string what = "note: " + f.message;
        if (option.empty() && !c.oil_temperature_key.empty()) c.warnings.push_back(c.oil_temperature_key + ": " + what);
        else c.warnings.push_back(InputError::format("", 0, 0, option.empty() ? "thermal.oil_temperature" : option, what));
    }
    if (m.thermal.mode != solver::ThermalMode::fixed) return;
    if (!(m.thermal.oil_temperature > m.oil.max_temperature)) return;
    const std::string what = fmt::format("warning: fixed oil temperature {:.1f} degC is above the permissible {:.1f} degC "
                                         "of oil '{}' (its 'max_temperature')",
                                         m.thermal.oil_temperature - 273.15, m.oil.max_temperature - 273.15, m.oil.name);
    if (option.empty() && !c.oil_temperature_key.empty()) c.warnings.push_back(c.oil_temperature_key + ": " + what);
    else c.warnings.push_back(InputError::format("", 0, 0, option.empty() ? "thermal.oil_temperature" : option, what));
}

void print_warnings(const Case& c) {
    static std::mutex mutex;
    static std::set<std::string> printed;
    const std::lock_guard lock(mutex);
    for (const auto& w : c.warnings)
        if (printed.insert(w).second) std::fprintf(stderr, "gearloss: %s\n", w.c_str());
}

}  // namespace gearloss::io
