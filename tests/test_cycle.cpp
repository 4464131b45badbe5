#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gearloss/clutch/wet_clutch.hpp"
#include "gearloss/cycle/drive_cycle.hpp"
#include "gearloss/cycle/simulate.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/results/cycle_report.hpp"
#include "gearloss/case/drive_cycle_csv.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "test_support.hpp"
#include "gearloss/torque_converter/torque_converter.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

namespace {
std::vector<std::string> cycle_dirs() { return {test_support::source_path("configs/cycles")}; }
constexpr double kC = 273.15;

cycle::Powertrain powertrain(const std::string& config) {
    const auto c = io::load_case(test_support::source_path(config));
    return io::load_powertrain(c, std::nullopt);
}

// Constant speed for `seconds` after a 30 s ramp from rest.
cycle::DriveCycle steady_cycle(double kmh, int seconds) {
    cycle::DriveCycle c;
    c.name = "steady";
    for (int t = 0; t <= seconds; ++t) {
        c.time.push_back(t);
        c.speed.push_back(std::min(1.0, t / 30.0) * kmh / 3.6);
    }
    return c;
}
}  // namespace

TEST_CASE("drive cycles: duration and distance against the published figures", "[cycle]") {
    // NEDC: 1180 samples (0-1179 s; the official 1180 s cycle ends at rest), 11.023 km official.
    const auto nedc = io::resolve_cycle("nedc", cycle_dirs());
    CHECK(nedc.time.size() == 1180);
    CHECK(nedc.duration() == 1179.0);
    CHECK(nedc.distance() / 1e3 == Approx(11.023).margin(0.005));
    // WLTC class 3b (UN GTR No. 15): 1800 s, 23.266 km integrated from the shipped 1 Hz trace.
    const auto wltc = io::resolve_cycle("wltc", cycle_dirs());
    CHECK(wltc.duration() == 1800.0);
    CHECK(wltc.distance() / 1e3 == Approx(23.266).margin(0.005));
    // Seed 003's ARTEMIS (§4.2: urban + highway, 2061 s and 33 605 m; motorway 130 assumed).
    const auto art = io::resolve_cycle("artemis", cycle_dirs());
    CHECK(art.duration() == 2061.0);
    CHECK(art.distance() == Approx(33605).margin(10));
    CHECK_THROWS_AS(io::resolve_cycle("no-such-cycle", cycle_dirs()), InputError);
}

TEST_CASE("wet clutch drag: Couette shear against a hand calculation", "[cycle][clutch]") {
    // 8 interfaces, r 60-80 mm, h 0.1 mm, eta 10 mPa s, slip 100 rad/s, smooth (H >> 7):
    // T = 8 pi 0.01 100 (0.08^4 - 0.06^4) / (2 x 1e-4) = 3.5186 N m, P = 351.86 W.
    clutch::WetClutchPack c{"C", 8, 0.06, 0.08, 1e-4, 1e-8, 0.0};
    const auto d = clutch::open_pack_drag(c, 0.01, 850, 100);
    CHECK(d.torque == Approx(3.5186).epsilon(1e-4));
    CHECK(d.power == Approx(351.86).epsilon(1e-4));
    // Patir & Cheng shear factor at H = 2: 11.1 2^2.31 exp(-4.76 + 0.44) = 0.73207.
    CHECK(clutch::shear_stress_factor(2.0) == Approx(0.73207).epsilon(1e-4));
    CHECK(clutch::shear_stress_factor(8.0) == 0.0);
    // A supply that cannot fill the gap: the film's centrifugal outflow at the wetted radius
    // equals the supply (mass conservation), and the drag falls below the full-film value.
    // Full-film outflow at 400 rad/s: pi 1e-12 850 400^2 (0.08^2 - 0.06^2) / (40 0.01 ln(4/3)) = 1.039e-5 m^3/s.
    const double w = 400, eta = 0.01, rho = 850;
    c.oil_supply = 0.9 * 1.039e-5;
    const double rw = clutch::wetted_outer_radius(c, eta, rho, w);
    REQUIRE(rw < c.r_outer);
    const double Q = std::numbers::pi * std::pow(c.clearance, 3) * rho * w * w * (rw * rw - c.r_inner * c.r_inner) /
                     (40 * eta * std::log(rw / c.r_inner));
    CHECK(Q == Approx(c.oil_supply).epsilon(1e-4));
    CHECK(clutch::open_pack_drag(c, eta, rho, w).torque < 3.5186 * 4);  // full film at 400 rad/s: 4 x 3.5186
    CHECK(clutch::open_pack_drag(c, eta, rho, w).torque > 0.0);
}

TEST_CASE("torque converter: HI viscous correction and the converter balance", "[cycle][converter]") {
    // US-unit check: nu 100 cSt, H 100 ft, Q 500 gpm, N 1750 rpm -> B = 3.30834, C_eta = 0.86121.
    const double B = torque_converter::hi_viscosity_parameter(100, 30.48, 500 * 6.30901964e-5, 1750 * std::numbers::pi / 30);
    CHECK(B == Approx(3.30834).epsilon(1e-5));
    CHECK(torque_converter::hi_efficiency_correction(B) == Approx(0.86121).epsilon(1e-4));
    CHECK(torque_converter::hi_efficiency_correction(10.0) == Approx(0.53962).epsilon(1e-4));
    CHECK(torque_converter::hi_efficiency_correction(0.8) == 1.0);

    const auto pt = powertrain("configs/automatic-6speed.yaml");
    const auto& tc = *pt.torque_converter;
    const double idle = pt.vehicle.engine.idle_speed;
    // Stall at idle: the pump absorbs (w/K(0))^2 and all its power heats the oil.
    const auto stall = torque_converter::operate(tc, 0.0, 0.0, idle, 10.0, false);
    const double K0 = tc.curve.capacity.front();
    CHECK(stall.pump_torque == Approx((idle / K0) * (idle / K0)).epsilon(1e-9));
    CHECK(stall.loss == Approx(stall.pump_torque * idle).epsilon(1e-9));
    // Drive: the turbine receives the demand, T_t = TR C_eta T_p with T_p = (w_p / K(SR))^2,
    // and the loss is the power difference.
    const double wt = 150, Tt = 180;
    for (double nu : {8.0, 300.0}) {
        const auto s = torque_converter::operate(tc, wt, Tt, idle, nu, false);
        REQUIRE(!s.locked);
        CHECK(s.torque_ratio * s.pump_torque == Approx(Tt).epsilon(1e-6));
        CHECK(s.loss == Approx(s.pump_torque * s.pump_speed - Tt * wt).epsilon(1e-6));
    }
    // Cold fluid lowers the converter's efficiency at the same demand.
    CHECK(torque_converter::operate(tc, wt, Tt, idle, 300.0, false).loss >
          torque_converter::operate(tc, wt, Tt, idle, 8.0, false).loss);
    // Locked: no loss.
    CHECK(torque_converter::operate(tc, wt, Tt, idle, 8.0, true).loss == 0.0);
}

TEST_CASE("vehicle: road load and fuel map", "[cycle]") {
    vehicle::Vehicle v;
    v.mass = 1500;
    v.rotating_mass_factor = 0.03;
    v.f0 = 130;
    v.f1 = 0.9 * 3.6;        // 0.9 N/(km/h)
    v.f2 = 0.035 * 3.6 * 3.6;  // 0.035 N/(km/h)^2
    // 50 km/h, 0.5 m/s^2: 130 + 0.9 x 50 + 0.035 x 2500 + 1545 x 0.5 = 1035 N.
    CHECK(v.tractive_force(50 / 3.6, 0.5) == Approx(1035.0).epsilon(1e-9));
    vehicle::FuelMap f;
    f.speeds = {100, 200};
    f.torques = {0, 100};
    f.rate = {{1, 3}, {2, 6}};
    CHECK(f.rate_at(150, 50) == Approx(0.25 * (1 + 3 + 2 + 6)));
    CHECK(f.rate_at(50, -10) == Approx(1.0));  // clamped at the edges
}

TEST_CASE("cycle: the thermal network conserves energy", "[cycle]") {
    // Heat generated (gearbox, converter, clutch drag) = heat to ambient + change of stored heat,
    // on the three-node network of the automatic over the NEDC from -10 degC.
    const auto pt = powertrain("configs/automatic-6speed.yaml");
    const auto dc = io::resolve_cycle("nedc", cycle_dirs());
    const double T0 = kC - 10;
    const auto r = cycle::simulate_cycle(pt, dc, cycle::uniform(T0), T0, false).totals;
    const double generated = r.gearbox_loss() + r.E_tc + r.E_heater;
    REQUIRE(generated > 1e5);
    CHECK(generated == Approx(r.E_ambient + r.stored_end - r.stored_start).epsilon(1e-9));
    CHECK(r.end[0] > T0 + 20);  // the oil warms
}

TEST_CASE("cycle: a constant-load cycle settles at map's stabilised temperature", "[cycle]") {
    // Manual transmission (oil + housing nodes) at 80 km/h for 5 h: the oil must end where
    // `map` puts the equilibrium of the same gear, speed and torque (steady heat balance
    // through the housing conductance in series), with the housing seeing the under-body air
    // of the moving vehicle (0.3 x 80 km/h = 6.67 m/s, above the case's own 2 m/s).
    const auto pt = powertrain("configs/manual-6speed.yaml");
    REQUIRE(pt.vehicle.underbody_air == 0.3);
    const auto r = cycle::simulate_cycle(pt, steady_cycle(80, 18000), cycle::uniform(kC + 20), kC + 20, true);
    const auto& last = r.trace[r.trace.size() - 2];  // last step with a load
    REQUIRE(last.gear > 0);
    auto m = pt.gears[last.gear - 1];
    std::get<thermal::HousingSurface>(m.thermal.rejection.model).air_speed = 0.3 * 80 / 3.6;
    const auto p = solver::solve_point(m, last.input_speed, last.input_torque, false, kC + 20);
    REQUIRE(p.status == solver::PointStatus::ok);
    CHECK(r.totals.end[0] == Approx(p.oil_temperature).margin(0.05));
    // and the network is then in balance: nothing more is stored.
    CHECK(last.P_gearbox == Approx(p.losses.total()).epsilon(1e-3));
    // Without the under-body air the box runs hotter.
    auto still = pt;
    still.vehicle.underbody_air = 0;
    const auto hot = cycle::simulate_cycle(still, steady_cycle(80, 18000), cycle::uniform(kC + 20), kC + 20, false);
    CHECK(hot.totals.end[0] > r.totals.end[0] + 1.0);
}

TEST_CASE("pre-warming: 886 J/K and 100 W take 886 s from -10 to 90 degC (seed 003 section 4)", "[cycle]") {
    // One node of 886 J/K with no heat path (huge resistance): t = C dT / P exactly. Seed 003 §4
    // gives 886 s for 100 W from -10 to +90 degC; 886 J/K is the capacity that implies.
    auto c = io::load_case(test_support::source_path("configs/manual-6speed.yaml"));
    auto pt = io::load_powertrain(c, std::nullopt);
    for (auto& m : pt.gears) {
        m.thermal.network = {};
        m.thermal.network.C_oil = 886;
        thermal::ThermalResistance R;
        R.R0 = 1e12;
        m.thermal.rejection.model = R;
    }
    const auto p = cycle::prewarm(pt, cycle::uniform(kC - 10), kC + 90, 100, kC - 10);
    REQUIRE(p.reached);
    CHECK(p.time == Approx(886).margin(0.01));
    CHECK(p.energy == Approx(88600).epsilon(1e-6));
    // With the shipped heat path the same heater falls short: it says where the oil levels off.
    const auto real = cycle::prewarm(powertrain("configs/manual-6speed.yaml"), cycle::uniform(kC - 10), kC + 90, 100,
                                     kC - 10, 3 * 3600.0);
    CHECK(!real.reached);
    CHECK(real.max_oil_temperature < kC + 90);
}

TEST_CASE("seed 003 trends (sections 4.1, 4.2): pre-warming helps more from -10 than from 23 degC, and more on NEDC than ARTEMIS",
          "[cycle][seed003]") {
    const auto pt = powertrain("configs/automatic-6speed.yaml");
    auto saving = [&](const std::string& name, double start_C) {
        io::CycleStudyOptions o;
        o.start_temperature = o.ambient = kC + start_C;
        o.prewarm_target = kC + 90;
        o.heater_power = 2000;
        const auto s = io::run_cycle_study(pt, io::resolve_cycle(name, cycle_dirs()), o);
        return (s.cold.totals.fuel - s.prewarmed->fuel) / s.cold.totals.fuel;
    };
    const double nedc_cold = saving("nedc", -10), nedc_mild = saving("nedc", 23);
    const double art_cold = saving("artemis", -10), art_mild = saving("artemis", 23);
    INFO("fuel saving NEDC " << nedc_cold << " / " << nedc_mild << ", ARTEMIS " << art_cold << " / " << art_mild);
    CHECK(nedc_cold > nedc_mild);
    CHECK(art_cold > art_mild);
    CHECK(nedc_cold > art_cold);
    CHECK(nedc_mild > art_mild);
    CHECK(art_mild > 0);
}

namespace {
// The CSV text as rows of cells, the header first.
std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    size_t start = 0;
    while (start < text.size()) {
        const size_t end = text.find('\n', start);
        const std::string line = text.substr(start, end - start);
        std::vector<std::string> cells;
        size_t a = 0;
        for (size_t b; (b = line.find(',', a)) != std::string::npos; a = b + 1) cells.push_back(line.substr(a, b - a));
        cells.push_back(line.substr(a));
        rows.push_back(cells);
        start = end == std::string::npos ? text.size() : end + 1;
    }
    return rows;
}
}  // namespace

TEST_CASE("cycle trace: the warm-start and pre-warmed runs follow the start run's columns, on the same steps",
          "[cycle][trace]") {
    const auto pt = powertrain("configs/automatic-6speed.yaml");
    io::CycleStudyOptions o;
    o.start_temperature = o.ambient = kC - 10;
    o.warm_temperature = kC + 90;
    o.prewarm_target = kC + 90;
    o.heater_power = 2000;
    const auto s = io::run_cycle_study(pt, io::resolve_cycle("nedc", cycle_dirs()), o);
    const auto rows = csv_rows(io::cycle_trace_csv(pt, s));
    const auto& h = rows.front();
    const auto at = [&](const std::string& name) {
        const auto it = std::find(h.begin(), h.end(), name);
        REQUIRE(it != h.end());
        return static_cast<size_t>(it - h.begin());
    };
    // The start run's columns first, as before (the converter and fuel columns last of them).
    REQUIRE(h.size() == 30);
    CHECK(h[0] == "time_s");
    CHECK(h[23] == "fuel_g_s");
    const std::vector<std::string> added{"warm_oil_temp_C",      "warm_P_gearbox_W",      "warm_P_converter_W",
                                         "prewarmed_oil_temp_C", "prewarmed_P_gearbox_W", "prewarmed_P_converter_W"};
    CHECK(std::vector<std::string>(h.begin() + 24, h.end()) == added);
    REQUIRE(rows.size() == s.cold.trace.size() + 1);
    // First row: each run at its own start (the warm start's 90 degC is the option; the pre-warmed
    // run starts where the heater left the oil, at or above the 90 degC target).
    CHECK(std::stod(rows[1][at("oil_temp_C")]) == Approx(-10.0).margin(1e-3));
    CHECK(std::stod(rows[1][at("warm_oil_temp_C")]) == Approx(90.0).margin(1e-3));
    CHECK(std::stod(rows[1][at("prewarmed_oil_temp_C")]) == Approx(s.prewarm->state[0] - kC).margin(1e-3));
    CHECK(std::stod(rows[1][at("prewarmed_oil_temp_C")]) >= 90.0 - 1e-3);
    // Last row: the oil temperature at the end of each run, as its totals (integrated apart) say.
    CHECK(std::stod(rows.back()[at("warm_oil_temp_C")]) == Approx(s.warm.end[0] - kC).margin(1e-3));
    CHECK(std::stod(rows.back()[at("prewarmed_oil_temp_C")]) == Approx(s.prewarmed->end[0] - kC).margin(1e-3));
    // Another route to each run's transmission loss: the trace's loss rates (at the start of each
    // step) summed over the steps against the totals the ODE integration gives; the rates change
    // within a step as the oil warms, so the two agree to about a per cent, not exactly.
    const auto energy = [&](const std::string& col) {
        double e = 0;
        for (size_t i = 1; i + 1 < rows.size(); ++i)
            e += std::stod(rows[i][at(col)]) * (std::stod(rows[i + 1][0]) - std::stod(rows[i][0]));
        return e;
    };
    CHECK(energy("P_gearbox_W") == Approx(s.cold.totals.gearbox_loss()).epsilon(0.03));
    CHECK(energy("warm_P_gearbox_W") == Approx(s.warm.gearbox_loss()).epsilon(0.03));
    CHECK(energy("prewarmed_P_gearbox_W") == Approx(s.prewarmed->gearbox_loss()).epsilon(0.03));
    CHECK(energy("warm_P_converter_W") == Approx(s.warm.E_tc).epsilon(0.03));
    // The warm start loses less than the cold one (the summary's "cold start costs" line).
    CHECK(energy("warm_P_gearbox_W") < energy("P_gearbox_W"));

    // Without pre-warming: the warm run's columns only.
    o.prewarm_target.reset();
    const auto plain = io::run_cycle_study(pt, io::resolve_cycle("nedc", cycle_dirs()), o);
    const auto h2 = csv_rows(io::cycle_trace_csv(pt, plain)).front();
    CHECK(h2.size() == 27);
    CHECK(h2.back() == "warm_P_converter_W");
}

TEST_CASE("cycle trace streamed: byte for byte the trace held whole, with or without pre-warming", "[cycle][trace]") {
    // The streamed writer (runs simulated again, rows written as they come, small chunks here)
    // against the text of the study that kept its traces.
    for (const char* config : {"configs/automatic-6speed.yaml", "configs/manual-6speed.yaml"}) {
        const auto pt = powertrain(config);
        const auto dc = io::resolve_cycle("nedc", cycle_dirs());
        for (bool prewarm : {false, true}) {
            io::CycleStudyOptions o;
            o.start_temperature = o.ambient = kC - 10;
            if (prewarm) o.prewarm_target = kC + 60, o.heater_power = 2000;
            const auto held = io::run_cycle_study(pt, dc, o);
            o.keep_traces = false;
            const auto bare = io::run_cycle_study(pt, dc, o);
            CHECK(bare.cold.trace.empty());
            CHECK(bare.cold.totals.gearbox_loss() == held.cold.totals.gearbox_loss());
            std::string streamed;
            size_t chunks = 0;
            io::write_cycle_trace(pt, dc, bare, o, [&](std::string_view s) {
                streamed += s;
                ++chunks;
            });
            CHECK(streamed == io::cycle_trace_csv(pt, held));
            CHECK(io::cycle_trace_header(pt, bare) == streamed.substr(0, streamed.find('\n') + 1));
            CHECK(chunks >= 1);
        }
    }
}

TEST_CASE("cycle: an engine asked beyond its fuel map without max_torque is counted and reported, not silent",
          "[cycle][units37]") {
    // Manual, second gear held, from 20 to 56 km/h at 5 m/s^2 (half a g, below the 1 g refusal).
    // Hand calculation of the least engine torque: F = 1550 kg x 1.03 x 5 m/s^2 = 7982.5 N at the
    // wheels (road load only adds), wheel torque 7982.5 x 0.31 m = 2474.6 N m, through the final
    // drive 3.7 (efficiency 0.97) and g2 (n_in/n_out = 2.0526, 19/39):
    // T_eng >= 2474.6 / (3.7 x 0.97 x 2.0526) = 335.9 N m, beyond the map's 200 N m.
    const auto pt = powertrain("configs/manual-6speed.yaml");
    cycle::DriveCycle dc;
    dc.name = "hard";
    dc.file = "hard.csv";
    for (int k = 0; k <= 10; ++k) {
        dc.time.push_back(k * 0.2 + (k > 0 ? 10 : 0));  // 10 s at 20 km/h, then 2 s of acceleration
        dc.speed.push_back(20 / 3.6 + (k > 0 ? 5.0 * (k - 1) * 0.2 : 0.0) * (k > 0));
        dc.gear.push_back(2);
        dc.line.push_back(k + 2);
    }
    const double T0 = kC + 80;
    const auto r = cycle::simulate_cycle(pt, dc, cycle::uniform(T0), T0, true);
    const auto& b = r.totals.engine_beyond_map;
    CHECK(b.map_torque == Approx(200.0));
    CHECK(b.peak_torque > 335.9);
    // The count against the trace, a different route: every row whose engine torque passes 200 N m.
    int beyond = 0;
    double peak = 0;
    for (const auto& row : r.trace)
        if (row.engine_torque > 200.0 + 1e-6) ++beyond, peak = std::max(peak, row.engine_torque);
    CHECK(b.rows == beyond);
    CHECK(b.rows >= 8);
    CHECK(b.peak_torque == Approx(peak));
    CHECK(b.first_line == 3);  // the first accelerating row (line 3 of the file: header, 10 s row, then it)
    const auto w = io::engine_beyond_map_warning(b);
    CHECK(w.find("beyond its fuel map (200 N m)") != std::string::npos);
    CHECK(w.find("line 3") != std::string::npos);
    // The same cycle at a gentle pace asks nothing beyond the map: no warning.
    auto gentle = dc;
    for (size_t k = 1; k < gentle.speed.size(); ++k) gentle.speed[k] = 20 / 3.6 + 0.5 * (k - 1) * 0.2;
    const auto g = cycle::simulate_cycle(pt, gentle, cycle::uniform(T0), T0, false).totals;
    CHECK(g.engine_beyond_map.rows == 0);
    CHECK(io::engine_beyond_map_warning(g.engine_beyond_map).empty());
}
