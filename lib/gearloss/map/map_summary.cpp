#include "gearloss/map/map_summary.hpp"

#include <algorithm>
#include <cmath>

#include "gearloss/io/json_text.hpp"

namespace gearloss::map {

PointFacts PointFacts::of(const solver::PointResult& r) {
    PointFacts p;
    p.status = r.status;
    p.has_efficiency = r.has_efficiency;
    p.evaluations = r.evaluations;
    p.total_loss = r.losses.total();
    p.oil_temperature = r.oil_temperature;
    p.efficiency = r.efficiency;
    return p;
}

void MapSummary::add(const PointFacts& r) {
    ++points_;
    evaluations_ += static_cast<size_t>(std::max(0, r.evaluations));
    no_equilibrium_ += r.status == solver::PointStatus::no_equilibrium;
    out_of_range_ += r.status == solver::PointStatus::out_of_range;
    if (!solver::has_values(r.status)) return;
    // A point with values has finite ones (solve_point); the ranges skip anything else.
    if (!std::isfinite(r.total_loss) || !std::isfinite(r.oil_temperature)) return;
    ++ok_;
    above_limit_ += r.status == solver::PointStatus::above_oil_limit;
    P_min_ = std::min(P_min_, r.total_loss);
    P_max_ = std::max(P_max_, r.total_loss);
    T_min_ = std::min(T_min_, r.oil_temperature);
    T_max_ = std::max(T_max_, r.oil_temperature);
    if (r.has_efficiency && std::isfinite(r.efficiency)) {
        eff_min_ = std::min(eff_min_, r.efficiency);
        eff_max_ = std::max(eff_max_, r.efficiency);
        eff_sum_ += r.efficiency;
        ++n_eff_;
    }
}

std::string MapSummary::json(double seconds, const std::function<void(nlohmann::ordered_json&)>& more) const {
    nlohmann::ordered_json j;
    j["points"] = points_;
    j["ok"] = ok_ - above_limit_;
    j["above_oil_limit"] = above_limit_;
    j["no_equilibrium"] = no_equilibrium_;
    j["out_of_range"] = out_of_range_;
    j["seconds"] = seconds;
    j["points_per_second"] = seconds > 0 ? static_cast<double>(points_) / seconds : 0.0;
    if (ok_ > 0) {
        j["loss_W"] = {{"min", P_min_}, {"max", P_max_}};
        j["oil_temp_C"] = {{"min", T_min_ - 273.15}, {"max", T_max_ - 273.15}};
    }
    if (n_eff_ > 0) j["efficiency"] = {{"min", eff_min_}, {"max", eff_max_}, {"mean", eff_sum_ / static_cast<double>(n_eff_)}};
    if (more) more(j);
    return io::json_line(j);
}

std::string map_summary_json(const std::vector<solver::PointResult>& results, double seconds,
                             const std::function<void(nlohmann::ordered_json&)>& more) {
    MapSummary s;
    for (const auto& r : results) s.add(r);
    return s.json(seconds, more);
}

}  // namespace gearloss::map
