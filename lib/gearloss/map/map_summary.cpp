#include "gearloss/map/map_summary.hpp"

#include <algorithm>
#include <cmath>

#include "gearloss/io/json.hpp"

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

std::string MapSummary::json(double seconds, const std::function<void(io::Json&)>& more) const {
    io::Json j;
    j.begin_object();
    j.key("points").value(points_);
    j.key("ok").value(ok_ - above_limit_);
    j.key("above_oil_limit").value(above_limit_);
    j.key("no_equilibrium").value(no_equilibrium_);
    j.key("out_of_range").value(out_of_range_);
    j.key("seconds").value(seconds);
    j.key("points_per_second").value(seconds > 0 ? points_ / seconds : 0.0);
    if (ok_ > 0) {
        j.key("loss_W").begin_object().key("min").value(P_min_).key("max").value(P_max_).end_object();
        j.key("oil_temp_C").begin_object().key("min").value(T_min_ - 273.15).key("max").value(T_max_ - 273.15).end_object();
    }
    if (n_eff_ > 0)
        j.key("efficiency").begin_object().key("min").value(eff_min_).key("max").value(eff_max_).key("mean")
            .value(eff_sum_ / n_eff_).end_object();
    if (more) more(j);
    j.end_object();
    return j.str() + "\n";
}

std::string map_summary_json(const std::vector<solver::PointResult>& results, double seconds,
                             const std::function<void(io::Json&)>& more) {
    MapSummary s;
    for (const auto& r : results) s.add(r);
    return s.json(seconds, more);
}

}  // namespace gearloss::map
