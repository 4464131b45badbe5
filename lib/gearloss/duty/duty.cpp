#include "gearloss/duty/duty.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>

#include "gearloss/core/errors.hpp"
#include "gearloss/core/message_text.hpp"
#include "gearloss/cycle/transient.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/model/validate.hpp"

namespace gearloss::duty {

namespace {

constexpr double kRpm = std::numbers::pi / 30.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A series lasts at most this long (as a drive cycle: 11.6 days).
constexpr double kMaxSeriesDuration = 1e6;  // s

// Energy supplied and delivered over `dt` at input power P_in with the loss energy E_loss: the
// supplied side is the input in drive, the output when driven from it.
void add_flow(DutyRow& r, double P_in, double dt, double E_loss) {
    if (P_in >= 0) {
        r.E_supplied = P_in * dt;
        r.E_delivered = P_in * dt - E_loss;
    } else {
        r.E_supplied = -P_in * dt + E_loss;
        r.E_delivered = -P_in * dt;
    }
}

double row_efficiency(const DutyRow& r) { return r.E_supplied > 0 ? std::max(0.0, r.E_delivered / r.E_supplied) : kNaN; }

DutyResult start_result(const io::Case& k, SpectrumKind kind) {
    DutyResult d;
    d.kind = kind;
    for (size_t j = 0; j < k.model.mechanisms.size(); ++j) {
        d.mechanisms.emplace_back(k.model.mechanisms[j].name());
        d.power_columns.emplace_back(k.model.mechanisms[j].column());
    }
    d.E_mech.assign(d.mechanisms.size(), 0.0);
    d.oil_limit = k.model.oil.max_temperature;
    d.ambient = k.model.thermal.ambient;
    d.T_oil_min = std::numeric_limits<double>::infinity();
    d.T_oil_max = -std::numeric_limits<double>::infinity();
    return d;
}

void add_row(DutyResult& d, DutyRow r) {
    for (size_t j = 0; j < r.energy.size(); ++j) d.E_mech[j] += r.energy[j];
    d.E_supplied += r.E_supplied;
    d.E_delivered += r.E_delivered;
    d.duration += r.duration;
    d.rows.push_back(std::move(r));
}

// A speed beyond the case's grid, at its cell.
void check_grid_speed(const io::Case& k, const Spectrum& s, size_t i) {
    const double top = grid_max_speed(k.grid);
    if (top > 0 && std::abs(s.speed[i]) > top * (1 + 1e-9))
        throw InputError(s.file, s.line[i], s.speed_column, s.speed_header,
                         fmt::format("{:.6g} rpm beyond the case's operating range (its grid reaches {:.6g} rpm): "
                                     "extend the case's `operating` speeds if the gearbox runs there",
                                     s.speed[i] / kRpm, top / kRpm));
}

}  // namespace

double DutyResult::efficiency() const { return E_supplied > 0 ? E_delivered / E_supplied : kNaN; }

double grid_max_speed(const io::OperatingGrid& g) {
    double top = 0;
    for (double w : g.speeds) top = std::max(top, std::abs(w));
    for (const auto& [w, T] : g.points) top = std::max(top, std::abs(w));
    return top;
}

DutyResult run_time_at_level(const io::Case& k, const Spectrum& s) {
    if (s.kind != SpectrumKind::time_at_level) throw InputError(s.file, 0, 0, "", "not a time-at-level spectrum");
    DutyResult d = start_result(k, s.kind);
    const solver::Model& m = k.model;
    for (size_t i = 0; i < s.speed.size(); ++i) {
        io::throw_if_interrupted();
        check_grid_speed(k, s, i);
        DutyRow r;
        r.line = s.line[i];
        r.speed = s.speed[i];
        r.torque = s.torque[i];
        r.duration = s.duration[i];
        // The bin as `gearloss map` solves it: stabilised (or fixed) oil, every mechanism.
        const solver::PointResult p = solver::solve_point(m, r.speed, r.torque, false);
        if (!solver::has_values(p.status))
            throw InputError(s.file, r.line, 0, "",
                             fmt::format("bin at {:.6g} rpm, {:.6g} N m: {}", r.speed / kRpm, r.torque,
                                         p.status == solver::PointStatus::no_equilibrium
                                             ? "no stable oil temperature below thermal.max_oil_temperature (the "
                                               "gearbox overheats there; give --oil-temp for a cooled sump)"
                                             : solver::status_text(p)));
        r.oil_temperature = p.oil_temperature;
        r.above_oil_limit = p.status == solver::PointStatus::above_oil_limit;
        r.power.assign(p.losses.power.begin(), p.losses.power.end());
        double E_loss = 0;
        for (double P : r.power) {
            r.energy.push_back(P * r.duration);
            E_loss += P * r.duration;
        }
        add_flow(r, p.power_in, r.duration, E_loss);
        r.efficiency = p.has_efficiency ? p.efficiency : kNaN;
        if (r.duration > 0) {
            d.T_oil_min = std::min(d.T_oil_min, r.oil_temperature);
            d.T_oil_max = std::max(d.T_oil_max, r.oil_temperature);
            if (r.above_oil_limit) {
                ++d.bins_above_limit;
                d.time_above_limit += r.duration;
            }
        }
        add_row(d, std::move(r));
    }
    d.T_oil_end = kNaN;
    return d;
}

DutyResult run_time_series(const io::Case& k, const Spectrum& s, double start_temperature, double ambient) {
    if (s.kind != SpectrumKind::time_series) throw InputError(s.file, 0, 0, "", "not a time series");
    const solver::Model& m = k.model;
    DutyResult d = start_result(k, s.kind);
    d.ambient = ambient;
    const bool fixed = m.thermal.mode == solver::ThermalMode::fixed;
    d.transient = !fixed;
    d.start_temperature = fixed ? m.thermal.oil_temperature : start_temperature;
    if (!(s.total_time() <= kMaxSeriesDuration))
        throw InputError(s.file, s.line.back(), s.weight_column, s.weight_header,
                         fmt::format("the series lasts {:g} s; at most {:g} s (11.6 days) are simulated", s.total_time(),
                                     kMaxSeriesDuration));
    const auto& net = m.thermal.network;
    if (d.transient) {
        if (auto f = solver::ambient_fault(ambient)) throw InputError("", 0, 0, "--ambient", *f);
        if (auto f = solver::oil_temperature_fault(m.oil, ambient)) throw InputError("", 0, 0, "--ambient", "ambient " + *f);
        if (auto f = solver::oil_temperature_fault(m.oil, start_temperature)) throw InputError("", 0, 0, "--start-temp", *f);
        if (!(net.C_oil > 0 && std::isfinite(net.C_oil)))
            throw InputError("", 0, 0, "thermal.heat_capacity", "a transient needs a positive, finite heat capacity of the oil");
        if (m.mechanisms.size() > cycle::kMaxMechanisms)
            throw InputError("", 0, 0, "mechanisms", fmt::format("at most {} loss mechanisms in a transient", cycle::kMaxMechanisms));
    }
    cycle::TransientState x = cycle::initial_state({d.start_temperature, d.start_temperature, d.start_temperature});
    const double stored_start = d.transient ? thermal::stored_heat(net, cycle::nodes(x), ambient) : 0.0;
    const size_t n_mech = m.mechanisms.size();
    const auto note_temperature = [&](double T) {
        d.T_oil_min = std::min(d.T_oil_min, T);
        d.T_oil_max = std::max(d.T_oil_max, T);
    };
    note_temperature(x[cycle::kOil]);
    for (size_t i = 0; i + 1 < s.time.size(); ++i) {
        io::throw_if_interrupted();
        check_grid_speed(k, s, i);
        DutyRow r;
        r.line = s.line[i];
        r.time = s.time[i];
        r.speed = s.speed[i];
        r.torque = s.torque[i];
        r.duration = s.time[i + 1] - s.time[i];
        cycle::TransientLoad load;
        load.omega_in = r.speed;
        const bool loaded = r.speed != 0.0;
        if (loaded) {
            load.gearbox = &m;
            solver::prepare_point(m, r.speed, r.torque, load.point);
            if (!load.point.fault.empty())
                throw InputError(s.file, r.line, 0, "",
                                 fmt::format("sample at {:.6g} rpm, {:.6g} N m: out_of_range: {}", r.speed / kRpm,
                                             r.torque, load.point.fault));
        }
        const double T0 = x[cycle::kOil];
        r.oil_temperature = T0;
        cycle::TransientState rates{};
        cycle::transient_rates(m, load, ambient, x, rates);
        r.power.assign(rates.begin() + cycle::kMech0, rates.begin() + cycle::kMech0 + n_mech);
        if (loaded) {
            const std::string fault = solver::loss_fault(m, load.point, T0, ambient);
            if (!fault.empty())
                throw InputError(s.file, r.line, 0, "",
                                 fmt::format("sample at {:.6g} rpm, {:.6g} N m, oil {}: out_of_range: {}", r.speed / kRpm,
                                             r.torque, celsius_text(T0), fault));
        }
        double E_loss = 0;
        if (d.transient) {
            const cycle::TransientState before = x;
            cycle::integrate_interval(m, load, ambient, x, s.time[i], s.time[i + 1]);
            for (size_t j = 0; j < n_mech; ++j) r.energy.push_back(x[cycle::kMech0 + j] - before[cycle::kMech0 + j]);
            const double T1 = x[cycle::kOil];
            if (auto f = solver::oil_temperature_fault(m.oil, T1))
                throw InputError(s.file, s.line[i + 1], 0, "", fmt::format("at t = {:g} s: oil temperature {}", s.time[i + 1], *f));
            if (T1 > m.thermal.equilibrium.T_max)
                throw InputError(s.file, s.line[i + 1], 0, "",
                                 fmt::format("at t = {:g} s the oil reaches {}, above thermal.max_oil_temperature {}: the "
                                             "duty overheats the gearbox beyond what the model covers",
                                             s.time[i + 1], celsius_text(T1), celsius_text(m.thermal.equilibrium.T_max)));
            // Time above the limit: the oil taken as linear over the interval.
            const double lim = d.oil_limit;
            double above = 0;
            if (T0 > lim && T1 > lim) above = 1;
            else if (T0 > lim || T1 > lim) above = (std::max(T0, T1) - lim) / std::abs(T1 - T0);
            d.time_above_limit += above * r.duration;
            r.above_oil_limit = above > 0;
            note_temperature(T1);
        } else {
            for (size_t j = 0; j < n_mech; ++j) r.energy.push_back(r.power[j] * r.duration);
            r.above_oil_limit = T0 > d.oil_limit;
            if (r.above_oil_limit) d.time_above_limit += r.duration;
        }
        for (double e : r.energy) E_loss += e;
        add_flow(r, r.speed * r.torque, r.duration, E_loss);
        r.efficiency = row_efficiency(r);
        add_row(d, std::move(r));
    }
    d.T_oil_end = x[cycle::kOil];
    if (d.transient) {
        d.E_ambient = x[cycle::kAmbient];
        d.stored_change = thermal::stored_heat(net, cycle::nodes(x), ambient) - stored_start;
    }
    return d;
}

}  // namespace gearloss::duty
