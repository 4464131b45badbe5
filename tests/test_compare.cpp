#include <catch2/catch.hpp>
#include <sstream>

#include "gearloss/case/config.hpp"
#include "gearloss/map/compare.hpp"
#include "gearloss/map/map_runner.hpp"
#include "test_support.hpp"

using namespace gearloss;

TEST_CASE("oil comparison: the 75W140-A / 75W90-A ranking flips with torque (seed 001)", "[compare]") {
    // Seed 001 (Pereira 2017) §3.7.3, Fig. 3.13: 75W140-A loses more at low torque and less than
    // 75W90-A at 200-250 N m, on the 600-800 rpm x 150-250 N m grid (§3.4, matrix 3.1).
    auto a = io::load_case(test_support::source_path("configs/transfer-box.yaml"));
    auto b = a;
    io::replace_oil(a, io::load_oil_file(test_support::source_path("configs/oils/75W90-A.yaml")));
    io::replace_oil(b, io::load_oil_file(test_support::source_path("configs/oils/75W140-A.yaml")));
    const auto ra = map::run_map(a.model, a.grid, {});
    const auto rb = map::run_map(b.model, b.grid, {});
    REQUIRE(ra.size() == 9);
    for (size_t i = 0; i < ra.size(); ++i) {
        const double dP = rb[i].losses.total() - ra[i].losses.total();
        INFO(ra[i].torque_in << " N m");
        if (ra[i].torque_in == 150) CHECK(dP > 0);
        if (ra[i].torque_in == 250) CHECK(dP < 0);
        // The row reports B - A of the two maps.
        std::stringstream row(map::compare_row(ra[i], rb[i]));
        std::string cell;
        for (int k = 0; k < 5; ++k) std::getline(row, cell, ',');
        CHECK(std::stod(cell) == Catch::Detail::Approx(dP).epsilon(1e-5));
    }
}
