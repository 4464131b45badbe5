#pragma once
// A map solved, formatted and written a block at a time: memory holds one block of
// results and text whatever the number of points, the rows are formatted on every thread,
// and the text and summary are those of the map held whole (run_map, then csv_row in
// order), byte for byte at any thread count.
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

#include "gearloss/case/config.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/map/map_summary.hpp"

namespace gearloss::map {

// Largest grid of one streamed map (one sweep variant): memory no longer limits it, only
// the time a mistyped list would take (10^10 points are half a day on two cores).
inline constexpr size_t kMaxStreamedPoints = 10'000'000'000;

// Appends the text of grid row `row` with its result; called on any thread, rows in any
// order. May throw (a VECTO table's hole): the first exception in row order ends the map.
using RowFormatter = std::function<void(const solver::PointResult& r, size_t row, std::string& out)>;
// Takes consecutive text of rows, in row order.
using TextSink = std::function<void(std::string_view)>;

// Rows [begin, end) of `grid` solved on opt.threads, a block at a time: each block's rows
// are formatted in parallel by `format`, then given to `summary` (if any) and written to
// `write`, both in row order. Progress is reported as rows done of end - begin. After an
// interrupt (io::g_interrupted) it throws io::Interrupted without writing the block.
void stream_rows(const solver::Model& m, const io::OperatingGrid& grid, size_t begin, size_t end, const MapOptions& opt,
                 const RowFormatter& format, const TextSink& write, MapSummary* summary);

// csv_row of each result, led by `prefix` (a sweep variant's values).
RowFormatter csv_formatter(const solver::Model& m, bool detail, std::string prefix = {});

}  // namespace gearloss::map
