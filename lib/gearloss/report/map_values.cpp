#include "gearloss/report/map_values.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numeric>

#include "gearloss/report/html.hpp"

namespace gearloss::report {
namespace {

// A cell label's font [px] (class gl-cell) and the width of one of its characters (digits,
// '.', '-' of a sans-serif face are at most ~0.6 em).
constexpr double kLabelFont = 9.5, kCharWidth = 0.6 * kLabelFont;

std::string state_mark(CellState s) {
    switch (s) {
        case CellState::no_equilibrium: return "<span class=\"gl-muted\" title=\"no equilibrium\">n.e.</span>";
        case CellState::out_of_range: return "<span class=\"gl-muted\" title=\"out of range\">o.r.</span>";
        default: return "&#8211;";
    }
}

std::string cell(const MapField& f, size_t i) {
    if (!std::isfinite(f.values[i])) return "<td>" + state_mark(f.states[i]) + "</td>";
    const bool limit = f.states[i] == CellState::above_oil_limit;
    return fmt::format("<td{}>{}</td>", limit ? " class=\"gl-limit\" title=\"above the oil's permissible temperature\"" : "",
                       label_text(f.values[i], f.label_digits));
}

}  // namespace

std::vector<size_t> even_indices(size_t n, size_t count) {
    std::vector<size_t> at;
    if (n <= count) {
        for (size_t i = 0; i < n; ++i) at.push_back(i);
        return at;
    }
    if (count < 2) return count ? std::vector<size_t>{0} : at;
    for (size_t k = 0; k < count; ++k) at.push_back((k * (n - 1) + (count - 1) / 2) / (count - 1));
    return at;
}

std::string label_text(double v, int digits) {
    if (!std::isfinite(v)) return {};
    const double a = std::fabs(v);
    const int magnitude = a == 0 ? 0 : static_cast<int>(std::floor(std::log10(a)));
    const int decimals = std::clamp(digits - 1 - magnitude, 0, 3);
    std::string s = fmt::format("{:.{}f}", v, decimals);
    if (s.find_first_not_of("-0.") == std::string::npos) s = fmt::format("{:.{}f}", 0.0, decimals);  // no "-0.0"
    return s;
}

bool labels_fit(const MapField& f, double cell_w, double cell_h) {
    size_t longest = 0;
    for (double v : f.values) longest = std::max(longest, label_text(v, f.label_digits).size());
    return cell_h >= kLabelFont + 3 && cell_w >= longest * kCharWidth + 4;
}

std::string values_table(const MapAxes& axes, const MapField& f) {
    if (cell_labels_shown(axes, f) || axes.points.empty()) return {};
    std::string h = "<div class=\"gl-values\">";
    if (axes.is_grid && !axes.speeds_rpm.empty() && !axes.torques_Nm.empty()) {
        const size_t nt = axes.torques_Nm.size();
        // Columns: speeds ascending; rows: torques descending (as the picture has them).
        std::vector<size_t> os(axes.speeds_rpm.size()), ot(nt);
        std::iota(os.begin(), os.end(), 0);
        std::iota(ot.begin(), ot.end(), 0);
        std::sort(os.begin(), os.end(), [&](size_t a, size_t b) { return axes.speeds_rpm[a] < axes.speeds_rpm[b]; });
        std::sort(ot.begin(), ot.end(), [&](size_t a, size_t b) { return axes.torques_Nm[a] > axes.torques_Nm[b]; });
        const auto cs = even_indices(os.size(), kTableSpeeds), rs = even_indices(ot.size(), kTableTorques);
        if (cs.size() < os.size() || rs.size() < ot.size())
            h += fmt::format("<p class=\"gl-note\">{} of {} speeds and {} of {} torques, evenly spread (every value: the "
                             "embedded data, or <code>gearloss map</code>).</p>",
                             cs.size(), os.size(), rs.size(), ot.size());
        h += fmt::format("<table class=\"gl-table gl-values-table\" data-map=\"{}\"><thead><tr><th>N&#183;m \\ rpm</th>", escape_html(f.id));
        for (size_t c : cs) h += "<th>" + fmt::format("{:.6g}", axes.speeds_rpm[os[c]]) + "</th>";
        h += "</tr></thead><tbody>";
        for (size_t r : rs) {
            h += "<tr><th>" + fmt::format("{:.6g}", axes.torques_Nm[ot[r]]) + "</th>";
            for (size_t c : cs) h += cell(f, os[c] * nt + ot[r]);
            h += "</tr>";
        }
        h += "</tbody></table>";
    } else {
        const auto rows = even_indices(axes.points.size(), kTableRows);
        if (rows.size() < axes.points.size())
            h += fmt::format("<p class=\"gl-note\">{} of {} points, evenly spread (every value: the embedded data, or "
                             "<code>gearloss map</code>).</p>",
                             rows.size(), axes.points.size());
        h += fmt::format("<table class=\"gl-table gl-values-table\" data-map=\"{}\"><thead><tr><th>rpm</th><th>N&#183;m</th>"
                         "<th>{}</th></tr></thead><tbody>",
                         escape_html(f.id), escape_html(f.unit));
        for (size_t i : rows)
            h += "<tr><td>" + fmt::format("{:.6g}", axes.points[i].first) + "</td><td>" + fmt::format("{:.6g}", axes.points[i].second) +
                 "</td>" + cell(f, i) + "</tr>";
        h += "</tbody></table>";
    }
    return h + "</div>";
}

}  // namespace gearloss::report
