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
    // A block's text is aimed at 4 MiB (the rows of the first block tell their size: ~140 bytes
    // plain, ~400 with --detail on the shipped cases), with its summary facts: small against the
    // 64 MiB a 10^7-point map may take, and few blocks, since each ends in a barrier where a
    // thread waits for the slowest chunk. Chunks of 16 rows are the unit of work (dynamic:
    // points near the oil limit cost ten times the others). Two blocks alternate: one thread
    // writes the block solved last while the team solves the next, so the writing is not serial.
    constexpr size_t kFirstBlock = 4096, kMinBlock = 1024, kMaxBlock = 32768, kChunk = 16;
    constexpr size_t kBlockBytes = size_t{4} << 20;
    const int threads = opt.threads > 0 ? opt.threads : omp_get_max_threads();
    const size_t total = end - begin;
    // Sized for this map: a sweep of one-point variants calls this once a point.
    const size_t rows_max = std::min(kMaxBlock, total), slots = (rows_max + kChunk - 1) / kChunk;
    size_t block_rows = kFirstBlock;
    struct Block {
        size_t rows = 0, chunks = 0;
        std::vector<std::string> text;
        std::vector<std::exception_ptr> failed;
        std::vector<PointFacts> facts;
    };
    Block blocks[2];
    for (auto& b : blocks) {
        b.text.resize(slots);
        b.failed.resize(slots);
        b.facts.resize(summary ? rows_max : 0);
    }
    // The summary and the text of a solved block, in row order.
    const auto emit = [&](const Block& b) {
        if (summary)
            for (size_t i = 0; i < b.rows; ++i) summary->add(b.facts[i]);
        for (size_t c = 0; c < b.chunks; ++c) write(b.text[c]);
    };
    std::atomic<size_t> done{0};
    std::atomic<bool> stop{false};
    std::exception_ptr write_failed;
    const Block* pending = nullptr;  // solved, not yet written
    // Threads bound to cores (proc_bind, see run_map); the empty region places the team. A
    // map of one chunk (a sweep's one-point variant) runs on this thread alone: waking the
    // team per variant would leave it spinning on the other core for nothing.
    if (total > kChunk) {
#pragma omp parallel num_threads(threads) proc_bind(close)
        { (void)omp_get_thread_num(); }
    }
    size_t parity = 0;
    for (size_t b0 = begin; b0 < end; b0 += blocks[parity].rows) {
        parity ^= 1;
        Block& cur = blocks[parity];
        cur.rows = std::min(end - b0, block_rows);
        cur.chunks = (cur.rows + kChunk - 1) / kChunk;
        const Block* prev = pending;
        const long chunks = static_cast<long>(cur.chunks);
#pragma omp parallel num_threads(threads) proc_bind(close) if (chunks > 1)
        {
#pragma omp single nowait
            if (prev) {
                try {
                    emit(*prev);
                } catch (...) {  // a write error (disk full, interrupt): the map stops
                    write_failed = std::current_exception();
                    stop = true;
                }
            }
#pragma omp for schedule(dynamic, 1)
            for (long c = 0; c < chunks; ++c) {
                const size_t k = static_cast<size_t>(c);
                cur.text[k].clear();
                cur.failed[k] = nullptr;
                try {
                    for (size_t i = b0 + k * kChunk; i < std::min(b0 + cur.rows, b0 + (k + 1) * kChunk); ++i) {
                        if (stop.load(std::memory_order_relaxed)) break;
                        if (io::g_interrupted.load(std::memory_order_relaxed)) {
                            stop = true;
                            break;
                        }
                        const auto [w, T] = grid.at(i);
                        const solver::PointResult r = solver::solve_point(m, w, T, opt.detail);
                        format(r, i, cur.text[k]);
                        if (summary) cur.facts[i - b0] = PointFacts::of(r);
                        const size_t d = ++done;
                        if (opt.progress && omp_get_thread_num() == 0 && (d & 255) == 0) opt.progress(d, total);
                    }
                } catch (...) {
                    cur.failed[k] = std::current_exception();
                }
            }
        }
        if (write_failed) std::rethrow_exception(write_failed);
        io::throw_if_interrupted();  // an incomplete block is not written
        size_t bytes = 0;
        for (size_t c = 0; c < cur.chunks; ++c) {
            if (cur.failed[c]) std::rethrow_exception(cur.failed[c]);
            bytes += cur.text[c].size();
        }
        if (bytes > 0)
            block_rows = std::clamp(kBlockBytes * cur.rows / bytes / kChunk * kChunk, kMinBlock, kMaxBlock);
        pending = &cur;
    }
    if (pending) emit(*pending);
    if (opt.progress) opt.progress(done.load(), total);
}

RowFormatter csv_formatter(const solver::Model& m, bool detail, std::string prefix) {
    return [&m, detail, prefix = std::move(prefix)](const solver::PointResult& r, size_t, std::string& out) {
        out += prefix;
        append_csv_row(out, m, r, detail);
    };
}

}  // namespace gearloss::map
