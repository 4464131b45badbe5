#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/sweep.hpp"
#include "gearloss/map/job.hpp"
#include "test_support.hpp"

using namespace gearloss;
using test_support::TempConfig;

namespace {
std::string with_sweep(const std::string& sweep) {
    return test_support::read_file(test_support::source_path("configs/transfer-box.yaml")) + "\nsweep:\n" + sweep;
}
}  // namespace

TEST_CASE("sweep: every combination, first axis slowest, values applied", "[sweep]") {
    TempConfig cfg(with_sweep("  - {parameter: oil, values: [oils/75W90-A.yaml, oils/75W140-A.yaml]}\n"
                              "  - {parameter: [gears.w2.face_width, gears.w1.face_width], values: [30 mm, 35 mm, 40 mm]}\n"));
    const auto v = io::expand_sweep(cfg.path, std::nullopt);
    REQUIRE(v.size() == 6);
    CHECK(v[0].values == std::vector<std::string>{"oils/75W90-A.yaml", "30 mm"});
    CHECK(v[5].values == std::vector<std::string>{"oils/75W140-A.yaml", "40 mm"});
    CHECK(v[0].c.model.oil.name == "75W90-A");
    CHECK(v[3].c.model.oil.name == "75W140-A");
    // Both gears of the mesh took the face width (w1 is gear 0, w2 gear 1 in the case).
    for (int k = 0; k < 3; ++k) {
        const double b = (30.0 + 5 * k) * 1e-3;
        CHECK(v[k].c.model.gearbox.gears[0].spec.b == Catch::Detail::Approx(b));
        CHECK(v[k].c.model.gearbox.gears[1].spec.b == Catch::Detail::Approx(b));
    }
    // The base case itself loads (the sweep block is read, not applied).
    CHECK(io::load_case(cfg.path).sweep.size() == 2);
}

TEST_CASE("sweep: a path that names nothing is an input error at its line", "[sweep]") {
    const std::string text = with_sweep("  - {parameter: gears.w9.module, values: [3 mm]}\n");
    TempConfig cfg(text);
    try {
        (void)io::load_case(cfg.path);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.line == test_support::line_of(text, "parameter: gears.w9.module"));
        CHECK_THAT(e.message, Catch::Contains("names no value"));
    }
}

TEST_CASE("shards of a sweep job joined by merge equal the single run", "[sweep]") {
    TempConfig cfg(with_sweep("  - {parameter: housing.oil_level, values: [-30 mm, -10 mm]}\n"));
    std::vector<map::MapJob::Variant> variants;
    for (auto& v : io::expand_sweep(cfg.path, std::nullopt)) variants.push_back({v.values, std::move(v.c)});
    const map::MapJob job({"housing.oil_level"}, variants);
    map::MapOptions opt;
    opt.detail = true;
    const std::string single = map::run_job(job, opt, std::nullopt);
    REQUIRE(job.total_points() == 18);
    std::vector<std::string> files;
    for (int k = 4; k >= 1; --k) {  // written in reverse: merge must order them
        const std::string f = cfg.path + ".shard" + std::to_string(k);
        std::ofstream(f) << map::run_job(job, opt, map::Shard{k, 4});
        files.push_back(f);
    }
    CHECK(map::merge_shards(files) == single);
    // Rows of the two variants differ (the oil level changes the churning).
    CHECK(single.find("\n-30 mm,600,150,") != std::string::npos);
    CHECK(single.find("\n-10 mm,600,150,") != std::string::npos);
    // A shard of another job is refused.
    variants.pop_back();
    const map::MapJob other({"housing.oil_level"}, variants);
    std::ofstream(files[0]) << map::run_job(other, opt, map::Shard{4, 4});
    CHECK_THROWS_AS(map::merge_shards(files), InputError);
    for (const auto& f : files) std::filesystem::remove(f);
    CHECK_THROWS_AS(map::parse_shard("5/4"), InputError);
    CHECK(map::Shard{2, 3}.range(10) == std::pair<size_t, size_t>{3, 6});
}
