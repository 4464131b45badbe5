// A thread keeps its operating-point storage from one point to the next (gearloss/solver/operating_point.cpp)
// and the bearings keep the powers of their dimensions in it. A model changed between two
// solves on one thread, as a sweep or a test does, must give what a fresh thread gives.
#include <catch2/catch.hpp>
#include <numbers>
#include <thread>

#include "gearloss/case/config.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;

TEST_CASE("reused point storage follows a changed bearing", "[solver][bearings]") {
    auto m = io::load_case(test_support::source_path("configs/transfer-box.yaml")).model;
    const double w = 1500 * std::numbers::pi / 30;
    const double first = solver::solve_point(m, w, 200, false).losses.total();  // fills this thread's storage
    for (auto& b : m.gearbox.bearings) {  // the same model changed in place: its storage is reused
        b.spec.d *= 1.2;
        b.spec.D *= 1.2;
    }
    double fresh = 0;
    std::thread([&] { fresh = solver::solve_point(m, w, 200, false).losses.total(); }).join();
    const double after = solver::solve_point(m, w, 200, false).losses.total();
    CHECK(after == fresh);
    CHECK(after != first);  // the change matters, so the comparison can fail
}
