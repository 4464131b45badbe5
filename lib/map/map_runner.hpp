#pragma once
// Every point of an operating grid, in parallel, and its CSV table.
#include <functional>
#include <string>
#include <vector>

#include "io/config.hpp"
#include "solver/operating_point.hpp"

namespace gearloss::map {

struct MapOptions {
    int threads = 0;        // 0 = all available
    bool detail = false;    // per-component columns
    // Called from one thread now and then with the number of points done.
    std::function<void(size_t done, size_t total)> progress;
};

// Results are stored by grid index, so the output does not depend on the
// number of threads or on the scheduling.
std::vector<solver::PointResult> run_map(const solver::Model& m, const io::OperatingGrid& grid, const MapOptions& opt);

std::string csv_header(const solver::Model& m, bool detail);
std::string csv_row(const solver::Model& m, const solver::PointResult& r, bool detail);

// Summary for scripts: point counts, efficiency, loss and oil-temperature ranges, solve time.
std::string map_summary_json(const std::vector<solver::PointResult>& results, double seconds);

}  // namespace gearloss::map
