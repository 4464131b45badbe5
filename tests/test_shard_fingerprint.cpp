// The job fingerprint on a shard's first line: stable hashes, file contents rather than
// paths, and merge refusing shards of different jobs with the differing component named.
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <algorithm>
#include <limits>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "gearloss/core/errors.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/map/fingerprint.hpp"
#include "gearloss/map/job.hpp"
#include "test_support.hpp"

using namespace gearloss;
namespace fs = std::filesystem;

namespace {
using test_support::TempDir;

std::string source(const std::string& rel) { return test_support::read_file(test_support::source_path(rel)); }

map::MapJob job_for(const std::string& config, const map::JobInputs& in) {
    io::Case c = io::load_case(config);
    c.grid.speeds.resize(2);
    c.grid.torques.resize(1);
    std::vector<map::MapJob::Variant> v;
    v.push_back({{}, std::move(c)});
    map::MapJob job({}, std::move(v));
    job.inputs = map::input_fingerprint(in);
    return job;
}

std::string write_shard(const TempDir& d, const std::string& name, const map::MapJob& job, int k, int n) {
    const std::string f = (d.path / name).string();
    std::ofstream(f) << map::run_job(job, map::MapOptions{}, map::Shard{k, n}); 
    return f;
}

std::string merge_error(const std::vector<std::string>& files) {
    try {
        (void)map::merge_shards(files);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST_CASE("shard fingerprint: FNV-1a is the fixed published function, not std::hash", "[shard]") {
    // FNV-1a 64 of "a" is af63dc4c8601ec8c (the published test vector); add() then mixes
    // in the 0xff separator. Pinned: shards of one job written by two builds must agree.
    CHECK(map::Fnv1a().add("a").hex() == "089bc907b544c769");
    CHECK(map::Fnv1a().add("ab").add("c").h != map::Fnv1a().add("a").add("bc").h);
    map::Fingerprint fp;
    fp.add("version", "0.1.0");
    fp.add("oil-temp", "333.15K");
    const auto back = map::Fingerprint::parse(fp.text());
    CHECK(back.parts() == fp.parts());
    CHECK(back.total() == fp.total());
}

TEST_CASE("shard fingerprint: contents count, not paths", "[shard]") {
    TempDir a, b;
    const std::string text = source("configs/transfer-box.yaml"), oil = source("configs/oils/75W90-A.yaml");
    for (const auto* d : {&a, &b}) {
        d->write("case.yaml", text);
        d->write("oils/75W90-A.yaml", oil);
    }
    // The same case from two directories (and named by a path with a detour): one job.
    const auto fa = map::input_fingerprint({.config = (a.path / "case.yaml").string()});
    const auto fb = map::input_fingerprint({.config = (b.path / "oils" / ".." / "case.yaml").string()});
    CHECK(fa.text() == fb.text());
    CHECK(fa.text().find("file:oil=") != std::string::npos);
    // The oil edited under the same name: the case's oil file is named as what differs.
    b.write("oils/75W90-A.yaml", test_support::replace_once(oil, "density: 885 kg", "density: 886 kg"));
    const auto fc = map::input_fingerprint({.config = (b.path / "case.yaml").string()});
    const auto d = fc.differences(fa, "b", "a");
    REQUIRE(d.size() == 1);
    CHECK_THAT(d[0], Catch::Contains("oil file content (the case's 'oil' file)"));
    // Overrides are components of their own, the temperature shown as resolved.
    const auto ft = map::input_fingerprint({.config = (a.path / "case.yaml").string(), .oil_temperature = 333.15});
    const auto dt = ft.differences(fa, "b", "a");
    REQUIRE(dt.size() == 1);
    CHECK(dt[0] == "oil temperature override (--oil-temp): 333.15K in b, none in a");
}

TEST_CASE("shard fingerprint: merge names what differs, and merges one job", "[shard]") {
    TempDir d;
    d.write("case.yaml", source("configs/transfer-box.yaml"));
    d.write("oils/75W90-A.yaml", source("configs/oils/75W90-A.yaml"));
    const std::string config = (d.path / "case.yaml").string();
    const auto base = job_for(config, {.config = config});
    const std::string s1 = write_shard(d, "s1.csv", base, 1, 2), s2 = write_shard(d, "s2.csv", base, 2, 2);
    CHECK(map::merge_shards({s2, s1}) == map::run_job(base, {}, std::nullopt));

    const auto other_version = job_for(config, {.config = config, .version = "9.9.9"});
    const std::string v2 = write_shard(d, "v2.csv", other_version, 2, 2);
    const std::string e1 = merge_error({s1, v2});
    CHECK_THAT(e1, Catch::Contains("program version: 9.9.9 in " + v2 + ", " GEARLOSS_VERSION " in " + s1));

    const auto detail = job_for(config, {.config = config, .detail = true});
    const std::string e2 = merge_error({s1, write_shard(d, "d2.csv", detail, 2, 2)});
    CHECK_THAT(e2, Catch::Contains("per-component columns (--detail): 1 in"));
    CHECK_THAT(e2, Catch::Contains("differs from " + s1));
}

TEST_CASE("shard: a shard of a 10^9-point job loads only its variants and keys the rows without listing them", "[shard]") {
    // 100 000 sweep variants of a 100 x 100 grid: 10^9 rows. Counting the loads shows what
    // the job reads: nothing to count the rows and key them (the grid is shared), then the
    // first variant (its columns are the job's) and the one variant of the shard.
    io::Case c = io::load_case(test_support::source_path("configs/transfer-box.yaml"));
    c.grid.speeds.clear();
    c.grid.torques.clear();
    for (int k = 0; k < 100; ++k) {
        c.grid.speeds.push_back((300 + 10 * k) * 3.14159265358979323846 / 30);
        c.grid.torques.push_back(10 + 2 * k);
    }
    size_t loads = 0;
    std::string changed;  // a value of variant 7 changed: another job
    map::MapJob::Source src;
    src.count = 100000;
    src.values = [&](size_t v) { return std::vector<std::string>{v == 7 ? "7" + changed : std::to_string(v)}; };
    src.load = [&](size_t) {
        ++loads;
        return c;
    };
    src.grid = c.grid;
    src.thermal = "stabilised";
    const map::MapJob job({"x"}, src);
    CHECK(job.total_points() == 1'000'000'000);
    const auto fp = job.fingerprint();
    CHECK(fp.text() == job.fingerprint().text());
    CHECK(loads == 0);
    const auto [begin, end] = map::Shard{50000, 100000}.range(job.total_points());
    CHECK(begin == 499'990'000);
    CHECK(end == 500'000'000);
    std::string text;
    map::MapOptions opt;
    opt.threads = 1;
    CHECK(job.run(opt, begin + 9990, end, [&](std::string_view s) { text += s; }, nullptr) == 10);
    CHECK(loads == 2);
    CHECK(std::count(text.begin(), text.end(), '\n') == 10);
    CHECK(text.rfind("49999,1290,190,", 0) == 0);  // variant 49999, row 9990: speed 99 (1290 rpm), torque 90 (190 N m)
    changed = "x";
    CHECK(map::MapJob({"x"}, src).fingerprint().differences(fp, "b", "a").size() == 1);
    // The rows of a job near 2^64 / N are cut without overflow, contiguous and complete.
    const size_t huge = std::numeric_limits<size_t>::max() / 3;
    size_t next = 0;
    for (int k = 1; k <= 7; ++k) {
        const auto [a, b] = map::Shard{k, 7}.range(huge);
        CHECK(a == next);
        next = b;
    }
    CHECK(next == huge);
}

TEST_CASE("merge streams: shards larger than a read piece, and damage found with its line", "[shard]") {
    // Shards are written here by hand from a text whose rows are known, so the expected
    // merge is the concatenation, not the program's own output. 100 000 rows of ~23 bytes:
    // each shard is longer than the 1 MiB piece LineReader reads, so rows cross pieces.
    TempDir d;
    const std::string header = "speed_in_rpm,torque_in_Nm,P_W,status\n";
    std::vector<std::string> rows;
    for (int i = 0; i < 100000; ++i) rows.push_back(fmt::format("{},{}.25,{:.6f},ok\n", 600 + i, i % 97, 1e3 / (i + 1)));
    const auto shard_text = [&](int k, int n, size_t total) {
        const auto [a, b] = map::Shard{k, n}.range(total);
        std::string s = fmt::format("# gearloss shard {}/{}: rows {}-{} of {}, job 00000000000000ab; case=x\n", k, n, a, b, total);
        s += header;
        for (size_t i = a; i < b; ++i) s += rows[i];
        return s;
    };
    std::string all = header;
    for (const auto& r : rows) all += r;
    const std::string s1 = d.write("s1.csv", shard_text(1, 2, 100000)), s2 = d.write("s2.csv", shard_text(2, 2, 100000));
    REQUIRE(std::filesystem::file_size(s1) > (size_t{1} << 20));
    CHECK(map::merge_shards({s2, s1}) == all);
    // Written as it is read: the sink gets pieces, never the whole text at once.
    size_t pieces = 0, largest = 0;
    map::merge_shards({s1, s2}, [&](std::string_view s) {
        ++pieces;
        largest = std::max(largest, s.size());
    });
    CHECK(pieces >= 4);
    CHECK(largest <= (size_t{1} << 20) + 100);

    const auto error_of = [&](const std::string& text2) {
        return merge_error({s1, d.write("bad.csv", text2)});
    };
    const std::string good2 = shard_text(2, 2, 100000);
    // The last row cut (no line end), a row missing, a row too many.
    CHECK_THAT(error_of(good2.substr(0, good2.size() - 1)), Catch::Contains("incomplete run"));
    CHECK_THAT(error_of(good2.substr(0, good2.size() - rows.back().size())),
               Catch::Contains("has 49999 rows, the shard line promises 50000"));
    CHECK_THAT(error_of(good2 + rows[0]), Catch::Contains("has 50001 rows, the shard line promises 50000"));
    // A control byte on the row 10 000 of shard 2: line 10 002 of its file, told by place.
    std::string ctl = good2;
    const size_t at = ctl.find(rows[50000 + 9999]);
    ctl[at + 2] = '\x01';
    CHECK_THAT(error_of(ctl), Catch::Contains("bad.csv:10002:3: control byte 0x01"));
    // An infinite cell, a missing cell: file, line (and column).
    std::string inf = good2;
    inf.replace(inf.find(rows[50000 + 20]), rows[50000 + 20].size(), "620,1.25,inf,ok\n");
    CHECK_THAT(error_of(inf), Catch::Contains("bad.csv:23:3: 'inf' is not a finite number"));
    std::string short_row = good2;
    short_row.replace(short_row.find(rows[50000 + 3]), rows[50000 + 3].size(), "603,1.25,ok\n");
    CHECK_THAT(error_of(short_row), Catch::Contains("bad.csv:6: 3 cells, the header has 4"));
    // A line longer than any input line may be (64 KiB), found without reading it whole.
    std::string longline = good2;
    longline.insert(longline.find(rows[50000 + 5]), std::string(100000, '7') + ",");
    CHECK_THAT(error_of(longline), Catch::Contains("bad.csv:8: line longer than 65536 bytes"));
    // A shard line edited to rows another shard holds.
    std::string moved = good2;
    moved.replace(0, moved.find('\n'), "# gearloss shard 2/2: rows 49000-99000 of 100000, job 00000000000000ab; case=x");
    CHECK_THAT(error_of(moved), Catch::Contains("holds rows 50000-100000, not 49000-99000"));
}
