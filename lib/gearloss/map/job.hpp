#pragma once
// A map job: every sweep variant x every grid point, in a fixed order, optionally cut
// into shards (`--shard K/N`) that `gearloss merge` joins into the very file a single
// run writes.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/io/config.hpp"
#include "gearloss/map/fingerprint.hpp"
#include "gearloss/map/map_runner.hpp"

namespace gearloss::map {

struct MapJob {
    std::vector<std::string> sweep_labels;  // leading CSV columns (empty without a sweep)
    struct Variant {
        std::vector<std::string> values;
        io::Case c;
    };
    std::vector<Variant> variants;  // one (no sweep) or the sweep's cartesian product
    size_t total_points() const;
    std::string header(bool detail) const;
    // What the job is computed from (case text, files it reads, overrides, version: the
    // CLI fills it in with input_fingerprint); empty in tests that build jobs by hand.
    Fingerprint inputs;
    // `inputs` plus the thermal mode of the variants and a hash of every row's key (sweep
    // values, speed, torque): written on each shard's first line so that shards of
    // different jobs are not merged by mistake, and merge can say what differs.
    Fingerprint fingerprint() const;
};

struct Shard {
    int index = 1, count = 1;  // K of N, 1-based
    // Rows [begin, end) of `total`: contiguous blocks, as even as possible.
    std::pair<size_t, size_t> range(size_t total) const;
};
// "K/N" with 1 <= K <= N.
Shard parse_shard(const std::string& text);

struct JobOutput {
    std::string csv;  // of the job, or of one shard (then with a first line `# gearloss shard ...`)
    std::vector<solver::PointResult> results;  // the rows computed, in order
};
JobOutput run_job(const MapJob& job, const MapOptions& opt, const std::optional<Shard>& shard);

// Joins shard files (any order) into the single-run CSV; checks that they come from one
// job and that every shard is there exactly once. Throws InputError naming the file.
std::string merge_shards(const std::vector<std::string>& files);

}  // namespace gearloss::map
