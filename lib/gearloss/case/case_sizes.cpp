// Sizes of parts against each other that no single key can judge: a bearing far from every
// gear of its shaft, a seal much larger or smaller than the bearings of its shaft, a sump far
// beyond the gears it wets. Each has been typed by mistake (a unit slip: `-60 km`, `1 m`,
// `800 m^3`) and each was read silently before, giving loads, seal drag or churning of a
// different machine. Bounds are wide (an error is a size no gearbox has); a size that is only
// unusual is a warning.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/case/case_plausibility.hpp"

namespace gearloss::io {

namespace {
// Reference diameter z m_n / cos(beta) [m].
double reference_diameter(const gearbox::Gear& g) { return g.spec.z * g.spec.mn / std::cos(g.spec.beta); }

std::string mm(double x) { return fmt::format("{:.4g} mm", x * 1e3); }

// The model's bearing read from YAML item `item` (its copies of `count` carry ".1", ".2").
const gearbox::Bearing* bearing_named(const gearbox::Gearbox& gb, const std::string& name) {
    for (const auto& b : gb.bearings)
        if (b.name == name || b.name == name + ".1") return &b;
    return nullptr;
}
}  // namespace

void check_component_sizes(const YamlNode& root, Case& c) {
    const auto& gb = c.model.gearbox;
    double largest_gear = 0;
    for (const auto& g : gb.gears) largest_gear = std::max(largest_gear, reference_diameter(g));

    // Bearings: axially within reach of the gears of their shaft. A shaft is rarely longer than a
    // few of its largest gear diameters; 20 of them (and at least 2 m) is no gearbox.
    if (auto list = root.get("bearings"))
        for (const auto& n : list->items()) {
            if (!n.has("position") || n.has("under_gear")) continue;
            const auto* b = bearing_named(gb, n.at("name").as_string());
            if (!b) continue;
            double nearest = INFINITY, scale = std::max(b->spec.D, largest_gear);
            for (const auto& g : gb.gears)
                if (g.shaft == b->shaft && !g.is_planet()) {
                    nearest = std::min(nearest, std::abs(g.position - b->position));
                    scale = std::max(scale, reference_diameter(g));
                }
            const double limit = std::max(2.0, 20.0 * scale);
            if (std::isfinite(nearest) ? nearest > limit : std::abs(b->position) > limit)
                n.at("position").fail(fmt::format(
                    "bearing '{}' at {} lies {} from the nearest gear of its shaft; no shaft is that long (at most {}, "
                    "20 x the largest gear or bearing diameter): check the unit",
                    n.at("name").as_string(), mm(b->position), mm(std::isfinite(nearest) ? nearest : std::abs(b->position)), mm(limit)));
        }

    // Seals: a radial lip seal runs on the shaft, whose diameter lies near the bore of its
    // bearings; its housing bore is rarely larger than theirs.
    const auto items = root.get("seals") ? root.at("seals").items() : std::vector<YamlNode>{};
    for (size_t i = 0; i < gb.seals.size() && i < items.size(); ++i) {
        const auto& s = gb.seals[i];
        double bore_min = INFINITY, outer_max = 0;
        for (const auto& b : gb.bearings)
            if (b.shaft == s.shaft && b.under_gear < 0) {
                bore_min = std::min(bore_min, b.spec.d);
                outer_max = std::max(outer_max, b.spec.D);
            }
        if (!(outer_max > 0)) continue;  // no bearing on that shaft to compare with (warned elsewhere)
        const YamlNode d = items[i].at("diameter");
        const std::string which = fmt::format("seal '{}' of {} on shaft '{}', whose bearings have bores from {} and outer "
                                              "diameters up to {}",
                                              s.name, mm(s.diameter), gb.shafts[s.shaft].name, mm(bore_min), mm(outer_max));
        if (s.diameter > 3 * outer_max || s.diameter < 0.3 * bore_min)
            d.fail(which + ": a lip seal runs on the shaft, near its bearings' bore; check the unit");
        if (s.diameter > outer_max || s.diameter < 0.6 * bore_min)
            c.warnings.push_back(d.located("warning: " + which + ": a lip seal is usually between about the bearing bore "
                                           "and its outer diameter (its drag grows with the diameter)"));
    }

    // Sump: against the space the gears sweep (pi/4 d^2 b each). Shipped cases hold 0.2-3 times
    // it (the wind turbine's is jet-lubricated); 1000 times is a tank, not a sump.
    if (auto h = root.get("housing"); h && h->has("oil_volume")) {
        double swept = 0;
        for (const auto& g : gb.gears) {
            const double d = reference_diameter(g);
            swept += std::numbers::pi / 4 * d * d * g.spec.b * std::max(1, g.planets);
        }
        const double V = gb.oil_volume;
        if (swept > 0 && V > 1000 * swept)
            h->at("oil_volume").fail(fmt::format("oil volume {:.4g} L is {:.0f} times the space the gears sweep ({:.3g} L); "
                                                 "a gearbox sump holds a few times it: check the unit",
                                                 V * 1e3, V / swept, swept * 1e3));
        if (swept > 0 && V > 100 * swept)
            c.warnings.push_back(h->at("oil_volume").located(
                fmt::format("warning: oil volume {:.4g} L is {:.0f} times the space the gears sweep ({:.3g} L)", V * 1e3,
                            V / swept, swept * 1e3)));
    }
}

}  // namespace gearloss::io
