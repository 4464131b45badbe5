#pragma once
// A map job: every sweep variant x every grid point, in a fixed order, optionally cut
// into shards (`--shard K/N`) that `gearloss merge` joins into the very file a single
// run writes. Variants are loaded one at a time and rows are streamed: memory holds one
// variant and one block of rows, whatever the size of the job, and a shard loads only
// the variants its rows belong to.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/case/config.hpp"
#include "gearloss/case/sweep.hpp"
#include "gearloss/map/fingerprint.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/map/map_stream.hpp"

namespace gearloss::map {

class MapJob {
public:
    struct Variant {
        std::vector<std::string> values;  // one per sweep axis
        io::Case c;
    };
    // Variants loaded on demand: `values(v)` and `load(v)` for v < count; `grid`, when given,
    // is the operating grid of every variant (a sweep that does not touch it), so that rows
    // are counted and keyed without loading any variant; otherwise each variant is loaded
    // once here for its grid.
    struct Source {
        size_t count = 0;
        std::function<std::vector<std::string>(size_t)> values;
        std::function<io::Case(size_t)> load;  // loaded and checked; InputError naming the variant
        std::optional<io::OperatingGrid> grid;
        std::string thermal;                   // thermal mode of the variants (fingerprint)
    };
    // The variants of a sweep, each passed through `prepare` (the caller's options and checks);
    // an InputError while loading or preparing a variant names it (`(sweep variant ...)`).
    // The caller sets `grid` and `thermal`.
    static Source sweep_source(std::shared_ptr<io::Sweep> sweep, std::function<io::Case(io::Case)> prepare);
    MapJob() = default;
    MapJob(std::vector<std::string> sweep_labels, Source source);
    // Variants held in memory (a case without sweep, tests).
    MapJob(std::vector<std::string> sweep_labels, std::vector<Variant> variants);

    const std::vector<std::string>& sweep_labels() const { return labels_; }
    size_t variant_count() const { return source_.count; }
    size_t total_points() const { return offsets_.back(); }
    // What the job is computed from (case text, files it reads, overrides, version: the
    // CLI fills it in with input_fingerprint); empty in tests that build jobs by hand.
    Fingerprint inputs;
    // `inputs` plus the thermal mode and a hash of every row's key (sweep values and the
    // grid's speeds and torques as written): written on each shard's first line so that
    // shards of different jobs are not merged by mistake, and merge can say what differs.
    // Computed from the axes and grids, never by listing the rows.
    Fingerprint fingerprint() const;

    // Loads every variant with rows in [begin, end) and checks that its CSV columns are the
    // first variant's: a bad variant is reported before any point is solved.
    void check(size_t begin, size_t end, bool detail) const;
    // Rows [begin, end) of the job to `write`, in order (no header); every row also to
    // `summary` when given. Returns the number of rows.
    size_t run(const MapOptions& opt, size_t begin, size_t end, const TextSink& write, MapSummary* summary) const;
    std::string header(bool detail) const;  // the sweep columns, then the first variant's
    io::Case load(size_t v) const;
    std::vector<std::string> values(size_t v) const { return source_.values(v); }

private:
    std::vector<std::string> labels_;
    Source source_;
    std::vector<size_t> offsets_ = {0};  // first row of each variant, and the total
    uint64_t rows_key_ = 0;
    // The first variant's CSV columns, without and with --detail: loaded once, not per use.
    const std::string& columns(bool detail) const;
    mutable std::optional<std::string> columns_[2];
};

struct Shard {
    int index = 1, count = 1;  // K of N, 1-based
    // Rows [begin, end) of `total`: contiguous blocks, as even as possible.
    std::pair<size_t, size_t> range(size_t total) const;
};
// "K/N" with 1 <= K <= N.
Shard parse_shard(const std::string& text);

// What a call fixes beside a case's sweep (the CLI's options, the Python module's
// arguments): for each, the name to report when an axis of the sweep sets the same value,
// or null when the call leaves it to the case.
struct SweepOverrides {
    const char* oil = nullptr;              // another oil file
    const char* oil_temperature = nullptr;  // a fixed oil temperature
    const char* ratio = nullptr;            // the gearbox ratio
    const char* speeds = nullptr;           // the grid's speeds
    const char* torques = nullptr;          // the grid's torques
    // The name of the override that sets the case's value at `path` ("oil.name",
    // "operating.points", ...), or null.
    const char* setting(const std::string& path) const;
};
// The job of a case's sweep: every variant loaded through `prepare` (the caller's options
// and checks); `first`, the first variant so prepared, gives the grid of every variant when
// no axis touches the operating points (or `given` fixes both speeds and torques) and the
// thermal mode of the fingerprint. An axis that sets what `given` fixes is an InputError
// naming the override: its column would label values never used.
MapJob sweep_job(std::shared_ptr<io::Sweep> sweep, const io::Case& first, std::function<io::Case(io::Case)> prepare,
                 const SweepOverrides& given);

// The job, or one shard of it (then with a first line `# gearloss shard ...`), to `write`;
// every row also to `summary` when given. Returns the rows written.
size_t run_job(const MapJob& job, const MapOptions& opt, const std::optional<Shard>& shard, const TextSink& write,
               MapSummary* summary = nullptr);
// The same as a string (tests).
std::string run_job(const MapJob& job, const MapOptions& opt, const std::optional<Shard>& shard);

// Joins shard files (any order) into the single-run CSV, streamed to `write`; checks that
// they come from one job, that every shard is there exactly once and that every row is
// complete. Throws InputError naming the file (and line). Memory does not grow with the
// shards' size.
void merge_shards(const std::vector<std::string>& files, const TextSink& write);
std::string merge_shards(const std::vector<std::string>& files);

}  // namespace gearloss::map
