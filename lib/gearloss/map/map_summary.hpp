#pragma once
// The summary of a map for scripts (`map --json`): point counts, efficiency, loss and
// oil-temperature ranges, solve time. Accumulated point by point in row order, so a map
// streamed block by block gives the very summary of the map held whole (the mean
// efficiency is a sum in row order: the same digits at any thread count).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "gearloss/solver/operating_point.hpp"


namespace gearloss::map {

// What the summary needs of one point (~40 bytes instead of the whole result).
struct PointFacts {
    solver::PointStatus status = solver::PointStatus::ok;
    bool has_efficiency = false;
    int evaluations = 0;
    double total_loss = 0, oil_temperature = 0, efficiency = 0;  // W, K, -
    static PointFacts of(const solver::PointResult& r);
};

class MapSummary {
public:
    void add(const PointFacts& p);  // in row order
    void add(const solver::PointResult& r) { add(PointFacts::of(r)); }
    size_t points() const { return points_; }
    size_t evaluations() const { return evaluations_; }
    size_t no_equilibrium() const { return no_equilibrium_; }
    // The JSON object; `more` adds members (e.g. the form spread).
    std::string json(double seconds, const std::function<void(nlohmann::ordered_json&)>& more = {}) const;

private:
    size_t points_ = 0, ok_ = 0, above_limit_ = 0, no_equilibrium_ = 0, out_of_range_ = 0, n_eff_ = 0, evaluations_ = 0;
    double eff_min_ = 1, eff_max_ = 0, eff_sum_ = 0, P_min_ = 1e300, P_max_ = 0, T_min_ = 1e300, T_max_ = -1e300;
};

// The summary of results held whole.
std::string map_summary_json(const std::vector<solver::PointResult>& results, double seconds,
                             const std::function<void(nlohmann::ordered_json&)>& more = {});

}  // namespace gearloss::map
