// The `vehicle` block of a case: road load, final drive, gears and shift schedule,
// engine (idle, overrun, fuel map) and an optional torque converter.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/case/config.hpp"

namespace gearloss::io {

namespace {
namespace dim = units::dim;

std::vector<double> quantity_list(const YamlNode& n, const units::Dimension& d, const char* example) {
    std::vector<double> v;
    for (const auto& x : n.items()) v.push_back(x.as_quantity(d, example));
    if (v.empty()) n.fail("empty list");
    return v;
}

void require_ascending(const YamlNode& n, const std::vector<double>& v) {
    for (size_t i = 1; i < v.size(); ++i)
        if (!(v[i] > v[i - 1])) n.items()[i].fail("values must increase strictly");
}

vehicle::FuelMap load_fuel_map(const YamlNode& n) {
    n.allow_keys({"speeds", "torques", "rate_unit", "fuel_rate", "note"});
    vehicle::FuelMap f;
    f.speeds = quantity_list(n.at("speeds"), dim::angular_speed, "2000 rpm");
    f.torques = quantity_list(n.at("torques"), dim::torque, "100 N*m");
    require_ascending(n.at("speeds"), f.speeds);
    require_ascending(n.at("torques"), f.torques);
    if (f.speeds.size() < 2 || f.torques.size() < 2) n.fail("a fuel map needs at least 2 speeds and 2 torques");
    units::UnitFactor u;
    const YamlNode un = n.at("rate_unit");
    try {
        u = units::parse_unit(un.as_string());
    } catch (const units::UnitError& e) {
        un.fail(e.message + " (expected a mass flow unit, e.g. 'g/h' or 'kg/h')");
    }
    if (!(u.dim == units::make_dim(0, 1, -1, 0)) || u.affine) un.fail("expected a mass flow unit, e.g. 'g/h'");
    const auto rows = n.at("fuel_rate").items();
    if (rows.size() != f.speeds.size())
        n.at("fuel_rate").fail("one row per speed expected (" + std::to_string(f.speeds.size()) + ")");
    for (const auto& row : rows) {
        const auto cells = row.items();
        if (cells.size() != f.torques.size())
            row.fail("one value per torque expected (" + std::to_string(f.torques.size()) + ")");
        std::vector<double> r;
        for (const auto& c : cells) {
            const double x = c.as_number();
            if (!(x >= 0) || !std::isfinite(x)) c.fail("fuel rate must be a non-negative number");
            r.push_back(x * u.scale);
        }
        f.rate.push_back(r);
    }
    return f;
}

torque_converter::TorqueConverter load_tc(const YamlNode& n) {
    n.allow_keys({"speed_ratio", "torque_ratio", "capacity", "impeller_head", "impeller_flow", "lockup", "note"});
    torque_converter::TorqueConverter tc;
    auto& c = tc.curve;
    for (const auto& x : n.at("speed_ratio").items()) c.speed_ratio.push_back(x.as_number());
    for (const auto& x : n.at("torque_ratio").items()) c.torque_ratio.push_back(x.as_number());
    // K = n_pump / sqrt(T_pump), given in rpm/sqrt(N m) as is customary.
    for (const auto& x : n.at("capacity").items()) c.capacity.push_back(x.as_number() * M_PI / 30.0);
    const size_t m = c.speed_ratio.size();
    if (m < 2 || c.torque_ratio.size() != m || c.capacity.size() != m)
        n.fail("speed_ratio, torque_ratio and capacity need the same number (>= 2) of values");
    require_ascending(n.at("speed_ratio"), c.speed_ratio);
    if (c.speed_ratio.front() != 0.0) n.at("speed_ratio").items()[0].fail("the characteristic starts at stall (0)");
    if (c.speed_ratio.back() > 1.0) n.at("speed_ratio").items()[m - 1].fail("speed ratio above 1");
    // A converter multiplies torque at stall (its stator turns the flow back; passenger cars
    // 1.7-2.5) and couples 1:1 beyond the coupling point; below 1 at stall it is no converter,
    // and well below 1 anywhere the turbine would give back less than a fluid coupling.
    if (!(c.torque_ratio.front() >= 1.0))
        n.at("torque_ratio").items()[0].fail(fmt::format(
            "torque ratio {:g} at stall: a converter multiplies torque there (at least 1, typically 1.7 to 2.5)",
            c.torque_ratio.front()));
    for (size_t i = 0; i < m; ++i) {
        if (!(c.torque_ratio[i] > 0 && c.torque_ratio[i] < 5)) n.at("torque_ratio").items()[i].fail("must be in (0, 5)");
        if (c.torque_ratio[i] < 0.8)
            n.at("torque_ratio").items()[i].fail(fmt::format(
                "torque ratio {:g}: below 0.8 the turbine gives back far less than a fluid coupling (1); check the curve",
                c.torque_ratio[i]));
        if (!(c.capacity[i] > 0)) n.at("capacity").items()[i].fail("must be positive (rpm/sqrt(N*m))");
    }
    if (n.has("impeller_head") != n.has("impeller_flow"))
        n.fail("give both 'impeller_head' and 'impeller_flow' (the viscous correction needs both) or neither");
    if (n.has("impeller_head")) {
        tc.impeller_head = n.positive_quantity("impeller_head", dim::length, "40 m");
        tc.impeller_flow = n.positive_quantity("impeller_flow", units::make_dim(3, 0, -1, 0), "60 m^3/h");
    }
    if (auto l = n.get("lockup")) {
        l->allow_keys({"from_gear", "min_speed"});
        tc.lockup_from_gear = l->at("from_gear").as_int();
        if (tc.lockup_from_gear < 1) l->at("from_gear").fail("a gear number from 1");
        if (auto s = l->get("min_speed")) tc.lockup_min_speed = s->as_quantity(dim::angular_speed, "1200 rpm");
    }
    return tc;
}
// vehicle.motor: the envelope of an electric traction motor (vehicle.hpp, Motor).
vehicle::Motor load_motor(const YamlNode& n) {
    n.allow_keys({"max_speed", "max_torque", "max_power", "recuperation_torque", "recuperation_power", "note"});
    vehicle::Motor m;
    m.max_speed = n.positive_quantity("max_speed", dim::angular_speed, "12000 rpm");
    m.max_torque = n.positive_quantity("max_torque", dim::torque, "310 N*m");
    m.max_power = n.positive_quantity("max_power", dim::power, "150 kW");
    m.recuperation_torque = n.has("recuperation_torque") ? n.positive_quantity("recuperation_torque", dim::torque, "200 N*m")
                                                         : m.max_torque;
    m.recuperation_power = n.has("recuperation_power") ? n.positive_quantity("recuperation_power", dim::power, "100 kW")
                                                       : m.max_power;
    // Traction motors of road vehicles turn at most about 25 000 rpm (the fastest series e-axles
    // run near 20 000 rpm); a faster one is a unit slip.
    if (m.max_speed * 30 / std::numbers::pi > 30000)
        n.at("max_speed").fail(fmt::format("{:.4g} rpm above 30 000 rpm, beyond road-vehicle traction motors",
                                           m.max_speed * 30 / std::numbers::pi));
    return m;
}
}  // namespace

void load_vehicle(const YamlNode& n, Case& c) {
    n.allow_keys({"mass", "rotating_mass_factor", "wheel_radius", "road_load", "final_drive", "gears", "shift",
                  "engine", "motor", "torque_converter", "underbody_air", "note"});
    vehicle::Vehicle v;
    v.mass = n.positive_quantity("mass", dim::mass, "1500 kg");
    if (auto e = n.get("rotating_mass_factor")) {
        v.rotating_mass_factor = e->as_number();
        if (!(v.rotating_mass_factor >= 0 && v.rotating_mass_factor < 1)) e->fail("must be in [0, 1)");
    }
    v.wheel_radius = n.positive_quantity("wheel_radius", dim::length, "0.31 m");
    // A road vehicle's dynamic rolling radius: 0.1 m (small scooter wheels) to 2 m (the largest
    // mining-truck tyres); a radius outside, e.g. 0.31 mm for 0.31 m, would show up only later as
    // an absurd input speed of the gearbox.
    if (!(v.wheel_radius >= 0.1 && v.wheel_radius <= 2.0))
        n.at("wheel_radius").fail(fmt::format("{:.4g} m outside the range of road-vehicle wheels 0.1..2 m", v.wheel_radius));
    if (auto u = n.get("underbody_air")) {
        v.underbody_air = u->as_number();
        if (!(v.underbody_air >= 0 && v.underbody_air <= 1)) u->fail("a share of the vehicle speed, in [0, 1]");
    }
    const YamlNode rl = n.at("road_load");
    rl.allow_keys({"f0", "f1", "f2", "rolling_resistance", "CdA", "air_density"});
    if (rl.has("f0")) {
        if (rl.has("rolling_resistance") || rl.has("CdA"))
            rl.fail("give either f0/f1/f2 (coast-down coefficients) or rolling_resistance and CdA");
        v.f0 = rl.quantity("f0", dim::force, "130 N");
        if (auto f1 = rl.get("f1")) v.f1 = f1->as_quantity(units::make_dim(0, 1, -1, 0), "0.9 N/(km/h)");
        if (auto f2 = rl.get("f2")) v.f2 = f2->as_quantity(units::make_dim(-1, 1, 0, 0), "0.035 N*h^2/km^2");
    } else {
        const double crr = rl.at("rolling_resistance").as_number();
        if (!(crr >= 0 && crr < 0.1)) rl.at("rolling_resistance").fail("must be in [0, 0.1)");
        const double CdA = rl.positive_quantity("CdA", dim::area, "0.68 m^2");
        const double rho = rl.has("air_density") ? rl.positive_quantity("air_density", dim::density, "1.2 kg/m^3") : 1.2;
        v.f0 = crr * v.mass * 9.81;
        v.f2 = 0.5 * rho * CdA;
    }
    if (v.f0 < 0 || v.f1 < 0 || v.f2 < 0) rl.fail("road-load coefficients must not be negative");
    const YamlNode fd = n.at("final_drive");
    fd.allow_keys({"ratio", "efficiency"});
    v.final_drive = fd.at("ratio").as_number();
    if (!(v.final_drive > 0 && v.final_drive < 50)) fd.at("ratio").fail("must be in (0, 50)");
    if (auto e = fd.get("efficiency")) {
        v.final_drive_efficiency = e->as_number();
        if (!(v.final_drive_efficiency > 0.5 && v.final_drive_efficiency <= 1)) e->fail("must be in (0.5, 1]");
    }
    // A gearbox of one fixed ratio (no gearbox.ratios: a single-stage reducer) has one gear, the
    // case as it is: `gears` is then left out.
    const auto gear_list = n.get("gears");
    for (const auto& g : gear_list ? gear_list->items() : std::vector<YamlNode>{}) {
        v.gears.push_back(g.as_string());
        // Each vehicle gear is one ratio of the gearbox; the same ratio twice is a slip (the
        // shift schedule would shift into the gear it is in).
        if (std::count(v.gears.begin(), v.gears.end(), v.gears.back()) > 1)
            g.fail(fmt::format("ratio '{}' is listed twice in vehicle.gears (gear {} and gear {})", v.gears.back(),
                               std::find(v.gears.begin(), v.gears.end(), v.gears.back()) - v.gears.begin() + 1,
                               v.gears.size()));
    }
    if (gear_list && v.gears.empty()) gear_list->fail("empty list");
    if (auto sh = n.get("shift")) {
        sh->allow_keys({"upshift", "downshift"});
        v.shift.upshift_speed = sh->quantity("upshift", dim::angular_speed, "2500 rpm");
        v.shift.downshift_speed = sh->quantity("downshift", dim::angular_speed, "1200 rpm");
        if (!(v.shift.downshift_speed > 0 && v.shift.downshift_speed < v.shift.upshift_speed))
            sh->fail("need 0 < downshift < upshift");
    }
    if (auto e = n.get("engine")) {
        e->allow_keys({"idle_speed", "max_speed", "max_torque", "overrun_torque", "fuel_map", "fuel_density",
                       "lower_heating_value", "note"});
        auto& en = v.engine;
        if (auto x = e->get("idle_speed")) en.idle_speed = x->as_quantity(dim::angular_speed, "800 rpm");
        // Road-vehicle engines idle between about 500 rpm (heavy diesels) and 1500 rpm (small petrol
        // engines, cold); 200..3000 rpm leaves room and still catches a red line typed as the idle.
        if (!(en.idle_speed * 30 / std::numbers::pi >= 200 && en.idle_speed * 30 / std::numbers::pi <= 3000))
            e->at("idle_speed").fail(fmt::format("{:.4g} rpm outside the plausible idle speeds 200..3000 rpm",
                                                 en.idle_speed * 30 / std::numbers::pi));
        if (auto x = e->get("max_speed")) {
            en.max_speed = x->as_quantity(dim::angular_speed, "6500 rpm");
            if (!(en.max_speed > en.idle_speed)) x->fail("must be above the idle speed");
        }
        if (auto x = e->get("max_torque")) {
            en.max_torque = x->as_quantity(dim::torque, "350 N*m");
            if (!(*en.max_torque > 0)) x->fail("must be positive");
        }
        if (auto x = e->get("overrun_torque")) en.overrun_torque = x->as_quantity(dim::torque, "25 N*m");
        if (en.overrun_torque < 0) e->at("overrun_torque").fail("must not be negative (a drag torque magnitude)");
        if (auto x = e->get("fuel_density")) en.fuel_density = x->as_quantity(dim::density, "745 kg/m^3");
        if (auto x = e->get("lower_heating_value"))
            en.lower_heating_value = x->as_quantity(units::make_dim(2, 0, -2, 0), "43 MJ/kg");
        if (!(en.lower_heating_value > 0)) e->at("lower_heating_value").fail("must be positive");
        if (!(en.fuel_density > 0)) e->at("fuel_density").fail("must be positive");
        if (auto fm = e->get("fuel_map")) en.fuel_map = load_fuel_map(*fm);
    }
    if (auto mo = n.get("motor")) {
        if (n.has("engine")) mo->fail("give either an engine or a motor, not both");
        if (n.has("torque_converter")) n.at("torque_converter").fail("an electric motor drives without a torque converter");
        v.motor = load_motor(*mo);
        // No idle: the motor turns with the wheels from standstill; no fuel, no engine drag.
        v.engine.idle_speed = 0.0;
        v.engine.max_speed = v.motor->max_speed;
        v.engine.overrun_torque = 0.0;
    }
    if (auto tc = n.get("torque_converter")) {
        c.torque_converter = load_tc(*tc);
        v.torque_converter = true;
        if (c.torque_converter->lockup_from_gear > static_cast<int>(v.gears.size()))
            tc->at("lockup").at("from_gear").fail("beyond the last gear");
    }
    c.vehicle = v;
}

}  // namespace gearloss::io
