#include <catch2/catch.hpp>
#include "loss_parts.hpp"
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <random>
#include <sstream>

#include "gearloss/case/config.hpp"
#include "gearloss/io/csv_format.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/map/map_stream.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"

using namespace gearloss;
constexpr double rpm = std::numbers::pi / 30;

namespace {
const char* kCases[] = {"configs/transfer-box.yaml", "configs/fzg-c40-paor.yaml"};

std::vector<std::string> split(std::string row) {
    while (!row.empty() && row.back() == '\n') row.pop_back();
    std::vector<std::string> cells;
    std::stringstream ss(row);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    if (!row.empty() && row.back() == ',') cells.push_back("");
    return cells;
}

// Every cell of a CSV row is empty or a finite number, except the status.
void check_cells(const std::string& row, size_t expected_cells) {
    std::string r = row;
    while (!r.empty() && r.back() == '\n') r.pop_back();
    std::stringstream ss(r);
    std::string cell;
    std::vector<std::string> cells;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    if (!r.empty() && r.back() == ',') cells.push_back("");
    CHECK(cells.size() == expected_cells);
    for (size_t i = 0; i < cells.size(); ++i) {
        const std::string& c = cells[i];
        // An explicit status; out_of_range names its cause (a bearing beyond any rolling bearing's n d_m at 60000 rpm).
        if (c.empty() || c == "ok" || c == "no_equilibrium" || c == "above_oil_limit" || c.rfind("out_of_range: ", 0) == 0)
            continue;
        INFO("cell " << i << " of " << row);
        char* end = nullptr;
        const double v = std::strtod(c.c_str(), &end);
        CHECK(end == c.c_str() + c.size());
        CHECK(std::isfinite(v));
    }
}
}  // namespace

TEST_CASE("property: no loss component is ever negative", "[properties]") {
    for (const char* f : kCases) {
        auto c = io::load_case(test_support::source_path(f));
        for (double T_oil : {233.15, 313.15, 393.15})
            for (double n : {0.0, 10.0, 500.0, 1500.0, 4000.0})
                for (double T : {-300.0, 0.0, 50.0, 300.0}) {
                    c.model.thermal.mode = solver::ThermalMode::fixed;
                    c.model.thermal.oil_temperature = T_oil;
                    const auto r = solver::solve_point(c.model, n * rpm, T, true);
                    const auto& L = r.losses;
                    INFO(f << " " << n << " rpm " << T << " N m " << T_oil << " K");
                    for (double v : L.power) CHECK(v >= 0);
                    for (const auto& d : L.detail)
                        for (size_t k = 0; k < d.values.size(); k += d.quantities) CHECK(d.values[k] >= 0);
                }
    }
}

TEST_CASE("property: total loss grows with torque at fixed speed and oil temperature", "[properties]") {
    for (const char* f : kCases) {
        auto c = io::load_case(test_support::source_path(f));
        c.model.thermal.mode = solver::ThermalMode::fixed;
        for (double T_oil : {293.15, 353.15, 413.15})
            for (double n : {100.0, 1000.0, 3000.0}) {
                c.model.thermal.oil_temperature = T_oil;
                double prev = -1;
                for (double T = 0; T <= 500; T += 20) {
                    const double P = solver::solve_point(c.model, n * rpm, T).losses.total();
                    INFO(f << " " << n << " rpm, " << T << " N m, " << T_oil << " K");
                    CHECK(P > prev);
                    prev = P;
                }
            }
    }
}

TEST_CASE("property: results are independent of grid order and thread count", "[properties]") {
    auto c = io::load_case(test_support::source_path("configs/fzg-c40-paor.yaml"));
    io::OperatingGrid grid;
    for (double n : {200.0, 700.0, 1300.0, 2100.0, 3000.0}) grid.speeds.push_back(n * rpm);
    grid.torques = {0, 46.6, 132.5, 265, 378.3};
    map::MapOptions one;
    one.threads = 1;
    one.detail = true;
    const auto ref = map::run_map(c.model, grid, one);
    std::map<std::pair<double, double>, std::string> by_point;
    for (const auto& r : ref) by_point[{r.speed_in, r.torque_in}] = map::csv_row(c.model, r, true);
    // The same points, shuffled into a point list, on 2 threads.
    io::OperatingGrid shuffled;
    shuffled.is_grid = false;
    for (size_t i = 0; i < grid.size(); ++i) shuffled.points.push_back(grid.at(i));
    std::mt19937 rng(7);
    std::shuffle(shuffled.points.begin(), shuffled.points.end(), rng);
    map::MapOptions two = one;
    two.threads = 2;
    const auto out = map::run_map(c.model, shuffled, two);
    REQUIRE(out.size() == ref.size());
    for (size_t i = 0; i < out.size(); ++i) {
        CHECK(out[i].speed_in == shuffled.points[i].first);
        CHECK(map::csv_row(c.model, out[i], true) == by_point.at({out[i].speed_in, out[i].torque_in}));
    }
}

TEST_CASE("property: a map streamed block by block is the map held whole, at every thread count", "[properties]") {
    // 5 x 2000 points: a first block of 4096 rows and larger ones after, near the oil limit at
    // high torque (points without equilibrium) as well; a prefix as a sweep's leading cells.
    // Truth: run_map (every result held), then csv_row and the summary in row order.
    auto c = io::load_case(test_support::source_path("configs/transfer-box.yaml"));
    io::OperatingGrid grid;
    for (double n : {300.0, 900.0, 1500.0, 2100.0, 2700.0}) grid.speeds.push_back(n * rpm);
    for (int k = 0; k < 2000; ++k) grid.torques.push_back(10 + 0.3 * k);
    map::MapOptions opt;
    opt.detail = true;
    const auto res = map::run_map(c.model, grid, opt);
    REQUIRE(res.size() == 10000);
    std::vector<std::string> rows;
    for (const auto& r : res) rows.push_back("a,b," + map::csv_row(c.model, r, true));
    const auto joined = [&](size_t a, size_t b) {
        std::string s;
        for (size_t i = a; i < b; ++i) s += rows[i];
        return s;
    };
    size_t no_equilibrium = 0;
    for (const auto& r : res) no_equilibrium += r.status == solver::PointStatus::no_equilibrium;
    CHECK(no_equilibrium > 0);
    const auto fmt = map::csv_formatter(c.model, true, "a,b,");
    for (int threads : {1, 2, 3}) {
        INFO(threads << " threads");
        opt.threads = threads;
        for (const auto& [a, b] : std::vector<std::pair<size_t, size_t>>{{0, 10000}, {100, 8300}, {4095, 4097}, {8191, 8193}, {9999, 20000}}) {
            INFO("rows " << a << "-" << b);
            std::string text;
            map::MapSummary summary;
            map::stream_rows(c.model, grid, a, b, opt, fmt, [&](std::string_view s) { text += s; }, &summary);
            CHECK(text == joined(a, std::min<size_t>(b, 10000)));
            if (a == 0 && b == 10000) CHECK(summary.json(0.1) == map::map_summary_json(res, 0.1));
        }
    }
    // A row that fails: the first failure in row order is thrown and its block is not
    // written. Row 70 is in the first block (nothing written); row 9000 is not (the first
    // block, 4096 rows, is written: whole rows, in order, none at or after the failure).
    for (size_t bad : {size_t(70), size_t(9000)}) {
        std::string text;
        const map::RowFormatter failing = [&](const solver::PointResult& r, size_t i, std::string& out) {
            if (i == bad || i == bad + 500) throw InputError("", 0, 0, "", "row " + std::to_string(i));
            fmt(r, i, out);
        };
        opt.threads = 2;
        try {
            map::stream_rows(c.model, grid, 0, 10000, opt, failing, [&](std::string_view s) { text += s; }, nullptr);
            FAIL("no error");
        } catch (const InputError& e) {
            CHECK(e.message == "row " + std::to_string(bad));
        }
        const auto written = static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
        CHECK(text == joined(0, written));
        CHECK(written == (bad < 4096 ? 0 : 4096));
    }
}

TEST_CASE("stress map: extreme but legal inputs give finite numbers or an explicit status", "[properties]") {
    const std::vector<double> speeds = {0, 1e-3, 1, 100, 3000, 20000, 60000};
    const std::vector<double> torques = {-2000, -1, 0, 1e-6, 1, 500, 5000};
    struct Variant { const char* name; std::string from, to, from_fzg, to_fzg; };
    // "Barely touching": the oil level 0.1 um above the lowest tip point of the
    // lowest dipping wheel (transfer box wheel 4: tip radius 54.2145 mm at the input
    // axis; FZG wheel: tip diameter 118.3647 mm, axes at the origin level).
    const Variant variants[] = {
        {"as shipped", "", "", "", ""},
        {"cold ambient -40 degC", "ambient: 25 degC", "ambient: -40 degC", "ambient: 25 degC", "ambient: -40 degC"},
        {"cold oil, fixed -40 degC", "mode: stabilised", "mode: fixed\n  oil_temperature: -40 degC  #", "mode: stabilised",
         "mode: fixed\n  oil_temperature: -40 degC  #"},
        {"hot oil, fixed 250 degC", "mode: stabilised", "mode: fixed\n  oil_temperature: 250 degC  #", "mode: stabilised",
         "mode: fixed\n  oil_temperature: 250 degC  #"},
        {"gear barely touching the oil", "oil_level: -30 mm", "oil_level: -54.2144 mm", "oil_level: 0 mm",
         "oil_level: -59.18225 mm"},
    };
    size_t cells_rows = 0, no_eq = 0;
    for (const char* f : kCases)
        for (const auto& v : variants) {
            std::string text = test_support::read_file(test_support::source_path(f));
            const bool fzg = std::string(f).find("fzg") != std::string::npos;
            if (!v.from.empty())
                text = fzg ? test_support::replace_once(text, v.from_fzg, v.to_fzg) : test_support::replace_once(text, v.from, v.to);
            test_support::TempConfig cfg(text);
            auto c = io::load_case(cfg.path);
            io::OperatingGrid g;
            for (double n : speeds) g.speeds.push_back(n * rpm);
            g.torques = torques;
            map::MapOptions opt;
            opt.detail = true;
            const auto res = map::run_map(c.model, g, opt);
            INFO(f << ": " << v.name);
            const size_t columns = split(map::csv_header(c.model, true)).size();
            for (const auto& r : res) {
                const std::string row = map::csv_row(c.model, r, true);
                check_cells(row, columns);
                CHECK(row.find("nan") == std::string::npos);
                CHECK(row.find("inf") == std::string::npos);
                no_eq += !solver::has_values(r.status);
                ++cells_rows;
            }
        }
    CHECK(cells_rows == 2 * 5 * 49);
    CHECK(no_eq > 0);  // the grid reaches powers no housing can reject
}

TEST_CASE("property: the heat balance holds at every stabilised point", "[properties]") {
    for (const char* f : kCases) {
        const auto c = io::load_case(test_support::source_path(f));
        for (double n : {100.0, 800.0, 2000.0})
            for (double T : {0.0, 100.0, 300.0}) {
                const auto r = solver::solve_point(c.model, n * rpm, T);
                if (!solver::has_values(r.status)) continue;
                const double Q = c.model.heat_flow(r.oil_temperature, r.ambient, n * rpm);
                INFO(f << " " << n << " rpm " << T << " N m");
                CHECK(std::abs(r.losses.total() - Q) < 0.05);
            }
    }
}

TEST_CASE("property: CSV numbers are printf's %.6g and %.Nf digit for digit", "[properties]") {
    // The truth is the C library's printf, a different route from std::to_chars: random
    // magnitudes from 1e-30 to 1e30 of both signs, random bit patterns, and the halfway cases
    // where rounding differs between implementations (x.5 at the 6th digit, 0.125 at 2 places).
    std::mt19937_64 g(7);
    std::uniform_real_distribution<double> exponent(-30, 30);
    std::vector<double> xs = {0.0, -0.0, 5e-324, 1.7976931348623157e308, 999999.5, 9999995, 0.00001234565, 0.125, -0.125, 2.5, 1e21};
    for (int i = 0; i < 200000; ++i) xs.push_back((i % 2 ? -1 : 1) * std::pow(10.0, exponent(g)));
    for (int i = 0; i < 50000; ++i) {
        const uint64_t bits = g();
        double d;
        std::memcpy(&d, &bits, sizeof d);
        if (std::isfinite(d)) xs.push_back(d);
    }
    for (int k = 0; k < 2000; ++k) {
        xs.push_back((100000 + k + 0.5) * 1e-3);
        xs.push_back((k + 0.5) / 1000.0);
    }
    const auto printf_text = [](const char* f, double v) {
        char b[512];
        std::snprintf(b, sizeof b, f, v);
        return std::string(b);
    };
    size_t differ = 0;
    for (double v : xs) {
        differ += io::csv_number(v) != printf_text("%.6g", v == 0.0 ? 0.0 : v);
        if (std::abs(v) < 1e30) {
            differ += io::csv_fixed(v, 2) != printf_text("%.2f", v);
            differ += io::csv_fixed(v, 6) != printf_text("%.6f", v);
        }
    }
    CHECK(differ == 0);
    CHECK(io::csv_number(-0.0) == "0");
    CHECK(io::csv_number(std::nan("")).empty());
    CHECK(io::csv_fixed(1e300, 2) == printf_text("%.2f", 1e300));  // past the stack buffer
}
