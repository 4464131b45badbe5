#include "gearloss/results/cycle_report.hpp"

#include "gearloss/losses/loss_mechanism.hpp"

#include <chrono>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_format.hpp"
#include "gearloss/io/json_text.hpp"
#include "gearloss/model/validate.hpp"

namespace gearloss::io {

namespace {
constexpr double kRpm = 30.0 / std::numbers::pi;
double celsius(double K) { return K - 273.15; }
}  // namespace

cycle::Powertrain load_powertrain(const Case& c, const std::optional<std::string>& oil_file) {
    if (!c.vehicle) throw InputError(c.file, 0, 0, "vehicle", "the case has no 'vehicle' block (needed by `gearloss cycle`)");
    cycle::Powertrain pt;
    pt.vehicle = *c.vehicle;
    pt.torque_converter = c.torque_converter;
    // One loaded case; each gear is the model with that ratio selected (no re-reading).
    Case k = c;
    if (oil_file) replace_oil(k, load_oil_file(*oil_file));
    for (const auto& g : c.vehicle->gears) pt.gears.push_back(k.model.with_ratio(g));
    // No vehicle.gears: one gear, the case's fixed ratio.
    if (c.vehicle->gears.empty()) pt.gears.push_back(k.model);
    return pt;
}

void CycleStudyOptions::validate() const {
    const auto temperature = [](const char* key, double T) {
        // The bounds as written in degC: -100 degC is 173.14999999999998 K after the offset.
        constexpr double rounding = 1e-9;
        if (!(T >= solver::kMinAmbient_K - rounding && T <= solver::kMaxAmbient_K + rounding))
            throw InputError("", 0, 0, key, fmt::format("{:.4g} degC is outside the stated range -100..300 degC", T - 273.15));
    };
    temperature("--start-temp", start_temperature);
    temperature("--ambient", ambient);
    temperature("--warm-temp", warm_temperature);
    if (prewarm_target) {
        temperature("--prewarm", *prewarm_target);
        if (!(*prewarm_target > start_temperature))
            throw InputError("", 0, 0, "--prewarm", "the pre-warm temperature must be above the start temperature");
    }
    if (!(heater_power > 0 && heater_power <= 1e6))
        throw InputError("", 0, 0, "--heater", "heater power must be positive and at most 1 MW");
}

CycleStudy run_cycle_study(const cycle::Powertrain& pt, const cycle::DriveCycle& dc, const CycleStudyOptions& o) {
    o.validate();
    CycleStudy s;
    s.cycle_name = dc.name;
    const auto t0 = std::chrono::steady_clock::now();
    s.cold = cycle::simulate_cycle(pt, dc, cycle::uniform(o.start_temperature), o.ambient, o.keep_traces);
    s.seconds_per_run = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // The traces of the reference runs cost the loss rates at each step (not the integration):
    // the totals are those of a run without trace.
    auto warm = cycle::simulate_cycle(pt, dc, cycle::uniform(o.warm_temperature), o.ambient, o.keep_traces);
    s.warm = warm.totals;
    s.warm_trace = std::move(warm.trace);
    if (o.prewarm_target) {
        const auto& net = pt.thermal_model().thermal.network;
        s.ideal_prewarm_time = net.C_oil * (*o.prewarm_target - o.start_temperature) / o.heater_power;
        s.prewarm = cycle::prewarm(pt, cycle::uniform(o.start_temperature), *o.prewarm_target, o.heater_power, o.ambient);
        auto run = cycle::simulate_cycle(pt, dc, s.prewarm->state, o.ambient, o.keep_traces);
        s.prewarmed = run.totals;
        s.prewarmed_trace = std::move(run.trace);
    }
    return s;
}

namespace {
// The columns of a reference run (`prefix`_oil_temp_C, ...).
std::string run_columns(const char* prefix, bool tc) {
    std::string s = fmt::format(",{0}_oil_temp_C,{0}_P_gearbox_W", prefix);
    if (tc) s += fmt::format(",{}_P_converter_W", prefix);
    return s;
}
// What the time series keeps of a reference run at a step, and its cells.
struct RunCells {
    double T_oil = 0, P_gearbox = 0, P_tc = 0;
    static RunCells of(const cycle::TraceRow& t) { return {t.T_oil, t.P_gearbox, t.P_tc}; }
};
std::string run_cells(const RunCells& t, bool tc) {
    std::string s = "," + csv_fixed(celsius(t.T_oil), 3) + "," + csv_number(t.P_gearbox);
    if (tc) s += "," + csv_number(t.P_tc);
    return s;
}

// The time series' header line (with its newline): the start run's columns, then the
// reference runs' (`warm`, `prewarmed`) when they are in the table.
std::string trace_header(const cycle::Powertrain& pt, bool warm, bool prewarmed) {
    const bool fuel = pt.vehicle.engine.fuel_map.has_value();
    const bool tc = pt.torque_converter.has_value();
    const auto& net = pt.thermal_model().thermal.network;
    std::string s =
        "time_s,speed_kmh,accel_m_s2,gear,input_speed_rpm,input_torque_Nm,engine_speed_rpm,engine_torque_Nm,oil_temp_C";
    if (net.has_housing()) s += ",housing_temp_C";
    if (net.has_clutch()) s += ",clutch_temp_C";
    const auto& mechs = pt.thermal_model().mechanisms;
    for (size_t k = 0; k < mechs.size(); ++k) s += fmt::format(",{}", mechs[k].column());
    s += ",P_gearbox_W";
    if (tc) s += ",P_converter_W,converter_speed_ratio,lockup";
    if (fuel) s += ",fuel_g_s";
    if (warm) s += run_columns("warm", tc);
    if (prewarmed) s += run_columns("prewarmed", tc);
    return s + "\n";
}

// One step of the time series appended to `s`: the start run's row `t`, the reference runs'
// cells at the same step (null: not in the table).
void append_trace_row(std::string& s, const cycle::Powertrain& pt, const cycle::TraceRow& t, const RunCells* warm,
                      const RunCells* prewarmed) {
    const bool fuel = pt.vehicle.engine.fuel_map.has_value();
    const bool tc = pt.torque_converter.has_value();
    const auto& net = pt.thermal_model().thermal.network;
    const auto& mechs = pt.thermal_model().mechanisms;
    s += fmt::format("{},{},{},{},{},{},{},{},{}", csv_number(t.time), csv_fixed(t.speed * 3.6, 3), csv_number(t.accel),
                     t.gear, csv_number(t.input_speed * kRpm), csv_number(t.input_torque), csv_number(t.engine_speed * kRpm),
                     csv_number(t.engine_torque), csv_fixed(celsius(t.T_oil), 3));
    if (net.has_housing()) s += "," + csv_fixed(celsius(t.T_housing), 3);
    if (net.has_clutch()) s += "," + csv_fixed(celsius(t.T_clutch), 3);
    for (size_t k = 0; k < mechs.size(); ++k) s += "," + csv_number(k < t.P_mech.size() ? t.P_mech[k] : 0.0);
    s += "," + csv_number(t.P_gearbox);
    if (tc) s += fmt::format(",{},{},{}", csv_number(t.P_tc), csv_number(t.tc_speed_ratio), t.lockup ? 1 : 0);
    if (fuel) s += "," + csv_number(t.fuel_rate * 1e3);
    if (warm) s += run_cells(*warm, tc);
    if (prewarmed) s += run_cells(*prewarmed, tc);
    s += "\n";
}
}  // namespace

std::string cycle_trace_csv(const cycle::Powertrain& pt, const CycleStudy& study) {
    const auto& r = study.cold;
    // The reference runs step through the same cycle: one row each per row of the start run.
    const bool warm = study.warm_trace.size() == r.trace.size();
    const bool prewarmed = study.prewarmed && study.prewarmed_trace.size() == r.trace.size();
    std::string s = trace_header(pt, warm, prewarmed);
    for (size_t i = 0; i < r.trace.size(); ++i) {
        const RunCells w = warm ? RunCells::of(study.warm_trace[i]) : RunCells{};
        const RunCells p = prewarmed ? RunCells::of(study.prewarmed_trace[i]) : RunCells{};
        append_trace_row(s, pt, r.trace[i], warm ? &w : nullptr, prewarmed ? &p : nullptr);
    }
    return s;
}

std::string cycle_trace_header(const cycle::Powertrain& pt, const CycleStudy& study) {
    return trace_header(pt, true, study.prewarm && study.prewarmed);
}

void write_cycle_trace(const cycle::Powertrain& pt, const cycle::DriveCycle& dc, const CycleStudy& study,
                       const CycleStudyOptions& o, const std::function<void(std::string_view)>& write) {
    // The reference runs again, their cells kept (3 numbers a step); then the start run again,
    // each row formatted as it comes and written a chunk at a time.
    const auto cells_of = [&](const thermal::NodeTemperatures& start) {
        std::vector<RunCells> v;
        v.reserve(dc.time.size());
        cycle::simulate_cycle(pt, dc, start, o.ambient, true, [&](const cycle::TraceRow& t) { v.push_back(RunCells::of(t)); });
        return v;
    };
    const std::vector<RunCells> warm = cells_of(cycle::uniform(o.warm_temperature));
    const bool prewarmed = study.prewarm && study.prewarmed;
    const std::vector<RunCells> pre = prewarmed ? cells_of(study.prewarm->state) : std::vector<RunCells>{};
    std::string chunk = trace_header(pt, true, prewarmed);
    size_t i = 0;
    cycle::simulate_cycle(pt, dc, cycle::uniform(o.start_temperature), o.ambient, true, [&](const cycle::TraceRow& t) {
        append_trace_row(chunk, pt, t, i < warm.size() ? &warm[i] : nullptr, prewarmed && i < pre.size() ? &pre[i] : nullptr);
        ++i;
        if (chunk.size() >= kTraceChunkBytes) {
            write(chunk);
            chunk.clear();
        }
    });
    write(chunk);
}

std::string engine_beyond_map_warning(const cycle::CycleTotals::EngineBeyondData& b, std::string_view indent) {
    if (b.rows == 0) return {};
    return fmt::format("{}warning: the engine is asked beyond its fuel map ({:.0f} N m) on {} row{} from t = {:g} s{}, up to "
                       "{:.0f} N m at t = {:g} s: the vehicle could not follow the cycle there and the fuel is read at the "
                       "map's edge (give the engine a max_torque to make such rows errors)\n",
                       indent, b.map_torque, b.rows, b.rows == 1 ? "" : "s", b.first_time,
                       b.first_line > 0 ? fmt::format(" (line {})", b.first_line) : std::string(), b.peak_torque,
                       b.peak_time);
}

namespace {
double litres(const cycle::Powertrain& pt, double kg) { return kg / pt.vehicle.engine.fuel_density * 1e3; }

nlohmann::ordered_json totals_json(const cycle::Powertrain& pt, const cycle::CycleTotals& t) {
    nlohmann::ordered_json j;
    j["oil_temp_start_C"] = celsius(t.start[0]);
    j["oil_temp_end_C"] = celsius(t.end[0]);
    j["gearbox_loss_kJ"] = t.gearbox_loss() / 1e3;
    const auto& mechs = pt.thermal_model().mechanisms;
    for (size_t k = 0; k < mechs.size(); ++k)
        j[std::string(mechs[k].name()) + "_kJ"] = k < t.E_mech.size() ? t.E_mech[k] / 1e3 : 0.0;
    j["converter_kJ"] = t.E_tc / 1e3;
    j["heat_to_ambient_kJ"] = t.E_ambient / 1e3;
    j["gearbox_mean_efficiency"] = t.mean_efficiency();
    if (pt.vehicle.motor) {
        // Drive and recuperation energies at the gearbox's two shafts (docs/config.md, vehicle.motor).
        j["gearbox_input_kJ"] = t.E_gearbox_in / 1e3;
        j["gearbox_output_kJ"] = t.E_gearbox_out / 1e3;
        j["recuperation_output_supplied_kJ"] = t.E_output_supplied / 1e3;
        j["recuperation_input_recovered_kJ"] = t.E_input_recovered / 1e3;
    }
    if (t.has_fuel) {
        j["fuel_L"] = litres(pt, t.fuel);
        j["fuel_L_per_100km"] = t.distance > 0 ? litres(pt, t.fuel) / (t.distance / 1e5) : 0.0;
    }
    if (const auto& b = t.engine_beyond_map; b.rows > 0) {
        auto& e = j["engine_beyond_fuel_map"];
        e["rows"] = b.rows;
        e["fuel_map_max_torque_Nm"] = b.map_torque;
        e["peak_torque_Nm"] = b.peak_torque;
        e["peak_time_s"] = b.peak_time;
        e["first_time_s"] = b.first_time;
        if (b.first_line > 0) e["first_line"] = b.first_line;
    }
    return j;
}

std::string totals_text(const cycle::Powertrain& pt, const cycle::CycleTotals& t, const char* label) {
    const auto& mechs = pt.thermal_model().mechanisms;
    std::string parts;
    for (size_t k = 0; k < mechs.size(); ++k)
        parts += fmt::format("{}{} {:.1f}", k ? ", " : "", mechs[k].label(), k < t.E_mech.size() ? t.E_mech[k] / 1e3 : 0.0);
    std::string s = fmt::format("{}: oil {:.1f} -> {:.1f} degC; gearbox loss {:.1f} kJ ({})", label, celsius(t.start[0]),
                                celsius(t.end[0]), t.gearbox_loss() / 1e3, parts);
    if (pt.torque_converter) s += fmt::format(", converter {:.1f} kJ", t.E_tc / 1e3);
    s += fmt::format("; mean gearbox efficiency {:.2f} %", 100 * t.mean_efficiency());
    if (t.has_fuel)
        s += t.distance > 0
                 ? fmt::format("; fuel {:.3f} L ({:.2f} L/100 km)", litres(pt, t.fuel), litres(pt, t.fuel) / (t.distance / 1e5))
                 : fmt::format("; fuel {:.3f} L (no distance driven)", litres(pt, t.fuel));
    return s + "\n" + engine_beyond_map_warning(t.engine_beyond_map, "       ");
}

double relative_saving(double base, double other) { return base > 0 ? (base - other) / base : 0.0; }
}  // namespace

std::string cycle_summary_text(const cycle::Powertrain& pt, const CycleStudy& s, const CycleStudyOptions& o) {
    const auto& c = s.cold.totals;
    std::string out = fmt::format("cycle {}: {:.0f} s, {:.3f} km, tractive energy at the wheels {:.0f} kJ; ambient {:.1f} degC\n",
                                  s.cycle_name, c.duration, c.distance / 1e3, c.E_wheel / 1e3, celsius(o.ambient));
    out += totals_text(pt, c, "start  ");
    out += totals_text(pt, s.warm, "warm   ");
    const double extra = c.gearbox_loss() + c.E_tc - s.warm.gearbox_loss() - s.warm.E_tc;
    out += fmt::format("cold start costs {:.1f} kJ more transmission loss than a warm start at {:.0f} degC", extra / 1e3,
                       celsius(o.warm_temperature));
    if (c.has_fuel)
        out += fmt::format(" ({:.3f} L fuel, {:.2f} %)", litres(pt, c.fuel - s.warm.fuel),
                           100 * relative_saving(c.fuel, s.warm.fuel));
    out += "\n";
    if (s.prewarm) {
        const auto& p = *s.prewarm;
        out += fmt::format("pre-warm to {:.0f} degC at {:.0f} W: ideal (no heat loss, oil node {:.0f} J/K) {:.0f} s; ",
                           celsius(*o.prewarm_target), o.heater_power, pt.thermal_model().thermal.network.C_oil,
                           s.ideal_prewarm_time);
        if (p.reached)
            out += fmt::format("with the heat path to ambient {:.0f} s, {:.1f} kJ ({:.1f} kJ lost meanwhile)\n", p.time,
                               p.energy / 1e3, p.heat_lost / 1e3);
        else
            out += fmt::format("not reached: the oil levels off at {:.1f} degC (heat loss = heater power); after {:.0f} s "
                               "it is at {:.1f} degC, {:.1f} kJ spent\n",
                               celsius(p.max_oil_temperature), p.time, celsius(p.state[0]), p.energy / 1e3);
        const auto& w = *s.prewarmed;
        out += totals_text(pt, w, "prewarm");
        const double saved = c.gearbox_loss() + c.E_tc - w.gearbox_loss() - w.E_tc;
        out += fmt::format("pre-warming saves {:.1f} kJ of transmission loss for {:.1f} kJ of heater energy", saved / 1e3,
                           p.energy / 1e3);
        if (c.has_fuel) {
            const double fuel_saved = c.fuel - w.fuel;
            out += fmt::format("; fuel {:.3f} L ({:.2f} %), {:.1f} kJ of fuel energy; net {:.1f} kJ", litres(pt, fuel_saved),
                               100 * relative_saving(c.fuel, w.fuel), fuel_saved * pt.vehicle.engine.lower_heating_value / 1e3,
                               (fuel_saved * pt.vehicle.engine.lower_heating_value - p.energy) / 1e3);
        }
        out += "\n";
    }
    return out;
}

std::string cycle_summary_json(const cycle::Powertrain& pt, const CycleStudy& s, const CycleStudyOptions& o) {
    nlohmann::ordered_json j;
    const auto& c = s.cold.totals;
    j["cycle"] = s.cycle_name;
    j["duration_s"] = c.duration;
    j["distance_km"] = c.distance / 1e3;
    j["wheel_energy_kJ"] = c.E_wheel / 1e3;
    j["ambient_C"] = celsius(o.ambient);
    j["start"] = totals_json(pt, c);
    j["warm_start"] = totals_json(pt, s.warm);
    if (s.prewarm) {
        const auto& p = *s.prewarm;
        nlohmann::ordered_json w;
        w["target_C"] = celsius(*o.prewarm_target);
        w["heater_W"] = o.heater_power;
        w["ideal_time_s"] = s.ideal_prewarm_time;
        w["reached"] = p.reached;
        w["time_s"] = p.time;
        w["energy_kJ"] = p.energy / 1e3;
        w["heat_lost_kJ"] = p.heat_lost / 1e3;
        if (!p.reached) w["levels_off_at_C"] = celsius(p.max_oil_temperature);
        w["run"] = totals_json(pt, *s.prewarmed);
        if (c.has_fuel) {
            w["fuel_saved_L"] = litres(pt, c.fuel - s.prewarmed->fuel);
            w["fuel_saved_percent"] = 100 * relative_saving(c.fuel, s.prewarmed->fuel);
        }
        j["prewarm"] = std::move(w);
    }
    return json_line(j);
}

}  // namespace gearloss::io
