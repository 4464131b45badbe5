#include "gearloss/report/report_run.hpp"

#include <chrono>
#include <fmt/format.h>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/case/sweep.hpp"
#include "gearloss/map/form_spread.hpp"
#include "gearloss/map/output_metadata.hpp"
#include "gearloss/report/map_values.hpp"

namespace gearloss::report {
namespace {

void walk(const io::YamlNode& n, const std::string& path, std::vector<GivenValue>& out) {
    if (n.is_map()) {
        for (const auto& [key, child] : n.entries()) walk(child, path.empty() ? key : path + "." + key, out);
    } else if (n.is_sequence()) {
        const auto items = n.items();
        bool all_scalars = true;
        for (const auto& item : items) all_scalars = all_scalars && item.is_scalar();
        if (all_scalars) {  // a list of values ("speeds: [600 rpm, 800 rpm]") on one row
            std::string text;
            for (const auto& item : items) text += (text.empty() ? "" : ", ") + item.raw().Scalar();
            out.push_back({path, "[" + text + "]", static_cast<int>(n.location().line)});
            return;
        }
        for (size_t i = 0; i < items.size(); ++i) {
            std::string name = std::to_string(i);
            if (items[i].is_map() && items[i].has("name") && items[i].at("name").is_scalar()) name = items[i].at("name").raw().Scalar();
            walk(items[i], path + "." + name, out);
        }
    } else if (n.is_scalar()) {
        out.push_back({path, n.raw().Scalar(), static_cast<int>(n.location().line)});
    } else {
        out.push_back({path, "", static_cast<int>(n.location().line)});  // null
    }
}

std::string oil_sweep_note(const std::vector<io::SweepAxis>& axes) {
    std::string s;
    for (const auto& a : axes) s += (s.empty() ? "" : "; ") + a.label + " (" + std::to_string(a.values.size()) + " values)";
    return s;
}

bool is_oil_sweep(const std::vector<io::SweepAxis>& axes) {
    return axes.size() == 1 && axes[0].paths.size() == 1 && axes[0].paths[0] == "oil";
}

// The grid a report shows: the case's up to kMaxReportPoints; a larger one down-sampled (a
// speeds x torques grid to at most kMaxReportAxis values on each axis, a point list to
// kMaxReportPoints points, evenly, the ends kept), with a note saying so. The page's memory
// and size then stay bounded (~10 kB a point) whatever the grid.
std::string bound_report_grid(io::OperatingGrid& g) {
    const size_t n = g.size();
    if (n <= kMaxReportPoints) return {};
    if (g.is_grid) {
        std::vector<double> sp, tq;
        for (size_t i : even_indices(g.speeds.size(), kMaxReportAxis)) sp.push_back(g.speeds[i]);
        for (size_t i : even_indices(g.torques.size(), kMaxReportAxis)) tq.push_back(g.torques[i]);
        const std::string note = fmt::format(
            "The operating grid has {} points ({} speeds x {} torques); a report shows at most {}: its maps and tables "
            "are drawn on {} speeds x {} torques spread evenly over the grid, the first and last kept. `gearloss map` "
            "computes every point.",
            n, g.speeds.size(), g.torques.size(), kMaxReportPoints, sp.size(), tq.size());
        g.speeds = std::move(sp);
        g.torques = std::move(tq);
        return note;
    }
    std::vector<std::pair<double, double>> pts;
    for (size_t i : even_indices(n, kMaxReportPoints)) pts.push_back(g.points[i]);
    g.points = std::move(pts);
    return fmt::format("The case lists {} operating points; a report shows at most {}: {} of them, spread evenly over "
                       "the list, the first and last kept. `gearloss map` computes every point.",
                       n, kMaxReportPoints, g.points.size());
}

OilMap map_of(const io::Case& k, std::string source, const map::MapOptions& opt) {
    OilMap m;
    m.oil_name = k.model.oil.name;
    m.source = std::move(source);
    m.model = k.model;
    m.results = map::run_map(k.model, k.grid, opt);
    io::throw_if_interrupted();
    return m;
}

}  // namespace

std::vector<GivenValue> given_values(const io::YamlNode& root) {
    std::vector<GivenValue> out;
    walk(root, "", out);
    return out;
}

ReportData collect_report(const ReportRequest& q) {
    ReportData d;
    io::Sweep sweep(q.config, q.ratio);
    auto [document, sweep_block] = sweep.as_written();
    const io::YamlNode root(document, q.config, "");
    d.given = given_values(root);
    if (sweep_block && sweep_block.IsDefined() && !sweep_block.IsNull()) {
        auto swept = given_values(io::YamlNode(sweep_block, q.config, "sweep"));
        for (auto& g : swept) g.key = "sweep." + g.key;
        d.given.insert(d.given.end(), swept.begin(), swept.end());
    }
    if (root.has("description") && root.at("description").is_scalar()) d.title = root.at("description").raw().Scalar();

    const bool oil_sweep = is_oil_sweep(sweep.axes());
    if (!sweep.axes().empty() && !oil_sweep)
        d.sweep_notes.push_back("The case sweeps " + oil_sweep_note(sweep.axes()) + ": this report shows its first variant (" +
                                sweep.tag(0) + "); `gearloss map` computes every variant.");
    d.reference = q.prepare(sweep.variant(0), oil_sweep ? "sweep variant " + sweep.tag(0) : "");
    if (const std::string note = bound_report_grid(d.reference.grid); !note.empty()) d.sweep_notes.push_back(note);
    const auto& k = d.reference;
    d.assumed = k.assumed;
    d.case_hash = map::case_hash(k);
    d.fixed_oil_temperature = k.model.thermal.mode == solver::ThermalMode::fixed;
    d.thermal = d.fixed_oil_temperature ? fmt::format("fixed at {:.1f} degC", k.model.thermal.oil_temperature - 273.15) +
                                              (q.overrides.oil_temp.empty() ? " (the case's thermal.mode)" : " (--oil-temp)")
                                        : "stabilised (thermal equilibrium of losses and heat rejection)";

    // The spread's size is checked before any map is solved (as map --spread does).
    std::vector<map::SpreadAxis> axes;
    if (q.spread) {
        axes = map::spread_axes(k.model, q.spread_axes);
        if (axes.empty()) d.spread_note = "No mechanism of this case has alternative forms.";
        else if (map::combination_count(axes) > map::kMaxSpreadCombinations) {
            d.spread_note = fmt::format("{} form combinations exceed {}: choose axes with --spread-axes.",
                                        map::combination_count(axes), map::kMaxSpreadCombinations);
            axes.clear();
        }
    } else {
        d.spread_note = "Not computed (--no-spread).";
    }

    // The compared oils, each checked as `compare` checks its two before anything is solved.
    std::vector<std::pair<io::Case, std::string>> others;
    for (const auto& file : q.oils) {
        io::Case c = k;
        io::replace_oil_file(c, file);
        map::CaseOverrides o = q.overrides;
        o.oil = file;
        map::validate_case(c, o);
        others.emplace_back(std::move(c), "--oil " + file);
    }
    if (oil_sweep)
        for (size_t v = 1; v < sweep.size(); ++v) {
            io::throw_if_interrupted();
            others.emplace_back(q.prepare(sweep.variant(v), "sweep variant " + sweep.tag(v)), "sweep " + sweep.tag(v));
            bound_report_grid(others.back().first.grid);  // the same grid as the reference's
        }

    const auto t0 = std::chrono::steady_clock::now();
    d.reference_map = map_of(k, oil_sweep ? "sweep " + sweep.tag(0) : "the case", q.map_options);
    if (!axes.empty()) {
        SpreadMap s;
        s.axes = axes;
        s.combinations = map::combination_count(axes);
        s.note = map::not_applicable_note(axes, map::not_applicable_combinations(k.model, axes));
        s.result = map::run_spread(k.model, k.grid, axes, q.map_options);
        io::throw_if_interrupted();
        d.spread = std::move(s);
    }
    for (auto& [c, source] : others) d.comparisons.push_back(map_of(c, source, q.map_options));
    d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    d.version = GEARLOSS_VERSION;
    d.command_line = q.command_line;
    return d;
}

}  // namespace gearloss::report
