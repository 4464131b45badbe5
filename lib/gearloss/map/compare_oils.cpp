// `gearloss compare` with N oils, --detail and --json (docs/outputs.md).
#include "gearloss/io/json_text.hpp"
#include "gearloss/map/compare_oils.hpp"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/io/csv_format.hpp"
#include "gearloss/losses/loss_mechanism.hpp"
#include "gearloss/map/compare.hpp"

namespace gearloss::map {

using nlohmann::ordered_json;

namespace {

constexpr double kRpm = 30.0 / std::numbers::pi;
std::string num(double v) { return io::csv_number(v); }
ordered_json number(double v) { return io::json_number(v); }

// "P_mesh_W" -> "P_mesh" (the mechanism's column without its unit).
std::string stem(std::string_view column) {
    return std::string(column.ends_with("_W") ? column.substr(0, column.size() - 2) : column);
}

// The values of one result that the comparison reports (NaN where the point has none).
struct Values {
    double P = NAN, T = NAN, eta = NAN;
    std::vector<double> mech;
};
Values values_of(const solver::Model& m, const solver::PointResult& r) {
    Values v;
    v.mech.assign(m.mechanisms.size(), NAN);
    if (!solver::has_values(r.status)) return v;
    v.P = r.losses.total();
    v.T = r.oil_temperature - 273.15;
    v.eta = r.has_efficiency ? r.efficiency : NAN;
    for (size_t i = 0; i < m.mechanisms.size() && i < r.losses.power.size(); ++i) v.mech[i] = r.losses.power[i];
    return v;
}

}  // namespace

std::vector<std::string> oil_column_names(const std::vector<std::string>& oil_names) {
    std::vector<std::string> out;
    for (std::string s : oil_names) {
        for (char& c : s)
            if (c == ',' || c == '"') c = '_';
        out.push_back(std::move(s));
    }
    const bool two = out.size() == 2;
    std::vector<std::string> named = out;
    for (size_t k = 0; k < out.size(); ++k) {
        size_t same = 0;
        for (const auto& o : out) same += o == out[k];
        if (same > 1) named[k] += two ? (k == 0 ? "_A" : "_B") : fmt::format("_{}", k + 1);
    }
    return named;
}

std::string compare_oils_header(const solver::Model& m, const std::vector<std::string>& oil_names, bool detail) {
    std::string h;
    if (oil_names.size() == 2) {
        h = compare_header(oil_names[0], oil_names[1]);  // two oils: today's columns, exactly
        h.pop_back();
    } else {
        const auto k = oil_column_names(oil_names);
        h = "speed_in_rpm,torque_in_Nm";
        for (const auto& o : k) h += ",P_total_" + o + "_W";
        for (size_t i = 1; i < k.size(); ++i) h += ",dP_loss_" + k[i] + "_W";
        for (const auto& o : k) h += ",oil_temp_" + o + "_C";
        for (size_t i = 1; i < k.size(); ++i) h += ",dT_oil_" + k[i] + "_K";
        for (const auto& o : k) h += ",efficiency_" + o;
        for (size_t i = 1; i < k.size(); ++i) h += ",d_efficiency_" + k[i];
        for (const auto& o : k) h += ",status_" + o;
    }
    if (detail) {
        const auto k = oil_column_names(oil_names);
        for (size_t j = 0; j < m.mechanisms.size(); ++j) {
            const std::string s = stem(m.mechanisms[j].column());
            for (const auto& o : k) h += "," + s + "_" + o + "_W";
            for (size_t i = 1; i < k.size(); ++i) h += ",d" + s + "_" + k[i] + "_W";
        }
    }
    return h + "\n";
}

std::string compare_oils_row(const solver::Model& m, const std::vector<const solver::PointResult*>& r, bool detail) {
    std::string row;
    std::vector<Values> v;
    for (const auto* x : r) v.push_back(values_of(m, *x));
    if (r.size() == 2) {
        row = compare_row(*r[0], *r[1]);
        row.pop_back();
    } else {
        row = num(r[0]->speed_in * kRpm) + "," + num(r[0]->torque_in);
        for (const auto& x : v) row += "," + num(x.P);
        for (size_t i = 1; i < v.size(); ++i) row += "," + num(v[i].P - v[0].P);
        for (const auto& x : v) row += "," + num(x.T);
        for (size_t i = 1; i < v.size(); ++i) row += "," + num(v[i].T - v[0].T);
        for (const auto& x : v) row += "," + num(x.eta);
        for (size_t i = 1; i < v.size(); ++i) row += "," + num(v[i].eta - v[0].eta);
        for (const auto* x : r) row += "," + solver::status_text(*x);
    }
    if (detail)
        for (size_t j = 0; j < m.mechanisms.size(); ++j) {
            for (const auto& x : v) row += "," + num(x.mech[j]);
            for (size_t i = 1; i < v.size(); ++i) row += "," + num(v[i].mech[j] - v[0].mech[j]);
        }
    return row + "\n";
}

ordered_json compare_json(const solver::Model& m, const std::vector<std::string>& oil_names,
                          const std::vector<std::vector<solver::PointResult>>& maps, ordered_json metadata) {
    ordered_json j;
    j["metadata"] = std::move(metadata);
    j["reference"] = oil_names.empty() ? ordered_json(nullptr) : ordered_json(oil_names[0]);
    j["sign"] = "differences are (oil - reference): positive dP_loss_W means more loss than the reference";
    const size_t n = maps.empty() ? 0 : maps[0].size();
    // Summary per oil: its points with values, mean loss, and against the reference the mean,
    // smallest and largest dP over the points where both have values, and how many are worse.
    ordered_json summary = ordered_json::array();
    for (size_t k = 0; k < maps.size(); ++k) {
        size_t with = 0, both = 0, worse = 0, better = 0;
        double sum = 0, dsum = 0, dmin = INFINITY, dmax = -INFINITY;
        for (size_t i = 0; i < n; ++i) {
            const Values a = values_of(m, maps[0][i]), b = values_of(m, maps[k][i]);
            if (std::isfinite(b.P)) {
                ++with;
                sum += b.P;
            }
            if (k == 0 || !std::isfinite(a.P) || !std::isfinite(b.P)) continue;
            const double d = b.P - a.P;
            ++both;
            dsum += d;
            dmin = std::min(dmin, d);
            dmax = std::max(dmax, d);
            worse += d > 0;
            better += d < 0;
        }
        ordered_json o;
        o["oil"] = oil_names[k];
        o["points"] = n;
        o["points_with_values"] = with;
        o["P_total_mean_W"] = with ? number(sum / with) : ordered_json(nullptr);
        if (k > 0) {
            o["points_compared"] = both;
            o["dP_loss_mean_W"] = both ? number(dsum / both) : ordered_json(nullptr);
            o["dP_loss_min_W"] = both ? number(dmin) : ordered_json(nullptr);
            o["dP_loss_max_W"] = both ? number(dmax) : ordered_json(nullptr);
            o["points_worse"] = worse;
            o["points_better"] = better;
        }
        summary.push_back(o);
    }
    j["summary"] = summary;
    ordered_json points = ordered_json::array();
    for (size_t i = 0; i < n; ++i) {
        ordered_json p;
        p["speed_rpm"] = number(maps[0][i].speed_in * kRpm);
        p["torque_Nm"] = number(maps[0][i].torque_in);
        ordered_json oils = ordered_json::array();
        const Values a = values_of(m, maps[0][i]);
        for (size_t k = 0; k < maps.size(); ++k) {
            const Values b = values_of(m, maps[k][i]);
            ordered_json o;
            o["oil"] = oil_names[k];
            o["status"] = solver::status_text(maps[k][i]);
            o["P_total_W"] = number(b.P);
            o["oil_temp_C"] = number(b.T);
            o["efficiency"] = number(b.eta);
            ordered_json mech = ordered_json::object();
            for (size_t q = 0; q < m.mechanisms.size(); ++q) mech[std::string(m.mechanisms[q].column())] = number(b.mech[q]);
            o["mechanisms"] = mech;
            if (k > 0) {
                o["dP_loss_W"] = number(b.P - a.P);
                o["dT_oil_K"] = number(b.T - a.T);
                o["d_efficiency"] = number(b.eta - a.eta);
            }
            oils.push_back(o);
        }
        p["oils"] = oils;
        points.push_back(p);
    }
    j["points"] = points;
    return j;
}

}  // namespace gearloss::map
