#pragma once
// Every point of an operating grid, in parallel, and its CSV table.
#include <functional>
#include <string>
#include <vector>

#include "gearloss/case/config.hpp"
#include "gearloss/map/map_summary.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::map {

struct MapOptions {
    int threads = 0;        // 0 = all available
    bool detail = false;    // per-component columns
    // Called from one thread now and then with the number of points done.
    std::function<void(size_t done, size_t total)> progress;
    // Ceres-style check of the options (run_map calls it): throws InputError naming the option.
    void validate() const;
};

// Largest operating grid of a map held in memory (run_map: compare, spread, diagnosis);
// a map streamed to its file takes kMaxStreamedPoints (gearloss/map/map_stream.hpp).
inline constexpr size_t kMaxGridPoints = 10'000'000;

// Where a case's values came from besides its file: command-line overrides.
struct CaseOverrides {
    std::string oil_temp;                  // --oil-temp as given (empty: none)
    std::string oil;                       // --oil FILE (empty: none)
    bool speeds = false, torques = false;  // --speed / --torque given
    bool grid = true;                      // also check the operating points of k.grid
    size_t max_points = kMaxGridPoints;    // a streamed map takes more (kMaxStreamedPoints)
};

// solver::validate on the model, and the stated range of every operating point of the grid
// (and its size): the first issue (with the count of the others) as an InputError pointing at
// the line of the offending item in the case (or its oil file), or at the command-line option
// that set the value.
void validate_case(const io::Case& k, const CaseOverrides& o = {});
// The same for one operating point (--speed / --torque of `point`).
void validate_point(double omega_in, double torque_in);

// Results are stored by grid index, so the output does not depend on the
// number of threads or on the scheduling. A grid above kMaxGridPoints is an InputError.
// After SIGINT/SIGTERM (io::g_interrupted) it stops within a block of points and the result
// is incomplete (shorter, or with unsolved entries): callers check io::g_interrupted first.
std::vector<solver::PointResult> run_map(const solver::Model& m, const io::OperatingGrid& grid, const MapOptions& opt);

std::string csv_header(const solver::Model& m, bool detail);
std::string csv_row(const solver::Model& m, const solver::PointResult& r, bool detail);
// The same appended to `out` (no temporary string: the map's formatting loop).
void append_csv_row(std::string& out, const solver::Model& m, const solver::PointResult& r, bool detail);

}  // namespace gearloss::map
