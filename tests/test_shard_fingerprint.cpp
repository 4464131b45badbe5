// The job fingerprint on a shard's first line: stable hashes, file contents rather than
// paths, and merge refusing shards of different jobs with the differing component named.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/config.hpp"
#include "gearloss/map/fingerprint.hpp"
#include "gearloss/map/job.hpp"
#include "test_support.hpp"

using namespace gearloss;
namespace fs = std::filesystem;

namespace {
using test_support::TempDir;

std::string source(const std::string& rel) { return test_support::read_file(test_support::source_path(rel)); }

map::MapJob job_for(const std::string& config, const map::JobInputs& in) {
    map::MapJob job;
    io::Case c = io::load_case(config);
    c.grid.speeds.resize(2);
    c.grid.torques.resize(1);
    job.variants.push_back({{}, std::move(c)});
    job.inputs = map::input_fingerprint(in);
    return job;
}

std::string write_shard(const TempDir& d, const std::string& name, const map::MapJob& job, int k, int n) {
    const std::string f = (d.path / name).string();
    std::ofstream(f) << map::run_job(job, map::MapOptions{}, map::Shard{k, n}).csv;
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
    CHECK(map::merge_shards({s2, s1}) == map::run_job(base, {}, std::nullopt).csv);

    const auto other_version = job_for(config, {.config = config, .version = "9.9.9"});
    const std::string v2 = write_shard(d, "v2.csv", other_version, 2, 2);
    const std::string e1 = merge_error({s1, v2});
    CHECK_THAT(e1, Catch::Contains("program version: 9.9.9 in " + v2 + ", " GEARLOSS_VERSION " in " + s1));

    const auto detail = job_for(config, {.config = config, .detail = true});
    const std::string e2 = merge_error({s1, write_shard(d, "d2.csv", detail, 2, 2)});
    CHECK_THAT(e2, Catch::Contains("per-component columns (--detail): 1 in"));
    CHECK_THAT(e2, Catch::Contains("differs from " + s1));
}
