#include "gearloss/report/report_summary.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>

#include "gearloss/report/html.hpp"

namespace gearloss::report {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRpm = 30.0 / std::numbers::pi;  // rad/s -> rpm
// A mechanism whose loss stays within this at every point is "0 W everywhere" [W].
constexpr double kZeroLoss = 1e-9;

double celsius(double K) { return K - 273.15; }

KeyPoint key_point(const std::string& role, const solver::PointResult& r, size_t i) {
    KeyPoint k;
    k.role = role;
    k.index = i;
    k.speed_rpm = r.speed_in * kRpm;
    k.torque_Nm = r.torque_in;
    k.power_in_W = r.power_in;
    k.efficiency = r.has_efficiency ? r.efficiency : kNaN;
    k.oil_temp_C = celsius(r.oil_temperature);
    k.total_W = r.losses.total();
    k.above_oil_limit = r.status == solver::PointStatus::above_oil_limit;
    return k;
}

// The index of the point with values that maximises `better(a, b)` order; n when none.
template <class Better>
size_t best_of(const std::vector<solver::PointResult>& rs, Better better, bool need_efficiency) {
    size_t at = rs.size();
    for (size_t i = 0; i < rs.size(); ++i) {
        if (!solver::has_values(rs[i].status) || (need_efficiency && !rs[i].has_efficiency)) continue;
        if (at == rs.size() || better(rs[i], rs[at])) at = i;
    }
    return at;
}

// A speed or a torque as the case would write it ("500", "1234.5", "0").
std::string plain(double v) { return fmt::format("{:.6g}", v); }

std::string kW(double W) { return display_number(W / 1000.0, 4) + "&#160;kW"; }

std::string degC(double C) { return display_number(C, 3) + "&#160;&#176;C"; }

std::string percent(double fraction) { return std::isfinite(fraction) ? fmt::format("{:.2f}&#160;%", 100.0 * fraction) : "&#8211;"; }

std::string oil_label(const OilMap& m) { return escape_html(m.oil_name) + " <span class=\"gl-muted\">(" + escape_html(m.source) + ")</span>"; }

std::string ratio_text(const ReportData& d, const ReportSummary& s) {
    if (!std::isfinite(s.ratio_i) || s.ratio_i == 0) return "&#8211;";
    std::string t = fmt::format("i = n<sub>in</sub>/n<sub>out</sub> = <b>{}</b>", display_number(std::fabs(s.ratio_i), 4));
    std::string notes;
    if (!s.ratio_name.empty()) notes += "ratio '" + escape_html(s.ratio_name) + "'; ";
    notes += "n<sub>out</sub>/n<sub>in</sub> = " + display_number(d.reference.model.layout.ratio, 6);
    if (s.ratio_i < 0) notes += "; the output turns against the input";
    return t + " <span class=\"gl-muted\">(" + notes + ")</span>";
}

std::string grid_text(const ReportData& d, const ReportSummary& s) {
    const auto& g = d.reference.grid;
    std::string t = fmt::format("{}", g.size());
    if (g.is_grid && !g.speeds.empty() && !g.torques.empty()) {
        const auto [s0, s1] = std::minmax_element(g.speeds.begin(), g.speeds.end());
        const auto [t0, t1] = std::minmax_element(g.torques.begin(), g.torques.end());
        t += fmt::format(" ({} speeds &#215; {} torques: {}&#8230;{}&#160;rpm, {}&#8230;{}&#160;N&#183;m)", g.speeds.size(),
                         g.torques.size(), plain(*s0 * kRpm), plain(*s1 * kRpm), plain(*t0), plain(*t1));
    } else {
        t += " (point list)";
    }
    t += fmt::format("; {} with values", s.with_values);
    if (s.no_equilibrium) t += fmt::format(", {} without equilibrium", s.no_equilibrium);
    if (s.out_of_range) t += fmt::format(", {} out of range", s.out_of_range);
    if (s.above_limit) t += fmt::format(", {} above the oil's limit", s.above_limit);
    return t;
}

std::string thermal_limit_text(const ReportSummary& s) {
    std::string t = "the oil's permissible sump temperature <b>" + degC(s.oil_limit_C) + "</b>: ";
    if (s.above_limit == 0 && s.no_equilibrium == 0) {
        if (s.with_values == 0) return t + "no point with values";
        t += fmt::format("every point below it (highest oil temperature {}, {} below the limit)", degC(s.oil_temp_max_C),
                         display_number(s.oil_limit_C - s.oil_temp_max_C, 3) + "&#160;K");
        return t;
    }
    std::vector<std::string> parts;
    if (s.above_limit) parts.push_back(fmt::format("{} point{} above it", s.above_limit, s.above_limit == 1 ? "" : "s"));
    if (s.no_equilibrium)
        parts.push_back(fmt::format("{} point{} without a thermal equilibrium (the gearbox keeps heating up)", s.no_equilibrium,
                                    s.no_equilibrium == 1 ? "" : "s"));
    for (size_t i = 0; i < parts.size(); ++i) t += (i ? "; " : "") + parts[i];
    if (std::isfinite(s.lowest_beyond_W)) t += "; from " + kW(s.lowest_beyond_W) + " input power";
    if (std::isfinite(s.highest_admissible_W)) t += "; highest admissible point " + kW(s.highest_admissible_W);
    return t;
}

std::string key_points_table(const ReportData& d, const ReportSummary& s) {
    const auto& m = d.reference_map.model;
    const auto& rs = d.reference_map.results;
    if (s.key_points.empty()) return "<p class=\"gl-warn\">No operating point has values (see the maps' legends).</p>\n";
    std::string h = "<table class=\"gl-table gl-keypoints\"><thead><tr><th>point</th><th>speed [rpm]</th><th>torque [N&#183;m]</th>"
                    "<th>input power [kW]</th><th>efficiency</th><th>oil temperature [&#176;C]</th><th>total loss [W]</th>";
    for (size_t k : s.split_mechanisms)
        h += "<th data-column=\"" + escape_html(m.mechanisms[k].column()) + "\">" + escape_html(m.mechanisms[k].label()) + " [W]</th>";
    h += "</tr></thead><tbody>";
    for (const auto& p : s.key_points) {
        const auto& r = rs[p.index];
        h += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td><b>{}</b></td><td>{}{}</td><td><b>{}</b></td>",
                         escape_html(p.role), plain(p.speed_rpm), plain(p.torque_Nm),
                         display_number(p.power_in_W / 1000.0, 4), percent(p.efficiency), display_number(p.oil_temp_C, 3),
                         p.above_oil_limit ? " <span class=\"gl-warn\">(above the oil's limit)</span>" : "",
                         display_number(p.total_W, 4));
        for (size_t k : s.split_mechanisms) {
            const double P = r.losses.power[k];
            h += fmt::format("<td>{} <span class=\"gl-muted\">({:.1f}&#160;%)</span></td>", display_number(P, 4),
                             p.total_W > 0 ? 100.0 * P / p.total_W : 0.0);
        }
        h += "</tr>";
    }
    return h + "</tbody></table>\n";
}

std::string ranking_table(const ReportSummary& s) {
    if (s.oils.size() < 2) return "";
    const OilRank* ref = nullptr;
    for (const auto& o : s.oils)
        if (o.reference) ref = &o;
    std::string h = fmt::format("<h3>Oils ranked by mean total loss</h3>\n<p>Over the {} points where every oil has values; "
                                "the lowest loss first.</p>\n",
                                s.oils.front().points);
    h += "<table class=\"gl-table gl-ranking\"><thead><tr><th>rank</th><th>oil</th><th>mean total loss [W]</th>"
         "<th>vs the case's oil [W]</th><th>mean efficiency</th><th>highest oil temperature [&#176;C]</th></tr></thead><tbody>";
    for (size_t i = 0; i < s.oils.size(); ++i) {
        const auto& o = s.oils[i];
        const double dP = ref ? o.mean_total_W - ref->mean_total_W : kNaN;
        const std::string difference = o.reference ? "&#8211;" : fmt::format("{}{}", dP > 0 ? "+" : "", display_number(dP, 3));
        h += fmt::format("<tr><td>{}</td><td>{} <span class=\"gl-muted\">({})</span>{}</td><td><b>{}</b></td><td>{}</td>"
                         "<td>{}</td><td>{}</td></tr>",
                         i + 1, escape_html(o.name), escape_html(o.source), o.reference ? " (reference)" : "",
                         display_number(o.mean_total_W, 4), difference,
                         percent(o.mean_efficiency), display_number(o.max_oil_temp_C, 3));
    }
    return h + "</tbody></table>\n";
}

}  // namespace

ReportSummary summarise(const ReportData& d) {
    ReportSummary s;
    const auto& model = d.reference.model;
    const auto& rs = d.reference_map.results;
    s.ratio_i = model.layout.ratio != 0 ? 1.0 / model.layout.ratio : kNaN;
    s.ratio_name = model.ratio;
    s.oil_limit_C = celsius(d.reference_map.model.oil.max_temperature);
    s.highest_admissible_W = s.lowest_beyond_W = kNaN;
    bool first = true;
    for (const auto& r : rs) {
        s.no_equilibrium += r.status == solver::PointStatus::no_equilibrium;
        s.out_of_range += r.status == solver::PointStatus::out_of_range;
        s.above_limit += r.status == solver::PointStatus::above_oil_limit;
        if (r.status == solver::PointStatus::ok && !(r.power_in <= s.highest_admissible_W)) s.highest_admissible_W = r.power_in;
        if ((r.status == solver::PointStatus::above_oil_limit || r.status == solver::PointStatus::no_equilibrium) &&
            !(r.power_in >= s.lowest_beyond_W))
            s.lowest_beyond_W = r.power_in;
        if (!solver::has_values(r.status)) continue;
        ++s.with_values;
        const double T = celsius(r.oil_temperature);
        s.oil_temp_min_C = first ? T : std::min(s.oil_temp_min_C, T);
        s.oil_temp_max_C = first ? T : std::max(s.oil_temp_max_C, T);
        first = false;
    }
    for (size_t k = 0; k < model.mechanisms.size(); ++k) {
        bool zero = true;
        for (const auto& r : rs)
            if (solver::has_values(r.status) && std::fabs(r.losses.power[k]) > kZeroLoss) zero = false;
        (zero && s.with_values ? s.zero_mechanisms : s.split_mechanisms).push_back(k);
    }

    // Rated: the highest input power (ties: the higher speed, the later point); best and worst efficiency.
    const size_t rated = best_of(rs, [](const auto& a, const auto& b) {
        const double tie = 1e-9 * std::max(std::fabs(a.power_in), std::fabs(b.power_in));  // n T equal but for rounding
        return a.power_in > b.power_in + tie || (std::fabs(a.power_in - b.power_in) <= tie && a.speed_in >= b.speed_in);
    }, false);
    const size_t best = best_of(rs, [](const auto& a, const auto& b) { return a.efficiency > b.efficiency; }, true);
    const size_t worst = best_of(rs, [](const auto& a, const auto& b) { return a.efficiency < b.efficiency; }, true);
    // One row per point: a point that is two of them is named so once.
    if (rated < rs.size())
        s.key_points.push_back(key_point(std::string("rated (highest input power)") + (rated == best ? ", best efficiency" : "") +
                                             (rated == worst && worst != best ? ", worst efficiency" : ""),
                                         rs[rated], rated));
    if (best < rs.size() && best != rated) s.key_points.push_back(key_point("best efficiency", rs[best], best));
    if (worst < rs.size() && worst != best && worst != rated) s.key_points.push_back(key_point("worst efficiency", rs[worst], worst));

    // The ranking over the points where every oil has values.
    std::vector<const OilMap*> maps{&d.reference_map};
    for (const auto& c : d.comparisons) maps.push_back(&c);
    std::vector<size_t> common;
    for (size_t i = 0; i < rs.size(); ++i)
        if (std::all_of(maps.begin(), maps.end(), [i](const OilMap* m) { return i < m->results.size() && solver::has_values(m->results[i].status); }))
            common.push_back(i);
    for (const OilMap* m : maps) {
        OilRank o;
        o.name = m->oil_name;
        o.source = m->source;
        o.reference = m == &d.reference_map;
        o.points = common.size();
        double sum = 0, eta = 0;
        size_t n_eta = 0;
        o.max_oil_temp_C = kNaN;
        for (size_t i : common) {
            const auto& r = m->results[i];
            sum += r.losses.total();
            if (r.has_efficiency) eta += r.efficiency, ++n_eta;
            if (!(celsius(r.oil_temperature) <= o.max_oil_temp_C)) o.max_oil_temp_C = celsius(r.oil_temperature);
        }
        o.mean_total_W = common.empty() ? kNaN : sum / common.size();
        o.mean_efficiency = n_eta ? eta / n_eta : kNaN;
        s.oils.push_back(o);
    }
    std::stable_sort(s.oils.begin(), s.oils.end(), [](const OilRank& a, const OilRank& b) { return a.mean_total_W < b.mean_total_W; });
    return s;
}

std::string zero_mechanisms_line(const ReportData& d, const ReportSummary& s) {
    std::string t;
    for (size_t k : s.zero_mechanisms) {
        const auto& mech = d.reference_map.model.mechanisms[k];
        t += (t.empty() ? "" : "; ") + escape_html(mech.label()) + ": 0 W everywhere" + (mech.enabled() ? "" : " (switched off)");
    }
    return t;
}

std::string summary_section(const ReportData& d, const ReportSummary& s) {
    const auto& k = d.reference;
    std::string h = "<section id=\"summary\"><h2>Summary</h2>\n<table class=\"gl-table gl-summary\">";
    const auto row = [&](const std::string& a, const std::string& b) { h += "<tr><td>" + a + "</td><td>" + b + "</td></tr>"; };
    row("case", "<b>" + escape_html(k.model.name) + "</b> <span class=\"gl-muted\">(<code>" + escape_html(k.file) + "</code>)</span>");
    if (!d.title.empty()) row("description", escape_html(d.title));
    row("oil", oil_label(d.reference_map));
    row("ratio", ratio_text(d, s));
    row("operating points", grid_text(d, s));
    row("oil temperature", d.fixed_oil_temperature || s.with_values == 0
                               ? escape_html(d.thermal)
                               : fmt::format("stabilised: <b>{}&#8230;{}</b> over the map", degC(s.oil_temp_min_C), degC(s.oil_temp_max_C)));
    row("thermal limit", thermal_limit_text(s));
    std::string oils = fmt::format("<b>{}</b>: {}", 1 + d.comparisons.size(), oil_label(d.reference_map));
    for (const auto& c : d.comparisons) oils += ", " + oil_label(c);
    row("oils compared", d.comparisons.empty() ? "1 (give <code>--oil FILE</code> to compare)" : oils);
    row("assumed values", d.assumed.empty() ? "none" : fmt::format("{} values the case does not give (listed under <a href=\"#case\">The case</a>)", d.assumed.size()));
    if (!k.warnings.empty()) row("warnings", fmt::format("<span class=\"gl-warn\">{} plausibility warning{}</span> (<a href=\"#checks\">checks</a>)",
                                                        k.warnings.size(), k.warnings.size() == 1 ? "" : "s"));
    h += "</table>\n<h3>Key points</h3>\n" + key_points_table(d, s);
    if (const std::string z = zero_mechanisms_line(d, s); !z.empty()) h += "<p class=\"gl-zero\">" + z + ".</p>\n";
    for (const auto& n : d.sweep_notes) h += "<p class=\"gl-note\">" + escape_html(n) + "</p>\n";
    h += ranking_table(s);
    return h + "</section>\n";
}

}  // namespace gearloss::report
