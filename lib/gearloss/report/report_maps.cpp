#include "gearloss/report/report_maps.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "gearloss/io/json_text.hpp"
#include "gearloss/report/html.hpp"
#include "gearloss/report/map_values.hpp"
#include <numbers>

namespace gearloss::report {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRpm = 30.0 / std::numbers::pi;  // rad/s -> rpm

CellState cell_state(solver::PointStatus s) {
    switch (s) {
        case solver::PointStatus::ok: return CellState::value;
        case solver::PointStatus::above_oil_limit: return CellState::above_oil_limit;
        case solver::PointStatus::no_equilibrium: return CellState::no_equilibrium;
        case solver::PointStatus::out_of_range: return CellState::out_of_range;
    }
    return CellState::out_of_range;
}

// A quantity of each result (NaN where the point has no values).
template <class Get>
MapField field_of(const std::vector<solver::PointResult>& rs, std::string title, std::string unit, Get get) {
    MapField f;
    f.title = std::move(title);
    f.unit = std::move(unit);
    for (const auto& r : rs) {
        f.states.push_back(cell_state(r.status));
        f.values.push_back(solver::has_values(r.status) ? get(r) : kNaN);
    }
    return f;
}

double efficiency_percent(const solver::PointResult& r) { return r.has_efficiency ? 100.0 * r.efficiency : kNaN; }

// An efficiency map prints 4 significant digits (97.84 %): 3 would hide most of the map's range.
MapField efficiency_field(MapField f) {
    f.label_digits = 4;
    return f;
}

// Whether mechanism k is 0 W at every point with values of a map.
bool zero_everywhere(const std::vector<solver::PointResult>& rs, size_t k) {
    return std::all_of(rs.begin(), rs.end(), [k](const solver::PointResult& r) {
        return !solver::has_values(r.status) || std::fabs(r.losses.power[k]) <= 1e-9;
    });
}

// The difference oil k - reference of a quantity, point by point; a point without values in
// either map has none (and the state of whichever lacks them).
template <class Get>
MapField difference(const std::vector<solver::PointResult>& ref, const std::vector<solver::PointResult>& k,
                    std::string title, std::string unit, ColourSense sense, Get get) {
    MapField f;
    f.title = std::move(title);
    f.unit = std::move(unit);
    f.sense = sense;
    for (size_t i = 0; i < ref.size(); ++i) {
        const bool a = solver::has_values(ref[i].status), b = solver::has_values(k[i].status);
        f.values.push_back(a && b ? get(k[i]) - get(ref[i]) : kNaN);
        const auto worst = !b ? k[i].status : !a ? ref[i].status : k[i].status == solver::PointStatus::ok ? ref[i].status : k[i].status;
        f.states.push_back(cell_state(worst));
    }
    return f;
}

std::string figure(const MapAxes& axes, MapField f, const std::string& id, const std::string& caption = {}) {
    f.id = id;
    std::string s = "<figure class=\"gl-figure\">" + svg_map(axes, f) + values_table(axes, f);
    if (!caption.empty()) s += "<figcaption>" + caption + "</figcaption>";
    return s + "</figure>\n";
}

// Count, mean, least and greatest of the finite values.
struct Stats {
    size_t n = 0;
    double mean = kNaN, lo = kNaN, hi = kNaN;
};
Stats stats_of(const std::vector<double>& v) {
    Stats s;
    double sum = 0;
    for (double x : v)
        if (std::isfinite(x)) {
            sum += x;
            s.lo = s.n ? std::min(s.lo, x) : x;
            s.hi = s.n ? std::max(s.hi, x) : x;
            ++s.n;
        }
    if (s.n) s.mean = sum / s.n;
    return s;
}

std::string oil_label(const OilMap& m) { return escape_html(m.oil_name) + " <span class=\"gl-muted\">(" + escape_html(m.source) + ")</span>"; }

}  // namespace

MapAxes map_axes(const io::OperatingGrid& grid) {
    MapAxes a;
    a.is_grid = grid.is_grid;
    for (double w : grid.speeds) a.speeds_rpm.push_back(w * kRpm);
    a.torques_Nm = grid.torques;
    for (size_t i = 0; i < grid.size(); ++i) {
        const auto [w, T] = grid.at(i);
        a.points.emplace_back(w * kRpm, T);
    }
    return a;
}

std::string maps_section(const ReportData& d, const MapAxes& axes, const ReportSummary& summary) {
    const auto& rs = d.reference_map.results;
    const auto& m = d.reference_map.model;
    std::string s = "<section id=\"maps\"><h2>Maps over the operating points</h2>\n";
    s += fmt::format("<p>Oil {}; oil temperature {}. Each cell is one computed point, its value printed in the cell (or in "
                     "the table under the picture when the cells are too small; hover a cell for its value and status); "
                     "the colour scales span the values with the outer 2&#160;% clipped.</p>\n",
                     oil_label(d.reference_map), escape_html(d.thermal));
    s += "<div class=\"gl-grid\">";
    s += figure(axes, efficiency_field(field_of(rs, "efficiency", "%", efficiency_percent)), "map-efficiency");
    const std::string t_title = d.fixed_oil_temperature ? "oil temperature, " + d.thermal : "stabilised oil temperature";
    const std::string t_caption =
        d.fixed_oil_temperature
            ? "The oil temperature is fixed (no thermal solve): every point is at the same temperature."
            : "The temperature at which the losses equal the heat the housing rejects. Hatched: no such equilibrium "
              "below the solver's limit (the gearbox would keep heating up at that point).";
    s += figure(axes, field_of(rs, t_title, "degC", [](const auto& r) { return r.oil_temperature - 273.15; }),
                "map-oil-temperature", escape_html(t_caption));
    s += figure(axes, field_of(rs, "total loss", "W", [](const auto& r) { return r.losses.total(); }), "map-total-loss");
    s += "</div>\n<h3>Loss breakdown per mechanism</h3>\n";
    if (const std::string z = zero_mechanisms_line(d, summary); !z.empty())
        s += "<p class=\"gl-zero\">Not drawn, zero at every point: " + z + ".</p>\n";
    s += "<div class=\"gl-grid\">";
    for (size_t k : summary.split_mechanisms) {
        const auto& mech = m.mechanisms[k];
        const std::string title = fmt::format("{} loss ({})", mech.label(), mech.column());
        s += figure(axes, field_of(rs, title, "W", [k](const auto& r) { return r.losses.power[k]; }),
                    fmt::format("map-loss-{}", mech.name()),
                    mech.enabled() ? "" : "switched off in this case (options.losses)");
    }
    s += "</div></section>\n";
    return s;
}

std::string spread_section(const ReportData& d, const MapAxes& axes) {
    std::string s = "<section id=\"spread\"><h2>Model-form spread</h2>\n";
    if (!d.spread) {
        s += "<p class=\"gl-note\">" + escape_html(d.spread_note.empty() ? "not computed" : d.spread_note) + "</p></section>\n";
        return s;
    }
    const auto& sp = *d.spread;
    std::string list;
    for (const auto& a : sp.axes) {
        std::string forms;
        for (const auto& f : a.forms) forms += (forms.empty() ? "" : ", ") + (f == a.nominal ? "<b>" + escape_html(f) + "</b>" : escape_html(f));
        list += "<li><code>" + escape_html(a.label()) + "</code>: " + forms + "</li>";
    }
    s += fmt::format("<p>The same map solved with each of the {} combinations of the mechanisms' alternative forms "
                     "(as <code>gearloss map --spread</code>); the case's forms in bold:</p><ul>{}</ul>\n",
                     sp.combinations, list);
    if (!sp.note.empty()) s += "<p class=\"gl-note\">" + escape_html(sp.note) + "</p>\n";
    const auto& rs = d.reference_map.results;
    MapField band, rel;
    band.title = "spread band of the total loss (max - min over the forms)";
    band.unit = "W";
    rel.title = "spread band relative to the case's total loss";
    rel.unit = "%";
    for (size_t i = 0; i < rs.size(); ++i) {
        const auto& p = sp.result.points[i];
        const bool has = p.solved > 0;
        const double w = has ? p.P_max - p.P_min : kNaN;
        const double P = solver::has_values(rs[i].status) ? rs[i].losses.total() : kNaN;
        band.values.push_back(w);
        rel.values.push_back(has && P > 0 ? 100.0 * w / P : kNaN);
        const auto st = has ? cell_state(rs[i].status) : solver::has_values(rs[i].status) ? CellState::no_equilibrium : cell_state(rs[i].status);
        band.states.push_back(st);
        rel.states.push_back(st);
    }
    s += "<div class=\"gl-grid\">" + figure(axes, band, "map-spread-band") + figure(axes, rel, "map-spread-relative") + "</div>\n";
    const Stats st = stats_of(rel.values);
    if (st.n)
        s += fmt::format("<p>Relative band over {} points: mean {} %, largest {} %.</p>\n", st.n, display_number(st.mean, 3),
                         display_number(st.hi, 3));
    return s + "</section>\n";
}

std::string comparison_section(const ReportData& d, const MapAxes& axes) {
    std::string s = "<section id=\"oils\"><h2>Oil comparison</h2>\n";
    if (d.comparisons.empty()) {
        s += "<p class=\"gl-note\">No other oil: give <code>--oil FILE</code> (once per oil) or a case with an oil "
             "sweep to compare oils.</p></section>\n";
        return s;
    }
    const auto& ref = d.reference_map;
    s += "<p>Differences are <b>oil k &#8722; reference</b> (" + oil_label(ref) +
         ") at each point: a positive loss or temperature difference is worse (<span class=\"gl-worse\">red</span>), "
         "a positive efficiency difference better (<span class=\"gl-better\">blue</span>); the same colours on every "
         "picture.</p>\n";
    s += "<table class=\"gl-table\"><thead><tr><th>oil k</th><th>&#957;40 [cSt]</th><th>&#957;100 [cSt]</th>"
         "<th>points compared</th><th>mean &#916;P [W]</th><th>&#916;P range [W]</th><th>mean &#916;&#951; [points of %]</th>"
         "</tr></thead><tbody>";
    const auto row = [&](const OilMap& k, bool is_ref) {
        const auto s40 = k.model.oil.state(313.15), s100 = k.model.oil.state(373.15);
        std::string cells = fmt::format("<td>{}{}</td><td>{}</td><td>{}</td>", oil_label(k), is_ref ? " (reference)" : "",
                                        display_number(s40.nu_cSt), display_number(s100.nu_cSt));
        if (is_ref) return "<tr>" + cells + "<td colspan=\"4\"></td></tr>";
        const auto dP = difference(ref.results, k.results, "", "", ColourSense::higher_is_worse, [](const auto& r) { return r.losses.total(); });
        const auto de = difference(ref.results, k.results, "", "", ColourSense::higher_is_better, efficiency_percent);
        const Stats a = stats_of(dP.values), b = stats_of(de.values);
        return "<tr>" + cells +
               fmt::format("<td>{}</td><td>{}</td><td>{} &#8230; {}</td><td>{}</td></tr>", a.n, display_number(a.mean),
                           display_number(a.lo), display_number(a.hi), display_number(b.mean, 3));
    };
    s += row(ref, true);
    for (const auto& k : d.comparisons) s += row(k, false);
    s += "</tbody></table>\n";
    for (size_t j = 0; j < d.comparisons.size(); ++j) {
        const auto& k = d.comparisons[j];
        const std::string name = k.oil_name;
        s += fmt::format("<h3>{} &#8722; {}</h3>\n<div class=\"gl-grid\">", oil_label(k), oil_label(ref));
        s += figure(axes, difference(ref.results, k.results, "total loss difference " + name + " - " + ref.oil_name, "W",
                                     ColourSense::higher_is_worse, [](const auto& r) { return r.losses.total(); }),
                    fmt::format("map-oil{}-dP", j + 1));
        if (!d.fixed_oil_temperature)
            s += figure(axes, difference(ref.results, k.results, "oil temperature difference " + name + " - " + ref.oil_name,
                                         "K", ColourSense::higher_is_worse, [](const auto& r) { return r.oil_temperature; }),
                        fmt::format("map-oil{}-dT", j + 1));
        s += figure(axes, efficiency_field(difference(ref.results, k.results, "efficiency difference " + name + " - " + ref.oil_name,
                                                  "points of %", ColourSense::higher_is_better, efficiency_percent)),
                    fmt::format("map-oil{}-deta", j + 1));
        s += "</div>\n<details><summary>loss difference per mechanism</summary><div class=\"gl-grid\">";
        std::string zero;
        for (size_t q = 0; q < ref.model.mechanisms.size(); ++q) {
            const auto& mech = ref.model.mechanisms[q];
            if (zero_everywhere(ref.results, q) && zero_everywhere(k.results, q)) {
                zero += (zero.empty() ? "" : "; ") + escape_html(mech.label()) + ": 0 W everywhere with both oils";
                continue;
            }
            s += figure(axes, difference(ref.results, k.results, fmt::format("{} loss difference ({})", mech.label(), mech.column()),
                                         "W", ColourSense::higher_is_worse, [q](const auto& r) { return r.losses.power[q]; }),
                        fmt::format("map-oil{}-d-{}", j + 1, mech.name()));
        }
        s += "</div>";
        if (!zero.empty()) s += "<p class=\"gl-zero\">Not drawn: " + zero + ".</p>";
        s += "</details>\n";
    }
    return s + "</section>\n";
}

nlohmann::ordered_json map_columns(const OilMap& m) {
    using nlohmann::ordered_json;
    const auto& rs = m.results;
    const auto column = [&](auto get) {
        ordered_json a = ordered_json::array();
        for (const auto& r : rs) {
            const double v = get(r);
            a.push_back(io::json_number(v));
        }
        return a;
    };
    const auto with_values = [](auto get) {
        return [get](const solver::PointResult& r) { return solver::has_values(r.status) ? get(r) : kNaN; };
    };
    ordered_json j;
    j["speed_in_rpm"] = column([](const auto& r) { return r.speed_in * kRpm; });
    j["torque_in_Nm"] = column([](const auto& r) { return r.torque_in; });
    j["oil_temp_C"] = column(with_values([](const auto& r) { return r.oil_temperature - 273.15; }));
    for (size_t k = 0; k < m.model.mechanisms.size(); ++k)
        j[std::string(m.model.mechanisms[k].column())] = column(with_values([k](const auto& r) { return r.losses.power[k]; }));
    j["P_total_W"] = column(with_values([](const auto& r) { return r.losses.total(); }));
    j["efficiency"] = column(with_values([](const auto& r) { return r.has_efficiency ? r.efficiency : kNaN; }));
    ordered_json status = ordered_json::array();
    for (const auto& r : rs) status.push_back(solver::status_text(r));
    j["status"] = std::move(status);
    return j;
}

}  // namespace gearloss::report
