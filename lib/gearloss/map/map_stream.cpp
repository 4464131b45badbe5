#include "gearloss/map/map_stream.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <fmt/format.h>
#include <omp.h>
#include <vector>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/interrupt.hpp"

namespace gearloss::map {

void stream_rows(const solver::Model& m, const io::OperatingGrid& grid, size_t begin, size_t end, const MapOptions& opt,
                 const RowFormatter& format, const TextSink& write, MapSummary* summary) {
    opt.validate();
    end = std::min(end, grid.size());
    if (begin >= end) return;
    if (end - begin > kMaxStreamedPoints)
        throw InputError("", 0, 0, "operating",
                         fmt::format("{} operating points; a map holds at most {}", end - begin, kMaxStreamedPoints));
    // A block is ~1 MB of text (up to ~16 MB with --detail on a large gearbox) and its
    // summary facts: small against the 64 MiB a 10^7-point map may take, large enough that
    // the writing between blocks is ~2 % of the time. Chunks of rows are the unit of work
    // (dynamic: points near the oil limit cost ten times the others).
    constexpr size_t kBlock = 8192, kChunk = 64;
    const int threads = opt.threads > 0 ? opt.threads : omp_get_max_threads();
    const size_t total = end - begin;
    // Sized for this map: a sweep of one-point variants calls this once a point.
    const size_t block = std::min(kBlock, total), slots = (block + kChunk - 1) / kChunk;
    std::vector<std::string> text(slots);
    std::vector<std::exception_ptr> failed(slots);
    std::vector<PointFacts> facts(summary ? block : 0);
    std::atomic<size_t> done{0};
    std::atomic<bool> stop{false};
    // Threads bound to cores (proc_bind, see run_map); the empty region places the team.
#pragma omp parallel num_threads(threads) proc_bind(close)
    { (void)omp_get_thread_num(); }
    for (size_t b0 = begin; b0 < end; b0 += kBlock) {
        const size_t b1 = std::min(end, b0 + kBlock);
        const long chunks = static_cast<long>((b1 - b0 + kChunk - 1) / kChunk);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1) proc_bind(close) if (chunks > 1)
        for (long c = 0; c < chunks; ++c) {
            const size_t k = static_cast<size_t>(c);
            text[k].clear();
            failed[k] = nullptr;
            try {
                for (size_t i = b0 + k * kChunk; i < std::min(b1, b0 + (k + 1) * kChunk); ++i) {
                    if (stop.load(std::memory_order_relaxed)) break;
                    if (io::g_interrupted.load(std::memory_order_relaxed)) {
                        stop = true;
                        break;
                    }
                    const auto [w, T] = grid.at(i);
                    const solver::PointResult r = solver::solve_point(m, w, T, opt.detail);
                    format(r, i, text[k]);
                    if (summary) facts[i - b0] = PointFacts::of(r);
                    const size_t d = ++done;
                    if (opt.progress && omp_get_thread_num() == 0 && (d & 255) == 0) opt.progress(d, total);
                }
            } catch (...) {
                failed[k] = std::current_exception();
            }
        }
        io::throw_if_interrupted();  // an incomplete block is not written
        for (long c = 0; c < chunks; ++c)
            if (failed[static_cast<size_t>(c)]) std::rethrow_exception(failed[static_cast<size_t>(c)]);
        if (summary)
            for (size_t i = 0; i < b1 - b0; ++i) summary->add(facts[i]);
        for (long c = 0; c < chunks; ++c) write(text[static_cast<size_t>(c)]);
    }
    if (opt.progress) opt.progress(done.load(), total);
}

RowFormatter csv_formatter(const solver::Model& m, bool detail, std::string prefix) {
    return [&m, detail, prefix = std::move(prefix)](const solver::PointResult& r, size_t, std::string& out) {
        out += prefix;
        out += csv_row(m, r, detail);
    };
}

}  // namespace gearloss::map
