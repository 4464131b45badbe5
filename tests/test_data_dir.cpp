// The folder of the shipped data (lib/gearloss/io/data_dir.hpp), found from the environment or from the
// executable's place, in a private mkdtemp folder laid out as an installation and as a source
// tree with a build folder (tests/cli_install.sh runs a real installation).
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "gearloss/io/data_dir.hpp"
#include "test_support.hpp"

using namespace gearloss;
namespace fs = std::filesystem;

namespace {
using test_support::TempDir;
}  // namespace

TEST_CASE("data dir: installed, source tree, GEARLOSS_DATA_DIR", "[data_dir]") {
    TempDir t;
    const fs::path root = t.path;
    fs::create_directories(root / "prefix" / "bin");
    fs::create_directories(root / "prefix" / "share" / "gearloss" / "cycles");
    fs::create_directories(root / "src" / "build" / "app");
    fs::create_directories(root / "src" / "configs" / "cycles");
    fs::create_directories(root / "empty");

    // An installed binary: <prefix>/bin/gearloss -> <prefix>/share/gearloss.
    auto s = io::find_data_dir(nullptr, root / "prefix" / "bin" / "gearloss");
    REQUIRE(s.dir);
    CHECK(*s.dir == root / "prefix" / "share" / "gearloss");
    // A build folder of the source tree: <src>/build/app/gearloss -> <src>/configs, after the
    // installed layout was tried.
    s = io::find_data_dir("", root / "src" / "build" / "app" / "gearloss");
    REQUIRE(s.dir);
    CHECK(*s.dir == root / "src" / "configs");
    REQUIRE(s.tried.size() == 1);
    CHECK(s.tried[0] == (root / "src" / "build" / "share" / "gearloss").string() + " (not a folder)");
    // GEARLOSS_DATA_DIR wins, and is the only place searched.
    const std::string env = (root / "src" / "configs").string();
    s = io::find_data_dir(env.c_str(), root / "prefix" / "bin" / "gearloss");
    REQUIRE(s.dir);
    CHECK(*s.dir == root / "src" / "configs");
    const std::string empty = (root / "empty").string();
    s = io::find_data_dir(empty.c_str(), root / "prefix" / "bin" / "gearloss");
    CHECK_FALSE(s.dir);
    REQUIRE(s.tried.size() == 1);
    CHECK(s.tried[0] == "GEARLOSS_DATA_DIR=" + empty + " (no cycles/ folder there)");
    CHECK_THAT(s.explain(), Catch::Contains("Set GEARLOSS_DATA_DIR"));
    // Nothing beside a lone binary: both places named.
    s = io::find_data_dir(nullptr, root / "lone" / "bin" / "gearloss");
    CHECK_FALSE(s.dir);
    CHECK(s.explain() == "searched: " + (root / "lone" / "share" / "gearloss").string() + " (not a folder); " +
                             (root / "configs").string() +
                             " (not a folder). Set GEARLOSS_DATA_DIR to the folder that holds cycles/ "
                             "(<prefix>/share/gearloss of an installation, configs/ of the source tree)");
    // Unknown executable (no /proc).
    s = io::find_data_dir(nullptr, fs::path());
    CHECK_FALSE(s.dir);
    CHECK_THAT(s.explain(), Catch::Contains("/proc/self/exe"));
}
