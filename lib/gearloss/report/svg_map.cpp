#include "gearloss/report/svg_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <numeric>

#include "gearloss/report/html.hpp"
#include "gearloss/report/map_values.hpp"

namespace gearloss::report {
namespace {

// Picture layout [px].
constexpr double kWidth = 600, kLeft = 70, kTop = 36, kPlotW = 380, kPlotH = 260;
constexpr double kBarX = kLeft + kPlotW + 22, kBarW = 14;
constexpr double kLegendTop = kTop + kPlotH + 52;

struct Rgb {
    double r, g, b;
};

Rgb hex(unsigned v) { return {double((v >> 16) & 255), double((v >> 8) & 255), double(v & 255)}; }

// Linear interpolation between equally spaced colour stops.
template <size_t N>
std::string interpolate(const std::array<unsigned, N>& stops, double t) {
    t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
    const double x = t * (N - 1);
    const size_t i = std::min(static_cast<size_t>(x), N - 2);
    const double f = x - i;
    const Rgb a = hex(stops[i]), b = hex(stops[i + 1]);
    auto mix = [f](double p, double q) { return static_cast<int>(std::lround(p + f * (q - p))); };
    return fmt::format("#{:02x}{:02x}{:02x}", mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b));
}

// Viridis, perceptually uniform and readable in grey (Smith et al. 2015), ten stops.
constexpr std::array<unsigned, 10> kViridis = {0x440154, 0x482878, 0x3e4989, 0x31688e, 0x26828e,
                                               0x1f9e89, 0x35b779, 0x6ece58, 0xb5de2b, 0xfde725};
// Blue - white - red, the RdBu scheme of Harrower & Brewer (2003), from blue (t = 0) to red (t = 1).
constexpr std::array<unsigned, 9> kBlueRed = {0x2166ac, 0x4393c3, 0x92c5de, 0xd1e5f0, 0xf7f7f7,
                                              0xfddbc7, 0xf4a582, 0xd6604d, 0xb2182b};

// A value's share of [lo, hi] (0.5 when the range is empty).
double unit_position(double v, double lo, double hi) { return hi > lo ? (v - lo) / (hi - lo) : 0.5; }

// The q-quantile of the finite values (nearest rank).
double quantile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    const size_t i = static_cast<size_t>(std::lround(q * (v.size() - 1)));
    return v[std::min(i, v.size() - 1)];
}

// The colour range of a field: a plain quantity spans its values with the outer 2 % on each
// side clipped (one outlier point would otherwise take the whole scale; every cell still shows
// its value on hover); a difference is symmetric about zero so that white is "no change".
struct Range {
    double lo = 0, hi = 1;
    bool clipped_lo = false, clipped_hi = false;
};
Range colour_range(const MapField& f) {
    std::vector<double> v;
    for (double x : f.values)
        if (std::isfinite(x)) v.push_back(x);
    Range r;
    if (v.empty()) return r;
    const auto [mn, mx] = std::minmax_element(v.begin(), v.end());
    if (f.sense == ColourSense::sequential) {
        r.lo = v.size() >= 50 ? quantile(v, 0.02) : *mn;
        r.hi = v.size() >= 50 ? quantile(v, 0.98) : *mx;
        if (!(r.hi > r.lo)) r.lo = *mn, r.hi = *mx;
        if (!(r.hi > r.lo)) {  // one value: a band around it
            const double pad = r.lo != 0 ? std::fabs(r.lo) * 0.05 : 1.0;
            r.lo -= pad, r.hi += pad;
        }
    } else {
        std::vector<double> a;
        for (double x : v) a.push_back(std::fabs(x));
        double m = a.size() >= 50 ? quantile(a, 0.98) : *std::max_element(a.begin(), a.end());
        if (!(m > 0)) m = *std::max_element(a.begin(), a.end());
        if (!(m > 0)) m = 1.0;
        r.lo = -m, r.hi = m;
    }
    r.clipped_lo = *mn < r.lo;
    r.clipped_hi = *mx > r.hi;
    return r;
}

// Cell edges of an axis: midway between neighbouring values (in ascending order), the outer
// cells as wide as their neighbour's half gap; a single value gets a band around it.
// Returns per value (in the given order) its [low, high] edge.
std::vector<std::pair<double, double>> cell_edges(const std::vector<double>& values) {
    std::vector<size_t> order(values.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return values[a] < values[b]; });
    std::vector<std::pair<double, double>> e(values.size());
    if (values.size() == 1) {
        const double pad = values[0] != 0 ? std::fabs(values[0]) * 0.1 : 1.0;
        e[0] = {values[0] - pad, values[0] + pad};
        return e;
    }
    for (size_t k = 0; k < order.size(); ++k) {
        const double v = values[order[k]];
        const double lo = k > 0 ? 0.5 * (values[order[k - 1]] + v) : v - 0.5 * (values[order[1]] - v);
        const double hi = k + 1 < order.size() ? 0.5 * (v + values[order[k + 1]])
                                               : v + 0.5 * (v - values[order[k - 1]]);
        e[order[k]] = {lo, hi};
    }
    return e;
}

// A linear map from data [d0, d1] to pixels [p0, p1].
struct Scale {
    double d0, d1, p0, p1;
    double operator()(double v) const { return d1 > d0 ? p0 + (v - d0) / (d1 - d0) * (p1 - p0) : 0.5 * (p0 + p1); }
};

std::string px(double v) { return fmt::format("{:.1f}", v); }

// The plot's extent of a grid in data units: the union of the cells.
struct GridFrame {
    std::vector<std::pair<double, double>> ex, ey;  // per speed, per torque: cell edges
    Scale sx, sy;
};
GridFrame grid_frame(const MapAxes& axes) {
    GridFrame g{cell_edges(axes.speeds_rpm), cell_edges(axes.torques_Nm), {}, {}};
    double x0 = g.ex[0].first, x1 = g.ex[0].second, y0 = g.ey[0].first, y1 = g.ey[0].second;
    for (const auto& [a, b] : g.ex) x0 = std::min(x0, a), x1 = std::max(x1, b);
    for (const auto& [a, b] : g.ey) y0 = std::min(y0, a), y1 = std::max(y1, b);
    g.sx = {x0, x1, kLeft, kLeft + kPlotW};
    g.sy = {y0, y1, kTop + kPlotH, kTop};
    return g;
}

bool is_drawable_grid(const MapAxes& axes) { return axes.is_grid && !axes.speeds_rpm.empty() && !axes.torques_Nm.empty(); }

// Black or white, whichever reads better on a cell of colour "#rrggbb" (relative luminance,
// ITU-R BT.709 weights).
const char* label_colour(const std::string& fill) {
    if (fill.size() != 7 || fill[0] != '#') return "#000";
    const unsigned v = static_cast<unsigned>(std::stoul(fill.substr(1), nullptr, 16));
    const Rgb c = hex(v);
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b < 128 ? "#fff" : "#000";
}

const char* state_text(CellState s) {
    switch (s) {
        case CellState::value: return "ok";
        case CellState::above_oil_limit: return "above the oil's permissible temperature";
        case CellState::no_equilibrium: return "no equilibrium";
        case CellState::out_of_range: return "out of range";
    }
    return "";
}

// The fill of a cell without a colour value.
const char* state_fill(CellState s) {
    switch (s) {
        case CellState::no_equilibrium: return "url(#gl-hatch-noeq)";
        case CellState::out_of_range: return "url(#gl-hatch-range)";
        default: return "#ffffff";  // solved, but the quantity is not defined there (efficiency at zero torque)
    }
}

// Marching squares (the two-dimensional case of Lorensen & Cline 1987) over the grid nodes at one
// level: line segments with their ends interpolated linearly along the cell edges; cells with
// a corner without a value are skipped. `x`, `y`: node pixel positions (ascending order),
// `at(i, j)`: the value at node (i, j).
template <class At>
std::string contour_path(const std::vector<double>& x, const std::vector<double>& y, const At& at, double level) {
    std::string d;
    for (size_t i = 0; i + 1 < x.size(); ++i)
        for (size_t j = 0; j + 1 < y.size(); ++j) {
            const double c[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};  // corners counter-clockwise
            if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]) || !std::isfinite(c[3])) continue;
            const double px_[4] = {x[i], x[i + 1], x[i + 1], x[i]}, py_[4] = {y[j], y[j], y[j + 1], y[j + 1]};
            std::vector<std::pair<double, double>> cut;  // where the level crosses the 4 edges
            for (int e = 0; e < 4; ++e) {
                const int f = (e + 1) % 4;
                const bool a = c[e] >= level, b = c[f] >= level;
                if (a == b) continue;
                const double t = (level - c[e]) / (c[f] - c[e]);
                cut.emplace_back(px_[e] + t * (px_[f] - px_[e]), py_[e] + t * (py_[f] - py_[e]));
            }
            // Two crossings: one segment; four (a saddle): two, paired along the edges' order.
            for (size_t k = 0; k + 1 < cut.size(); k += 2)
                d += fmt::format("M{} {}L{} {}", px(cut[k].first), px(cut[k].second), px(cut[k + 1].first),
                                 px(cut[k + 1].second));
        }
    return d;
}

std::string tick_label(double v, double step) {
    // As many decimals as the step needs.
    const int decimals = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
    if (std::fabs(v) >= 1e6 || (v != 0 && std::fabs(v) < 1e-3 && decimals > 6)) return fmt::format("{:.2g}", v);
    std::string s = fmt::format("{:.{}f}", v, std::min(decimals, 6));
    if (s.find_first_not_of("-0.") == std::string::npos) s = fmt::format("{:.{}f}", 0.0, std::min(decimals, 6));
    return s;
}

double tick_step(const std::vector<double>& ticks) { return ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0; }

// Axis frame, ticks, grid-free labels.
std::string axes_svg(const Scale& sx, const Scale& sy) {
    std::string s = fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#333"/>)", px(kLeft),
                                px(kTop), px(kPlotW), px(kPlotH));
    const auto xt = nice_ticks(sx.d0, sx.d1, 6), yt = nice_ticks(sy.d0, sy.d1, 6);
    for (double v : xt)
        s += fmt::format(R"(<line x1="{0}" y1="{1}" x2="{0}" y2="{2}" stroke="#333"/><text x="{0}" y="{3}" )"
                         R"(text-anchor="middle" class="gl-tick">{4}</text>)",
                         px(sx(v)), px(kTop + kPlotH), px(kTop + kPlotH + 5), px(kTop + kPlotH + 18),
                         tick_label(v, tick_step(xt)));
    for (double v : yt)
        s += fmt::format(R"(<line x1="{0}" y1="{1}" x2="{2}" y2="{1}" stroke="#333"/><text x="{3}" y="{4}" )"
                         R"(text-anchor="end" class="gl-tick">{5}</text>)",
                         px(kLeft - 5), px(sy(v)), px(kLeft), px(kLeft - 8), px(sy(v) + 4), tick_label(v, tick_step(yt)));
    s += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle" class="gl-axis">input speed [rpm]</text>)",
                     px(kLeft + kPlotW / 2), px(kTop + kPlotH + 38));
    s += fmt::format(R"~(<text transform="translate({} {}) rotate(-90)" text-anchor="middle" class="gl-axis">)~"
                     R"(input torque [N&#183;m]</text>)",
                     px(18), px(kTop + kPlotH / 2));
    return s;
}

// The colour bar with its ticks, unit, and for a difference which end is worse.
std::string colour_bar_svg(const MapField& f, const Range& r) {
    std::string s;
    constexpr int kSteps = 64;
    const double h = kPlotH / kSteps;
    for (int k = 0; k < kSteps; ++k) {
        const double t = (k + 0.5) / kSteps;  // from the bottom
        s += fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" fill="{}"/>)", px(kBarX),
                         px(kTop + kPlotH - (k + 1) * h), px(kBarW), px(h + 0.3), scale_colour(f.sense, t));
    }
    s += fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#333"/>)", px(kBarX), px(kTop),
                     px(kBarW), px(kPlotH));
    const Scale sb{r.lo, r.hi, kTop + kPlotH, kTop};
    const auto ticks = nice_ticks(r.lo, r.hi, 6);
    for (size_t k = 0; k < ticks.size(); ++k) {
        std::string label = tick_label(ticks[k], tick_step(ticks));
        s += fmt::format(R"(<line x1="{0}" y1="{1}" x2="{2}" y2="{1}" stroke="#333"/><text x="{3}" y="{4}" class="gl-tick">{5}</text>)",
                         px(kBarX + kBarW), px(sb(ticks[k])), px(kBarX + kBarW + 4), px(kBarX + kBarW + 6),
                         px(sb(ticks[k]) + 4), label);
    }
    std::string unit = escape_html(f.unit);
    if (r.clipped_hi) unit += " (top: &#8805;)";
    s += fmt::format(R"(<text x="{}" y="{}" class="gl-tick" text-anchor="middle">{}</text>)", px(kBarX + kBarW / 2),
                     px(kTop - 6), unit);
    if (f.sense != ColourSense::sequential) {
        const bool up_worse = f.sense == ColourSense::higher_is_worse;
        s += fmt::format(R"(<text x="{}" y="{}" class="gl-tick" fill="{}">{}</text>)", px(kBarX - 2), px(kTop + kPlotH + 16),
                         up_worse ? "#2166ac" : "#b2182b", up_worse ? "better" : "worse");
    }
    if (r.clipped_lo)
        s += fmt::format(R"(<text x="{}" y="{}" class="gl-tick">bottom: &#8804;</text>)", px(kBarX - 2),
                         px(kTop + kPlotH + (f.sense == ColourSense::sequential ? 16 : 30)));
    return s;
}

// The legend: computed points, and each state without a colour value that occurs.
std::string legend_svg(const MapField& f, bool grid, bool labelled, int& rows) {
    std::string s;
    double y = kLegendTop;
    auto entry = [&](const std::string& swatch, const std::string& text) {
        s += swatch;
        s += fmt::format(R"(<text x="{}" y="{}" class="gl-legend">{}</text>)", px(kLeft + 22), px(y + 4), text);
        y += 18;
        ++rows;
    };
    if (labelled)
        entry(fmt::format(R"(<text x="{}" y="{}" text-anchor="middle" class="gl-legend">12.3</text>)", px(kLeft + 8), px(y + 4)),
              "computed point: its value at the cell centre; lines: contours at the colour bar's ticks");
    else
        entry(fmt::format(R"(<circle cx="{}" cy="{}" r="2.2" fill="#000" stroke="#fff" stroke-width="0.8"/>)", px(kLeft + 8), px(y)),
              grid ? "computed point (values: the table below); lines: contours at the bar's ticks"
                   : "computed point (values: the table below)");
    auto has = [&](CellState st) { return std::find(f.states.begin(), f.states.end(), st) != f.states.end(); };
    auto box = [&](const char* fill, const char* stroke) {
        return fmt::format(R"(<rect x="{}" y="{}" width="16" height="11" fill="{}" stroke="{}"/>)", px(kLeft), px(y - 5.5),
                           fill, stroke);
    };
    if (has(CellState::no_equilibrium))
        entry(box("url(#gl-hatch-noeq)", "#666"),
              "no equilibrium: losses exceed the heat rejected up to the solver's limit (no values)");
    if (has(CellState::out_of_range))
        entry(box("url(#gl-hatch-range)", "#666"), "out of range: an input or a component left the model's range");
    bool undefined = false;
    for (size_t i = 0; i < f.values.size(); ++i)
        undefined = undefined || (!std::isfinite(f.values[i]) && (f.states[i] == CellState::value || f.states[i] == CellState::above_oil_limit));
    if (undefined) entry(box("#ffffff", "#666"), "not defined at this point (e.g. efficiency at zero torque)");
    if (has(CellState::above_oil_limit))
        entry(box("none", "#d00"), "above the oil's permissible temperature (computed, not admissible)");
    return s;
}

}  // namespace

std::string scale_colour(ColourSense sense, double t) {
    switch (sense) {
        case ColourSense::sequential: return interpolate(kViridis, t);
        case ColourSense::higher_is_worse: return interpolate(kBlueRed, t);
        case ColourSense::higher_is_better: return interpolate(kBlueRed, 1.0 - t);
    }
    return "#000000";
}

std::vector<double> nice_ticks(double lo, double hi, int count) {
    std::vector<double> t;
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) {
        if (std::isfinite(lo)) t.push_back(lo);
        return t;
    }
    const double raw = (hi - lo) / std::max(count - 1, 1);
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    double step = p;
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
        if (m * p >= raw) {
            step = m * p;
            break;
        }
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step)
        t.push_back(std::fabs(v) < step * 1e-9 ? 0.0 : v);
    return t;
}

std::string svg_pattern_defs() {
    return R"(<svg width="0" height="0" style="position:absolute" aria-hidden="true"><defs>)"
           R"~(<pattern id="gl-hatch-noeq" width="6" height="6" patternUnits="userSpaceOnUse" patternTransform="rotate(45)">)~"
           R"(<rect width="6" height="6" fill="#e6e6e6"/><line x1="0" y1="0" x2="0" y2="6" stroke="#777" stroke-width="2"/></pattern>)"
           R"(<pattern id="gl-hatch-range" width="6" height="6" patternUnits="userSpaceOnUse">)"
           R"(<rect width="6" height="6" fill="#f4f4f4"/><path d="M0 0L6 6M6 0L0 6" stroke="#aaa" stroke-width="0.8"/></pattern>)"
           R"(</defs></svg>)";
}

bool cell_labels_shown(const MapAxes& axes, const MapField& f) {
    if (!is_drawable_grid(axes)) return false;
    const GridFrame g = grid_frame(axes);
    double w = kPlotW, h = kPlotH;
    for (const auto& [a, b] : g.ex) w = std::min(w, g.sx(b) - g.sx(a));
    for (const auto& [a, b] : g.ey) h = std::min(h, g.sy(a) - g.sy(b));
    return labels_fit(f, w, h);
}

std::string svg_map(const MapAxes& axes, const MapField& f) {
    const Range r = colour_range(f);
    const auto colour = [&](double v) { return scale_colour(f.sense, unit_position(v, r.lo, r.hi)); };
    std::string body;
    std::string dots;  // one path of zero-length round-capped strokes: a dot per computed point
    Scale sx{0, 1, kLeft, kLeft + kPlotW}, sy{0, 1, kTop + kPlotH, kTop};
    const auto cell_title = [&](size_t i) {
        const auto [n, T] = axes.points[i];
        std::string t = fmt::format("{} rpm, {} N&#183;m: ", display_number(n, 6), display_number(T, 6));
        if (std::isfinite(f.values[i])) t += display_number(f.values[i], 5) + " " + escape_html(f.unit);
        if (f.states[i] != CellState::value) t += std::string(std::isfinite(f.values[i]) ? " (" : "(") + state_text(f.states[i]) + ")";
        return "<title>" + t + "</title>";
    };
    const bool labelled = cell_labels_shown(axes, f);
    std::string labels;  // the value of each cell, drawn over everything else in the plot
    if (is_drawable_grid(axes)) {
        const GridFrame g = grid_frame(axes);
        const auto& ex = g.ex;
        const auto& ey = g.ey;
        sx = g.sx;
        sy = g.sy;
        const size_t nt = axes.torques_Nm.size();
        std::string limits;  // outlines of the cells above the oil's limit, drawn over the cells
        for (size_t i = 0; i < axes.points.size(); ++i) {
            const size_t is = i / nt, it = i % nt;
            const double xa = sx(ex[is].first), xb = sx(ex[is].second), ya = sy(ey[it].second), yb = sy(ey[it].first);
            const bool has = std::isfinite(f.values[i]);
            const std::string fill = has ? colour(f.values[i]) : state_fill(f.states[i]);
            body += fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" fill="{}">{}</rect>)", px(xa), px(ya),
                                px(xb - xa + 0.4), px(yb - ya + 0.4), fill, cell_title(i));
            if (f.states[i] == CellState::above_oil_limit)
                limits += fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#d00" stroke-width="1.2"/>)",
                                      px(xa + 0.6), px(ya + 0.6), px(xb - xa - 1.2), px(yb - ya - 1.2));
            if (labelled && has)
                labels += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle" class="gl-cell" fill="{}" data-i="{}">{}</text>)",
                                      px(sx(axes.points[i].first)), px(sy(axes.points[i].second) + 3.3), label_colour(fill), i,
                                      label_text(f.values[i], f.label_digits));
            else
                dots += fmt::format("M{} {}h0", px(sx(axes.points[i].first)), px(sy(axes.points[i].second)));
        }
        // Contours through the nodes in ascending order of each axis.
        std::vector<size_t> os(axes.speeds_rpm.size()), ot(nt);
        std::iota(os.begin(), os.end(), 0);
        std::iota(ot.begin(), ot.end(), 0);
        std::sort(os.begin(), os.end(), [&](size_t a, size_t b) { return axes.speeds_rpm[a] < axes.speeds_rpm[b]; });
        std::sort(ot.begin(), ot.end(), [&](size_t a, size_t b) { return axes.torques_Nm[a] < axes.torques_Nm[b]; });
        std::vector<double> nx, ny;
        for (size_t k : os) nx.push_back(sx(axes.speeds_rpm[k]));
        for (size_t k : ot) ny.push_back(sy(axes.torques_Nm[k]));
        const auto at = [&](size_t i, size_t j) { return f.values[os[i] * nt + ot[j]]; };
        std::string lines;
        const auto levels = nice_ticks(r.lo, r.hi, 6);
        for (double level : levels)
            if (level > r.lo && level < r.hi) lines += contour_path(nx, ny, at, level);
        body += limits;
        if (!lines.empty())
            body += fmt::format(R"(<path d="{}" fill="none" stroke="#000" stroke-opacity="0.45" stroke-width="0.9"/>)", lines);
        body += labels;
    } else if (!axes.points.empty()) {
        double x0 = axes.points[0].first, x1 = x0, y0 = axes.points[0].second, y1 = y0;
        for (const auto& [n, T] : axes.points) x0 = std::min(x0, n), x1 = std::max(x1, n), y0 = std::min(y0, T), y1 = std::max(y1, T);
        const double padx = x1 > x0 ? 0.06 * (x1 - x0) : std::max(1.0, std::fabs(x0) * 0.1);
        const double pady = y1 > y0 ? 0.06 * (y1 - y0) : std::max(1.0, std::fabs(y0) * 0.1);
        sx = {x0 - padx, x1 + padx, kLeft, kLeft + kPlotW};
        sy = {y0 - pady, y1 + pady, kTop + kPlotH, kTop};
        for (size_t i = 0; i < axes.points.size(); ++i) {
            const bool has = std::isfinite(f.values[i]);
            body += fmt::format(R"(<circle cx="{}" cy="{}" r="7" fill="{}" stroke="{}" stroke-width="{}">{}</circle>)",
                                px(sx(axes.points[i].first)), px(sy(axes.points[i].second)),
                                has ? colour(f.values[i]) : state_fill(f.states[i]),
                                f.states[i] == CellState::above_oil_limit ? "#d00" : "#333",
                                f.states[i] == CellState::above_oil_limit ? "1.5" : "0.6", cell_title(i));
            dots += fmt::format("M{} {}h0", px(sx(axes.points[i].first)), px(sy(axes.points[i].second)));
        }
    }
    int rows = 0;
    const std::string legend = legend_svg(f, axes.is_grid, labelled, rows);
    const double height = kLegendTop + rows * 18 + 4;
    std::string s = fmt::format(R"(<svg class="gl-map" id="{}" width="{}" height="{}" )"
                                R"(viewBox="0 0 {} {}" role="img" aria-label="{}">)",
                                escape_html(f.id), px(kWidth), px(height), px(kWidth), px(height), escape_html(f.title));
    s += fmt::format(R"(<text x="{}" y="20" class="gl-title">{}</text>)", px(kLeft), escape_html(f.title));
    s += fmt::format(R"~(<clipPath id="{}-clip"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath><g clip-path="url(#{}-clip)">)~",
                     escape_html(f.id), px(kLeft), px(kTop), px(kPlotW), px(kPlotH), escape_html(f.id));
    s += body;
    if (!dots.empty())
        s += fmt::format(R"(<path d="{}" stroke="#fff" stroke-width="4" stroke-linecap="round"/>)"
                         R"(<path d="{}" stroke="#000" stroke-width="2.4" stroke-linecap="round"/>)",
                         dots, dots);
    s += "</g>";
    s += axes_svg(sx, sy);
    s += colour_bar_svg(f, r);
    s += legend;
    s += "</svg>";
    return s;
}

}  // namespace gearloss::report
