#include "gearloss/cycle/simulate.hpp"

#include <algorithm>
#include <array>
#include <boost/math/tools/toms748_solve.hpp>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "gearloss/core/errors.hpp"
#include "gearloss/core/interrupt.hpp"
#include "gearloss/core/message_text.hpp"
#include "gearloss/model/validate.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::cycle {

namespace odeint = boost::numeric::odeint;

thermal::NodeTemperatures uniform(double T) { return {T, T, T}; }

namespace {

// Integrated state: node temperatures, then the energies of each heat flow [J].
// The mechanisms' energies take kMaxMechanisms slots (unused slots stay zero).
constexpr size_t kMaxMechanisms = 12;
using State = std::array<double, 3 + kMaxMechanisms + 3>;
enum : size_t { kOil, kHousing, kClutch, kMech0, kTc = kMech0 + kMaxMechanisms, kAmbient, kHeater };

State initial_state(const thermal::NodeTemperatures& start) {
    State x{};
    x[kOil] = start[0];
    x[kHousing] = start[1];
    x[kClutch] = start[2];
    return x;
}

thermal::NodeTemperatures nodes(const State& x) { return {x[kOil], x[kHousing], x[kClutch]}; }

// Node temperatures for the trace: an absent node reads as the oil.
void trace_temperatures(TraceRow& row, const thermal::Network& net, const State& x) {
    row.T_oil = x[kOil];
    row.T_housing = net.has_housing() ? x[kHousing] : x[kOil];
    row.T_clutch = net.has_clutch() ? x[kClutch] : x[kOil];
}


// What stays fixed over one step of the cycle (the oil temperature does not).
struct StepLoad {
    const solver::Model* gearbox = nullptr;  // null: gearbox at rest
    solver::PointState point;
    bool converter = false, lockup = false;
    double turbine_speed = 0, turbine_torque = 0;
    double heater = 0;
    double omega_in = 0;
    double air_speed = 0;  // under-body air over the housing [m/s]
};

struct Rates {
    const Powertrain& pt;
    const StepLoad& load;
    double ambient;
    void operator()(const State& x, State& dx, double /*t*/) const {
        const solver::Model& tm = pt.thermal_model();
        const auto& net = tm.thermal.network;
        const thermal::NodeTemperatures T = nodes(x);
        const lubricant::OilState os = tm.oil_state(T[0]);
        solver::LossBreakdown L;
        if (load.gearbox) L = solver::evaluate_losses(*load.gearbox, load.point, os, false);
        double P_tc = 0;
        if (load.converter)
            P_tc = torque_converter::operate(*pt.torque_converter, load.turbine_speed, load.turbine_torque,
                                             pt.vehicle.engine.idle_speed, os.nu_cSt, load.lockup)
                       .loss;
        // Heat of the mechanisms that do not heat the oil goes to the clutch-pack node.
        const double P_other = load.gearbox ? L.total() - L.into_oil(*load.gearbox) : 0.0;
        // The external cooler draws from the oil node, as in the stabilised balance (Model::heat_flow).
        const double Q_cooler = tm.thermal.cooler.present() ? tm.thermal.cooler.heat_flow(T[0], os.rho * os.cp) : 0.0;
        const double P_oil = L.total() - P_other + P_tc + load.heater - Q_cooler;
        const double Q = tm.surface_heat_flow(thermal::surface_temperature(net, T), ambient, load.omega_in, load.air_speed);
        const auto d = thermal::node_rates(net, T, P_oil, P_other, Q);
        dx.fill(0.0);
        dx[kOil] = d[0];
        dx[kHousing] = d[1];
        dx[kClutch] = d[2];
        for (size_t i = 0; i < L.power.size(); ++i) dx[kMech0 + i] = L.power[i];
        dx[kTc] = P_tc;
        dx[kAmbient] = Q + Q_cooler;  // heat that left the transmission
        dx[kHeater] = load.heater;
    }
};

// Bounds of the transient: a cycle lasts at most kMaxDuration (11.6 days; the regulatory
// cycles last 20-30 min), one interval between samples takes at most kMaxSteps accepted
// steps of the integrator (a 1-s interval takes a handful), the vehicle runs at most
// kMaxVehicleSpeed.
constexpr double kMaxDuration = 1e6;             // s
constexpr size_t kMaxSteps = 100000;             // per interval
constexpr double kMaxVehicleSpeed = 500.0 / 3.6; // m/s

std::string celsius(double T) { return std::isfinite(T) ? celsius_text(T) : "(not finite)"; }

[[noreturn]] void fail(const std::string& key, const std::string& message) { throw InputError("", 0, 0, key, message); }

// An error at sample i of the cycle: at its file and line when the cycle was read from one CSV file.
[[noreturn]] void fail_at(const DriveCycle& c, size_t i, const std::string& message) {
    if (!c.file.empty() && i < c.line.size()) throw InputError(c.file, c.line[i], 0, "cycle", message);
    fail("cycle", message);
}

// Called by the integrator once per accepted step: bounds the steps and stops at the first
// value that is not finite, naming the component when the gearbox is loaded.
struct StepGuard {
    const StepLoad& load;
    double ambient;
    size_t* steps;
    void operator()(const State& x, double t) const {
        if (++*steps > kMaxSteps)
            fail("cycle", fmt::format("the integration of the interval at t = {:g} s did not finish within {} steps", t,
                                      kMaxSteps));
        for (double v : x)
            if (!std::isfinite(v)) {
                std::string cause;
                if (load.gearbox && std::isfinite(x[kOil]))
                    cause = solver::loss_fault(*load.gearbox, load.point, x[kOil], ambient);
                fail("cycle", fmt::format("at t = {:g} s a temperature or energy is not a finite number (out_of_range: {})",
                                          t, cause.empty() ? "thermal network" : cause));
            }
    }
};

void integrate(const Powertrain& pt, const StepLoad& load, double ambient, State& x, double t0, double t1) {
    // Tolerances: 1e-4 K on temperatures (the energies are large numbers: relative 1e-7).
    auto stepper = odeint::make_controlled(1e-4, 1e-7, odeint::runge_kutta_dopri5<State>());
    size_t steps = 0;
    try {
        // First trial step at most 1 s: a cycle sampled every 100 s would otherwise start with a
        // trial of 100 s, whose stages leave the range where the oil's description holds.
        odeint::integrate_adaptive(stepper, Rates{pt, load, ambient}, x, t0, t1, std::min(t1 - t0, 1.0),
                                   StepGuard{load, ambient, &steps});
    } catch (const odeint::step_adjustment_error& e) {
        fail("cycle", fmt::format("the integration from t = {:g} s failed: {}", t0, e.what()));
    }
}

// The inputs of a run: the cycle's samples, the temperatures, the thermal network.
void check_run(const Powertrain& pt, const DriveCycle& cycle, const thermal::NodeTemperatures& start, double ambient) {
    if (pt.gears.empty()) fail("vehicle", "no gear");
    if (auto f = solver::ambient_fault(ambient)) fail("ambient", *f);
    const auto& tm = pt.thermal_model();
    const auto& net = tm.thermal.network;
    if (!(net.C_oil > 0 && std::isfinite(net.C_oil)))
        fail("thermal.heat_capacity", "a transient needs a positive, finite heat capacity of the oil");
    for (size_t k = 0; k < start.size(); ++k) {
        if ((k == 1 && !net.has_housing()) || (k == 2 && !net.has_clutch())) continue;
        if (auto f = solver::oil_temperature_fault(tm.oil, start[k])) fail("start temperature", *f);
    }
    if (auto f = solver::oil_temperature_fault(tm.oil, ambient)) fail("ambient", "ambient " + *f);
    const auto& t = cycle.time;
    if (tm.mechanisms.size() > kMaxMechanisms)
        fail("mechanisms", fmt::format("{} loss mechanisms; a cycle integrates at most {}", tm.mechanisms.size(), kMaxMechanisms));
    if (t.size() != cycle.speed.size() || (!cycle.gear.empty() && cycle.gear.size() != t.size()))
        fail("cycle", "the cycle's columns differ in length");
    for (size_t i = 0; i < t.size(); ++i) {
        if (!std::isfinite(t[i])) fail_at(cycle, i, fmt::format("sample {}: time is not a finite number", i + 1));
        if (i > 0 && !(t[i] > t[i - 1])) fail_at(cycle, i, fmt::format("sample {}: time does not increase", i + 1));
        if (!(cycle.speed[i] >= 0 && cycle.speed[i] <= kMaxVehicleSpeed))
            fail_at(cycle, i, fmt::format("sample {}: vehicle speed {:.4g} km/h outside 0..{:g} km/h", i + 1,
                                      cycle.speed[i] * 3.6, kMaxVehicleSpeed * 3.6));
        if (!cycle.gear.empty() && (cycle.gear[i] < 0 || cycle.gear[i] > static_cast<int>(pt.gears.size())))
            fail_at(cycle, i, fmt::format("sample {}: gear {} but the vehicle has gears 1..{} (0 = neutral)", i + 1,
                                      cycle.gear[i], pt.gears.size()));
    }
    if (!t.empty() && !(t.back() - t.front() <= kMaxDuration))
        fail("cycle", fmt::format("the cycle lasts {:g} s; at most {:g} s (11.6 days) are simulated",
                                  t.back() - t.front(), kMaxDuration));
}

}  // namespace

CycleResult simulate_cycle(const Powertrain& pt, const DriveCycle& cycle, const thermal::NodeTemperatures& start,
                           double ambient, bool keep_trace, const std::function<void(const TraceRow&)>& on_row) {
    check_run(pt, cycle, start, ambient);
    CycleResult res;
    auto& tot = res.totals;
    const auto& veh = pt.vehicle;
    const auto& net = pt.thermal_model().thermal.network;
    const size_t n_mech = pt.thermal_model().mechanisms.size();
    tot.duration = cycle.duration();
    tot.distance = cycle.distance();
    tot.start = start;
    tot.stored_start = thermal::stored_heat(net, start, ambient);
    tot.has_fuel = veh.engine.fuel_map.has_value();
    // Gearbox input speed per unit wheel speed in each gear.
    std::vector<double> input_per_wheel;
    for (const auto& m : pt.gears) input_per_wheel.push_back(veh.final_drive / std::abs(m.layout.ratio));

    State x = initial_state(start);
    StepLoad load;
    int gear = 1;
    double last_loss = 0;
    if (keep_trace && !on_row) res.trace.reserve(cycle.time.size());
    for (size_t i = 0; i + 1 < cycle.time.size(); ++i) {
        throw_if_interrupted();  // SIGINT / SIGTERM: Interrupted, exit 130 / 143
        const double dt = cycle.time[i + 1] - cycle.time[i];
        const double v = 0.5 * (cycle.speed[i] + cycle.speed[i + 1]);
        const double a = (cycle.speed[i + 1] - cycle.speed[i]) / dt;
        TraceRow row;
        row.time = cycle.time[i];
        row.speed = cycle.speed[i];
        row.accel = a;
        trace_temperatures(row, net, x);
        load = StepLoad{};
        load.air_speed = veh.underbody_air * v;
        const double w_wheel = v / veh.wheel_radius;
        const double T_wheel = veh.tractive_force(v, a) * veh.wheel_radius;
        if (!cycle.gear.empty()) gear = std::min<int>(cycle.gear[i], static_cast<int>(pt.gears.size()));
        else gear = vehicle::select_gear(veh, input_per_wheel, w_wheel, gear);
        const bool moving = v > 0.0 && gear > 0;
        double w_in = 0, T_in = 0;
        if (moving) {
            const solver::Model& gm = pt.gears[gear - 1];
            w_in = input_per_wheel[gear - 1] * w_wheel;
            const double P_wheel = T_wheel * w_wheel;
            if (P_wheel > 0) tot.E_wheel += P_wheel * dt;
            // Power at the gearbox output (final drive losses outside the gearbox).
            const double P_out = P_wheel >= 0 ? P_wheel / veh.final_drive_efficiency : P_wheel * veh.final_drive_efficiency;
            // Input torque that delivers P_out with the gearbox's own losses at this oil temperature;
            // in overrun the engine's drag limits it and the brakes take the rest.
            // Two fixed-point passes from the previous step's loss: the loss changes little with
            // torque, so the second pass leaves a torque error of a fraction of a per cent of the loss.
            T_in = std::max((P_out + last_loss) / w_in, -veh.engine.overrun_torque);
            for (int k = 0; k < 2; ++k) {
                solver::prepare_point(gm, w_in, T_in, load.point);
                last_loss = solver::total_loss(gm, load.point, x[kOil]);
                const double next = std::max((P_out + last_loss) / w_in, -veh.engine.overrun_torque);
                if (std::abs(next - T_in) < 1e-3 * (1.0 + std::abs(T_in))) break;
                T_in = next;
                if (k == 1) solver::prepare_point(gm, w_in, T_in, load.point);
            }
            if (!load.point.fault.empty() || !std::isfinite(last_loss) || !std::isfinite(T_in)) {
                std::string cause = load.point.fault;
                if (cause.empty()) cause = solver::loss_fault(gm, load.point, x[kOil], ambient);
                const auto value = [](double v) { return finite_number_text(v, 4); };
                fail_at(cycle, i, fmt::format("at t = {:g} s (gear {}, {} rpm, {} N m, oil {}): out_of_range: {}",
                                          cycle.time[i], gear, value(w_in * 30 / 3.14159265358979323846), value(T_in),
                                          celsius(x[kOil]), cause.empty() ? "gearbox loss not finite" : cause));
            }
            load.gearbox = &gm;
            load.omega_in = w_in;
            if (T_in > 0) {
                tot.E_gearbox_in += T_in * w_in * dt;
                tot.E_gearbox_out += std::max(0.0, P_out) * dt;
            }
        }
        row.gear = moving ? gear : 0;
        row.input_speed = w_in;
        row.input_torque = T_in;
        // Engine side: converter (automatic) or a slipping dry clutch below idle (manual).
        double w_eng = std::max(w_in, veh.engine.idle_speed), T_eng = T_in;
        if (pt.torque_converter) {
            const auto& tc = *pt.torque_converter;
            load.converter = true;
            load.lockup = moving && tc.lockup_from_gear > 0 && gear >= tc.lockup_from_gear && w_in >= tc.lockup_min_speed;
            load.turbine_speed = w_in;
            load.turbine_torque = T_in;
            const auto s = torque_converter::operate(tc, w_in, T_in, veh.engine.idle_speed,
                                                     pt.thermal_model().oil_state(x[kOil]).nu_cSt, load.lockup);
            w_eng = std::max(s.pump_speed, veh.engine.idle_speed);
            T_eng = s.pump_torque;
            row.tc_speed_ratio = s.speed_ratio;
            row.lockup = s.locked;
        }
        row.engine_speed = w_eng;
        row.engine_torque = T_eng;
        // A cycle the vehicle cannot drive (a gear far too low for the speed, a demand beyond the
        // engine) is an error at its row, not a result.
        // The gearbox input turns with the engine (a locked or slipping clutch, or the turbine of a
        // converter, which is never faster than its pump).
        if (w_in > veh.engine.max_speed * (1.0 + 1e-9))
            fail_at(cycle, i, fmt::format("at t = {:g} s ({:.4g} km/h, gear {}): gearbox input speed {:.0f} rpm above the "
                                      "engine's max_speed {:.0f} rpm; the vehicle cannot drive this row (check the speed "
                                      "and gear)",
                                      cycle.time[i], v * 3.6, gear, w_in * 30 / 3.14159265358979323846,
                                      veh.engine.max_speed * 30 / 3.14159265358979323846));
        if (veh.engine.max_torque && T_eng > *veh.engine.max_torque * (1.0 + 1e-9))
            fail_at(cycle, i, fmt::format("at t = {:g} s ({:.4g} km/h, gear {}): engine torque {:.0f} N m above the engine's "
                                      "max_torque {:.0f} N m; the vehicle cannot drive this row",
                                      cycle.time[i], v * 3.6, gear, T_eng, *veh.engine.max_torque));
        if (veh.engine.fuel_map && !veh.engine.max_torque && T_eng > veh.engine.fuel_map->torques.back() * (1.0 + 1e-9)) {
            // Without max_torque a demand beyond the map is not refused (shipped cold starts ask
            // for it: a converter stalled in -30 degC fluid); it is counted and reported.
            auto& b = tot.engine_beyond_map;
            if (b.rows++ == 0) {
                b.first_time = cycle.time[i];
                b.first_line = i < cycle.line.size() ? cycle.line[i] : 0;
                b.map_torque = veh.engine.fuel_map->torques.back();
            }
            if (T_eng > b.peak_torque) {
                b.peak_torque = T_eng;
                b.peak_time = cycle.time[i];
            }
        }
        if (veh.engine.fuel_map) {
            const bool fuel_cut = T_eng < 0 && w_eng > 1.05 * veh.engine.idle_speed;
            row.fuel_rate = fuel_cut ? 0.0 : veh.engine.fuel_map->rate_at(w_eng, std::max(T_eng, 0.0));
            tot.fuel += row.fuel_rate * dt;
        }
        if (keep_trace) {
            // Loss rates at the start of the step for the trace.
            State d{};
            Rates{pt, load, ambient}(x, d, 0.0);
            row.P_mech.assign(d.begin() + kMech0, d.begin() + kMech0 + n_mech);
            row.P_gearbox = 0.0;
            for (double P : row.P_mech) row.P_gearbox += P;
            row.P_tc = d[kTc];
            if (on_row) on_row(row);
            else res.trace.push_back(row);
        }
        integrate(pt, load, ambient, x, cycle.time[i], cycle.time[i + 1]);
        // The oil driven beyond its data (or the model's search range) makes every later row nonsense.
        if (auto f = solver::oil_temperature_fault(pt.thermal_model().oil, x[kOil]))
            fail_at(cycle, i + 1, fmt::format("at t = {:g} s: oil temperature {}", cycle.time[i + 1], *f));
        if (const double T_max = pt.thermal_model().thermal.equilibrium.T_max; x[kOil] > T_max)
            fail_at(cycle, i + 1, fmt::format("at t = {:g} s the oil reaches {}, above thermal.max_oil_temperature {}: the cycle "
                                      "overheats the gearbox beyond what the model covers",
                                      cycle.time[i + 1], celsius(x[kOil]), celsius(T_max)));
    }
    if (keep_trace) {
        TraceRow last;
        last.time = cycle.time.back();
        last.speed = cycle.speed.back();
        trace_temperatures(last, net, x);
        last.engine_speed = veh.engine.idle_speed;
        if (on_row) on_row(last);
        else res.trace.push_back(last);
    }
    tot.E_mech.assign(x.begin() + kMech0, x.begin() + kMech0 + n_mech);
    tot.E_tc = x[kTc];
    tot.E_ambient = x[kAmbient];
    tot.E_heater = x[kHeater];
    tot.end = nodes(x);
    tot.stored_end = thermal::stored_heat(net, tot.end, ambient);
    return res;
}

PrewarmResult prewarm(const Powertrain& pt, const thermal::NodeTemperatures& start, double target, double power,
                      double ambient, double max_time) {
    check_run(pt, DriveCycle{}, start, ambient);
    if (auto f = solver::oil_temperature_fault(pt.thermal_model().oil, target)) fail("pre-warm target", *f);
    if (!(power > 0 && std::isfinite(power))) fail("heater", "heater power must be a positive, finite number");
    if (!(max_time > 0 && max_time <= kMaxDuration)) fail("pre-warm time", "at most 1e6 s of pre-warming are simulated");
    PrewarmResult r;
    StepLoad load;
    load.heater = power;
    State x = initial_state(start);
    if (x[kOil] >= target) {
        r.reached = true;
        r.state = start;
        return r;
    }
    // 1 s steps; the crossing is interpolated linearly inside the last one.
    double t = 0;
    while (t < max_time) {
        throw_if_interrupted();
        const State before = x;
        integrate(pt, load, ambient, x, t, t + 1.0);
        if (x[kOil] >= target) {
            const double f = (target - before[kOil]) / (x[kOil] - before[kOil]);
            State at{};
            for (size_t k = 0; k < at.size(); ++k) at[k] = before[k] + f * (x[k] - before[k]);
            r.reached = true;
            r.time = t + f;
            r.energy = at[kHeater];
            r.heat_lost = at[kAmbient];
            r.state = nodes(at);
            return r;
        }
        t += 1.0;
    }
    r.time = t;
    r.energy = x[kHeater];
    r.heat_lost = x[kAmbient];
    r.state = nodes(x);
    // Steady oil temperature at this heater power: power = Q(T).
    const solver::Model& tm = pt.thermal_model();
    auto excess = [&](double T) { return tm.heat_flow(T, ambient, 0.0) - power; };  // rises with T
    double hi = ambient + 1.0;
    while (excess(hi) < 0 && hi < ambient + 1000) hi += (hi - ambient);
    if (!(excess(ambient) <= 0 && excess(hi) >= 0))  // not bracketed: beyond 1000 K above ambient
        fail("heater", fmt::format("the oil did not reach {} in {:g} s, and at this power it would level off more than "
                                   "1000 K above the ambient (heat rejection not finite or too small)",
                                   celsius(target), max_time));
    std::uintmax_t it = 80;
    const auto [a, b] = boost::math::tools::toms748_solve(
        excess, ambient, hi, [](double x0, double x1) { return std::abs(x1 - x0) < 1e-6; }, it);
    r.max_oil_temperature = 0.5 * (a + b);
    return r;
}

}  // namespace gearloss::cycle
