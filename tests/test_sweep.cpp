#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <yaml-cpp/yaml.h>

#include "gearloss/core/errors.hpp"
#include "gearloss/case/sweep.hpp"
#include "gearloss/map/job.hpp"
#include "gearloss/map/map_runner.hpp"
#include "test_support.hpp"

using namespace gearloss;
using test_support::TempConfig;

namespace {
std::string transfer_box() { return test_support::read_file(test_support::source_path("configs/transfer-box.yaml")); }
std::string with_sweep(const std::string& sweep) { return transfer_box() + "\nsweep:\n" + sweep; }

// The node at a sweep path in a throw-away copy (keys; list items by name or index).
YAML::Node old_slot(const YAML::Node& root, const std::string& path) {
    YAML::Node cur;
    cur.reset(root);
    std::stringstream ss(path);
    for (std::string seg; std::getline(ss, seg, '.');) {
        YAML::Node next;
        if (cur.IsMap()) {
            next.reset(cur[seg]);
        } else {
            for (size_t k = 0; k < cur.size(); ++k)
                if (cur[k].IsMap() && cur[k]["name"].IsDefined() && cur[k]["name"].Scalar() == seg) next.reset(cur[k]);
            if (!next.IsDefined()) next.reset(cur[static_cast<size_t>(std::stoul(seg))]);
        }
        cur.reset(next);
    }
    return cur;
}

// Variant v as the expansion before io::Sweep made it (kept here to compare with): the whole
// document cloned, the values written into the copy as text, emitted and read again.
io::Case old_variant(const std::string& file, size_t v) {
    const io::YamlNode root = io::YamlNode::load_file(file);
    const auto axes = io::read_sweep(root);
    YAML::Node doc = YAML::Clone(root.raw());
    doc.remove("sweep");
    std::vector<size_t> idx(axes.size());
    for (size_t k = axes.size(); k-- > 0;) {
        idx[k] = v % axes[k].values.size();
        v /= axes[k].values.size();
    }
    std::string tag;
    for (size_t k = 0; k < axes.size(); ++k) {
        tag += (tag.empty() ? "" : ", ") + axes[k].label + "=" + axes[k].values[idx[k]];
        for (const auto& path : axes[k].paths) {
            YAML::Node slot = old_slot(doc, path);
            slot = axes[k].values[idx[k]];  // a string: written into the copy's node
        }
    }
    YAML::Emitter em;
    em << doc;
    io::Case c = io::load_case_text(em.c_str(), file + " (sweep " + tag + ")",
                                    std::filesystem::path(file).parent_path().string(), std::nullopt);
    c.file = file;
    return c;
}

// The CSV rows (every component) of a case's map on its own grid.
std::string map_rows(const io::Case& c) {
    map::MapOptions opt;
    opt.detail = true;
    std::string rows = map::csv_header(c.model, true);
    for (const auto& r : map::run_map(c.model, c.grid, opt)) rows += map::csv_row(c.model, r, true);
    return rows;
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

TEST_CASE("Sweep: sizes, axes and values, first axis slowest, the case without its sweep", "[sweep]") {
    const std::string text = with_sweep("  - {parameter: oil, values: [oils/75W90-A.yaml, oils/75W140-A.yaml]}\n"
                                        "  - {parameter: housing.oil_level, values: [-30 mm, -20 mm, -10 mm]}\n");
    TempConfig cfg(text);
    io::Sweep sweep(cfg.path, std::nullopt);
    REQUIRE(sweep.size() == 6);
    REQUIRE(sweep.axes().size() == 2);
    CHECK(sweep.axes()[1].label == "housing.oil_level");
    CHECK(sweep.values(0) == std::vector<std::string>{"oils/75W90-A.yaml", "-30 mm"});
    CHECK(sweep.values(4) == std::vector<std::string>{"oils/75W140-A.yaml", "-20 mm"});
    CHECK_THROWS_AS(sweep.values(6), std::out_of_range);
    CHECK_THROWS_AS(sweep.variant(6), std::out_of_range);
    // Loaded in any order, each variant has its own values and nothing of the others.
    for (size_t v : {5, 0, 3, 1, 4, 2, 0}) {
        const io::Case c = sweep.variant(v);
        CHECK(c.file == cfg.path);
        CHECK(c.sweep.empty());
        CHECK(c.model.oil.name == (v < 3 ? "75W90-A" : "75W140-A"));
        REQUIRE(c.model.gearbox.oil_level);
        CHECK(*c.model.gearbox.oil_level == Approx(-30e-3 + 10e-3 * static_cast<double>(v % 3)));
        // The sweep block is not part of the variant's document (nor of its source index).
        CHECK_FALSE(c.model.source->has("sweep"));
        CHECK(c.model.source->has("housing.oil_level"));
    }
    // The swept value's place is its place in the sweep's list; the others keep theirs.
    const io::Case c = sweep.variant(2);
    CHECK(c.model.source->find("housing", "", "oil_level").line == test_support::line_of(text, "-10 mm]"));
    CHECK(c.model.source->find("housing", "", "oil_volume").line == test_support::line_of(text, "oil_volume: 2 L"));

    // A case without a sweep is one variant, the case itself.
    TempConfig plain(transfer_box());
    io::Sweep one(plain.path, std::nullopt);
    CHECK(one.size() == 1);
    CHECK(one.axes().empty());
    CHECK(one.values(0).empty());
    CHECK(map_rows(one.variant(0)) == map_rows(io::load_case(plain.path)));
}

TEST_CASE("Sweep: every variant's map equals that of the re-emitted case, byte for byte", "[sweep]") {
    TempConfig cfg(with_sweep("  - {parameter: oil, values: [oils/75W90-A.yaml, oils/75W140-A.yaml]}\n"
                              "  - {parameter: [gears.w2.face_width, gears.w1.face_width], values: [30 mm, 40 mm]}\n"
                              "  - {parameter: housing.oil_level, values: [-30 mm, -10 mm]}\n"
                              "  - {parameter: thermal.ambient, values: [20 degC, 40 degC]}\n"));
    io::Sweep sweep(cfg.path, std::nullopt);
    REQUIRE(sweep.size() == 16);
    const auto expanded = io::expand_sweep(cfg.path, std::nullopt);
    REQUIRE(expanded.size() == 16);
    std::set<std::string> distinct;
    for (size_t v = sweep.size(); v-- > 0;) {  // backwards: a variant owes nothing to the one before
        INFO("variant " << v);
        const std::string rows = map_rows(sweep.variant(v));
        CHECK(rows == map_rows(old_variant(cfg.path, v)));
        CHECK(rows == map_rows(expanded[v].c));
        distinct.insert(rows);
    }
    CHECK(distinct.size() == 16);  // every axis changes the losses
}

TEST_CASE("Sweep: aliases between the case and the values change no value and no other variant", "[sweep]") {
    // Nodes shared by the case and the sweep's lists (yaml-cpp makes an alias the very node of
    // its anchor): w1's face width is the first value of its own axis and w2's width too; w3's
    // width, swept by the first axis, is the second value of w1's axis; the ambient temperature
    // is the first value of its axis. Setting a value re-points these shared nodes, and the
    // values are taken as written in the lists whatever an earlier axis or variant did to them.
    std::string text = test_support::replace_once(transfer_box(), "face_width: 35 mm", "face_width: &fw 35 mm");  // w1
    text = test_support::replace_once(text, "face_width: 35 mm", "face_width: *fw");                               // w2
    text = test_support::replace_once(text, "face_width: 33.5 mm", "face_width: &w3 33.5 mm");                     // w3
    text = test_support::replace_once(text, "\nmeshes:\n",
                                      "\nsweep:\n"
                                      "  - {parameter: gears.w3.face_width, values: [31 mm, 32 mm]}\n"
                                      "  - {parameter: gears.w1.face_width, values: [*fw, *w3, 41 mm]}\n"
                                      "  - {parameter: thermal.ambient, values: [&amb 20 degC, 40 degC]}\n"
                                      "\nmeshes:\n");
    text = test_support::replace_once(text, "ambient: 25 degC", "ambient: *amb");
    TempConfig cfg(text);
    io::Sweep sweep(cfg.path, std::nullopt);
    REQUIRE(sweep.size() == 12);
    REQUIRE(sweep.values(2) == std::vector<std::string>{"31 mm", "33.5 mm", "20 degC"});
    const double b3[] = {31e-3, 32e-3}, b1[] = {35e-3, 33.5e-3, 41e-3}, ambient[] = {293.15, 313.15};
    for (size_t v : {0, 3, 11, 2, 9, 0, 5, 1, 3, 7, 10, 4, 6, 8, 2}) {
        INFO("variant " << v);
        const io::Case c = sweep.variant(v);
        CHECK(c.model.gearbox.gears[2].spec.b == Approx(b3[v / 6]));        // w3
        CHECK(c.model.gearbox.gears[0].spec.b == Approx(b1[v / 2 % 3]));    // w1
        CHECK(c.model.gearbox.gears[1].spec.b == Approx(b1[v / 2 % 3]));    // w2, the same node as w1's
        CHECK(c.model.thermal.ambient == Approx(ambient[v % 2]));
        CHECK(map_rows(c) == map_rows(old_variant(cfg.path, v)));
    }
}

TEST_CASE("Sweep: an error in a swept value points at the value in the sweep's list and names the variant", "[sweep]") {
    const std::string text = with_sweep("  - {parameter: thermal.ambient, values: [20 degC, 40 degC]}\n"
                                        "  - parameter: housing.oil_level\n"
                                        "    values:\n"
                                        "      - -30 mm\n"
                                        "      - -7 kg\n");
    TempConfig cfg(text);
    io::Sweep sweep(cfg.path, std::nullopt);
    REQUIRE(sweep.size() == 4);
    try {
        (void)sweep.variant(3);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.file == cfg.path);
        CHECK(e.line == test_support::line_of(text, "- -7 kg"));
        CHECK(e.column == 9);
        CHECK(e.key == "housing.oil_level");
        CHECK_THAT(e.message, Catch::Contains("'-7 kg' has dimension"));
        CHECK_THAT(e.message, Catch::EndsWith(" (sweep variant thermal.ambient=40 degC, housing.oil_level=-7 kg)"));
    }
    // The failed variant left nothing behind: the next one is the case with its own values.
    CHECK(map_rows(sweep.variant(2)) == map_rows(old_variant(cfg.path, 2)));
    // expand_sweep stops at the same error.
    CHECK_THROWS_WITH(io::expand_sweep(cfg.path, std::nullopt), Catch::Contains("(sweep variant thermal.ambient=20 degC, "
                                                                                "housing.oil_level=-7 kg)"));
}

TEST_CASE("Sweep: an error elsewhere in a variant points at its own line in the case and names the variant", "[sweep]") {
    // The value that is wrong is in the case, not swept: the error keeps its line.
    std::string text = test_support::replace_once(transfer_box(), "emissivity: 0.9", "emissivity: 2");
    text += "\nsweep:\n  - {parameter: housing.oil_level, values: [-30 mm, -10 mm]}\n";
    TempConfig cfg(text);
    io::Sweep sweep(cfg.path, std::nullopt);
    for (size_t v = 0; v < 2; ++v) try {
            (void)sweep.variant(v);
            FAIL("no error");
        } catch (const InputError& e) {
            CHECK(e.file == cfg.path);
            CHECK(e.line == test_support::line_of(text, "emissivity: 2"));
            CHECK_THAT(e.message, Catch::StartsWith("emissivity must be in [0, 1]"));
            CHECK_THAT(e.message,
                       Catch::EndsWith(std::string(" (sweep variant housing.oil_level=") + (v ? "-10" : "-30") + " mm)"));
        }
}

TEST_CASE("Sweep: oil files named by the variants are read once each, their errors at their own line", "[sweep]") {
    test_support::TempDir dir;
    const std::string good = test_support::read_file(test_support::source_path("configs/oils/75W90-A.yaml"));
    dir.write("oils/A.yaml", good);
    dir.write("oils/B.yaml", test_support::read_file(test_support::source_path("configs/oils/75W140-A.yaml")));
    const std::string broken = test_support::replace_once(good, "density: 885 kg/m^3", "density: 885 kg");
    dir.write("oils/broken.yaml", broken);
    const std::string text = test_support::replace_once(transfer_box(), "oil: oils/75W90-A.yaml", "oil: oils/A.yaml") +
                             "\nsweep:\n"
                             "  - {parameter: oil, values: [oils/A.yaml, oils/B.yaml, oils/broken.yaml, oils/none.yaml]}\n"
                             "  - {parameter: housing.oil_level, values: [-30 mm, -10 mm]}\n";
    const std::string file = dir.write("case.yaml", text);
    io::Sweep sweep(file, std::nullopt);
    CHECK(sweep.variant(0).model.oil.name == "75W90-A");
    // Once read, A.yaml is not read again by this sweep: its later variants keep the oil it held.
    dir.write("oils/A.yaml", "not: an oil\n");
    CHECK(sweep.variant(1).model.oil.name == "75W90-A");
    CHECK(sweep.variant(2).model.oil.name == "75W140-A");
    CHECK(sweep.variant(0).model.oil.name == "75W90-A");
    CHECK_THROWS_AS(io::Sweep(file, std::nullopt).variant(0), InputError);  // a new sweep reads it anew
    try {
        (void)sweep.variant(5);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.file == (dir.path / "oils/broken.yaml").string());
        CHECK(e.line == test_support::line_of(broken, "density: 885 kg"));
        CHECK_THAT(e.message, Catch::EndsWith(" (sweep variant oil=oils/broken.yaml, housing.oil_level=-10 mm)"));
    }
    try {
        (void)sweep.variant(6);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.file == file);
        CHECK(e.line == test_support::line_of(text, "oils/none.yaml"));
        CHECK_THAT(e.message, Catch::Contains("does not exist"));
        CHECK_THAT(e.message, Catch::EndsWith(" (sweep variant oil=oils/none.yaml, housing.oil_level=-30 mm)"));
    }
}

TEST_CASE("Sweep: a path an earlier axis took away is an error at its parameter", "[sweep]") {
    const std::string text = with_sweep("  - {parameter: gears.w1.name, values: [w1, w9]}\n"
                                        "  - {parameter: gears.w1.face_width, values: [30 mm]}\n");
    TempConfig cfg(text);
    io::Sweep sweep(cfg.path, std::nullopt);
    CHECK(sweep.variant(0).model.gearbox.gears[0].spec.b == Approx(30e-3));
    try {
        (void)sweep.variant(1);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.line == test_support::line_of(text, "parameter: gears.w1.face_width"));
        CHECK_THAT(e.message, Catch::Contains("names no value once the earlier axes are set"));
        CHECK_THAT(e.message, Catch::EndsWith("(sweep variant gears.w1.name=w9, gears.w1.face_width=30 mm)"));
    }
    CHECK(sweep.variant(0).model.gearbox.gears[0].spec.b == Approx(30e-3));  // the name is w1 again
}
