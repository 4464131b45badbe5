// Model-form spread of a map: every combination of the mechanisms' alternative forms.
#include "gearloss/map/form_spread.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <string>
#include <numbers>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_format.hpp"
#include "gearloss/io/interrupt.hpp"
#include <nlohmann/json.hpp>
#include "gearloss/losses/loss_mechanism.hpp"
#include "gearloss/model/validate.hpp"

namespace gearloss::map {

std::string SpreadAxis::label() const { return fmt::format("{}.{}", mechanism_name, axis); }

std::vector<SpreadAxis> spread_axes(const solver::Model& m, const std::vector<std::string>& only,
                                    const std::string& option) {
    std::vector<SpreadAxis> all;
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        const auto& mech = m.mechanisms[i];
        for (const auto& a : mech.forms(m))
            if (a.forms.size() > 1)
                all.push_back({i, std::string(mech.name()), a.axis, a.forms, mech.form(m, a.axis)});
    }
    if (only.empty()) return all;
    std::vector<SpreadAxis> chosen;
    for (const auto& want : only) {
        auto it = std::find_if(all.begin(), all.end(), [&](const SpreadAxis& a) { return a.label() == want; });
        if (it == all.end()) {
            std::string known;
            for (const auto& a : all) known += (known.empty() ? "" : ", ") + a.label();
            throw InputError("", 0, 0, option, fmt::format("no form axis '{}'; known: {}", want, known));
        }
        if (std::none_of(chosen.begin(), chosen.end(), [&](const SpreadAxis& a) { return a.label() == want; }))
            chosen.push_back(*it);
    }
    return chosen;
}

size_t combination_count(const std::vector<SpreadAxis>& axes) {
    size_t n = 1;
    for (const auto& a : axes) n = n > kMaxSpreadCombinations ? n : n * a.forms.size();
    return n;
}

void require_spread_size(const std::vector<SpreadAxis>& axes) {
    if (combination_count(axes) > kMaxSpreadCombinations)
        throw InputError("", 0, 0, "--spread",
                         fmt::format("{} form axes give more than {} combinations; choose some with --spread-axes",
                                     axes.size(), kMaxSpreadCombinations));
}

namespace {
// The form index of each axis in combination i (mixed radix, the first axis fastest).
std::vector<size_t> digits(const std::vector<SpreadAxis>& axes, size_t i) {
    std::vector<size_t> d(axes.size());
    for (size_t k = 0; k < axes.size(); ++k) {
        d[k] = i % axes[k].forms.size();
        i /= axes[k].forms.size();
    }
    return d;
}
}  // namespace

solver::Model combination_model(const solver::Model& nominal, const std::vector<SpreadAxis>& axes, size_t i) {
    solver::Model m = nominal;
    const auto d = digits(axes, i);
    for (size_t k = 0; k < axes.size(); ++k) m.mechanisms[axes[k].mechanism].set_form(m, axes[k].axis, axes[k].forms[d[k]]);
    return m;
}

std::string combination_label(const std::vector<SpreadAxis>& axes, size_t i) {
    const auto d = digits(axes, i);
    std::string s;
    for (size_t k = 0; k < axes.size(); ++k)
        if (axes[k].forms[d[k]] != axes[k].nominal)
            s += fmt::format("{}{}={}", s.empty() ? "" : ";", axes[k].label(), axes[k].forms[d[k]]);
    return s.empty() ? "nominal" : s;
}

namespace {
// The first issue of a combination's model that the case's own model does not have, or empty.
std::string new_issue(const std::vector<solver::Issue>& nominal, const solver::Model& combination) {
    for (const auto& is : solver::validate(combination))
        if (std::none_of(nominal.begin(), nominal.end(), [&](const solver::Issue& n) { return n.text() == is.text(); }))
            return is.message;
    return {};
}
}  // namespace

std::vector<NotApplicable> not_applicable_combinations(const solver::Model& m, const std::vector<SpreadAxis>& axes) {
    require_spread_size(axes);
    const auto nominal = solver::validate(m);
    std::vector<NotApplicable> out;
    for (size_t c = 0; c < combination_count(axes); ++c)
        if (auto why = new_issue(nominal, combination_model(m, axes, c)); !why.empty()) out.push_back({c, std::move(why)});
    return out;
}

std::string not_applicable_note(const std::vector<SpreadAxis>& axes, const std::vector<NotApplicable>& skipped) {
    if (skipped.empty()) return {};
    return fmt::format("{} of {} form combinations do not apply to this case and are not solved (first: {}: {})",
                       skipped.size(), combination_count(axes), combination_label(axes, skipped.front().combination),
                       skipped.front().reason);
}

SpreadResult run_spread(const solver::Model& m, const io::OperatingGrid& grid, const std::vector<SpreadAxis>& axes,
                        const MapOptions& opt) {
    require_spread_size(axes);
    const size_t combinations = combination_count(axes);
    SpreadResult out;
    out.points.resize(grid.size());
    // Forms the case rules out (a closed-form H_V outside its contact ratios) give no number to
    // compare: left out, not counted as combinations that failed to solve.
    out.not_applicable = not_applicable_combinations(m, axes);
    auto skipped = out.not_applicable.begin();
    MapOptions one = opt;
    one.detail = false;
    one.progress = nullptr;
    for (size_t c = 0; c < combinations; ++c) {
        if (io::g_interrupted.load()) break;
        if (skipped != out.not_applicable.end() && skipped->combination == c) {
            ++skipped;
            continue;
        }
        const auto results = run_map(combination_model(m, axes, c), grid, one);
        for (size_t p = 0; p < results.size(); ++p) {
            auto& s = out.points[p];
            const auto& r = results[p];
            const double P = r.losses.total();
            if (!solver::has_values(r.status) || !std::isfinite(P)) {
                ++s.unsolved;
                continue;
            }
            if (s.solved == 0 || P < s.P_min) s.P_min = P, s.at_min = c;
            if (s.solved == 0 || P > s.P_max) s.P_max = P, s.at_max = c;
            ++s.solved;
        }
        if (opt.progress) opt.progress((c + 1) * grid.size(), combinations * grid.size());
    }
    return out;
}

std::string spread_csv_header() { return "P_total_min_W,P_total_max_W,forms_at_min,forms_at_max,combinations_unsolved"; }

std::string spread_csv_cells(const std::vector<SpreadAxis>& axes, const PointSpread& s) {
    if (s.solved == 0) return fmt::format(",,,,{}", s.unsolved);
    return fmt::format("{},{},{},{},{}", io::csv_number(s.P_min), io::csv_number(s.P_max), combination_label(axes, s.at_min),
                       combination_label(axes, s.at_max), s.unsolved);
}

void spread_summary_json(nlohmann::ordered_json& j, const std::vector<SpreadAxis>& axes, const SpreadResult& spread,
                         const std::vector<solver::PointResult>& nominal) {
    const auto& spreads = spread.points;
    double widest = 0;  // (P_max - P_min) / P_nominal
    size_t at = 0, points_unsolved = 0;
    for (size_t p = 0; p < spreads.size() && p < nominal.size(); ++p) {
        points_unsolved += spreads[p].unsolved > 0;
        const double P = nominal[p].losses.total();
        if (spreads[p].solved == 0 || !solver::has_values(nominal[p].status) || !(P > 0)) continue;
        const double w = (spreads[p].P_max - spreads[p].P_min) / P;
        if (w > widest) widest = w, at = p;
    }
    nlohmann::ordered_json s;
    s["axes"] = nlohmann::ordered_json::array();
    for (const auto& a : axes) s["axes"].push_back({{"axis", a.label()}, {"nominal", a.nominal}, {"forms", a.forms}});
    s["combinations"] = combination_count(axes);
    s["combinations_not_applicable"] = spread.not_applicable.size();
    s["not_applicable"] = nlohmann::ordered_json::array();
    for (const auto& n : spread.not_applicable) s["not_applicable"].push_back(combination_label(axes, n.combination));
    s["points_with_unsolved_combinations"] = points_unsolved;
    s["widest_relative_spread"] = widest;
    if (widest > 0) {
        // The grid's speed back in rpm to 12 digits: the rad/s round trip leaves 799.9999999999999 for 800.
        const double rpm = std::stod(fmt::format("{:.12g}", nominal[at].speed_in * 30.0 / std::numbers::pi));
        s["widest_at"] = {{"speed_in_rpm", rpm}, {"torque_in_Nm", nominal[at].torque_in}};
    }
    j["spread"] = std::move(s);
}

}  // namespace gearloss::map
