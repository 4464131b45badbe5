#include "gearloss/map/loss_table.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_format.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/io/json_text.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/map/vecto.hpp"
#include "gearloss/model/validate.hpp"
#include "gearloss/units/ranges.hpp"
#include "gearloss/units/units.hpp"

namespace gearloss::map {

namespace {
constexpr double kZeroCelsius = 273.15;  // K
constexpr double kRpm = 30.0 / std::numbers::pi;  // rpm per rad/s

std::string trimmed(std::string s) {
    s.erase(0, s.find_first_not_of(" \t"));
    s.erase(s.find_last_not_of(" \t") + 1);
    return s;
}
// Where the unit of "60degC" starts (npos: a bare number).
size_t unit_start(const std::string& s) {
    size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) ++i;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E') && i + 1 < s.size() &&
        (std::isdigit(static_cast<unsigned char>(s[i + 1])) || s[i + 1] == '-' || s[i + 1] == '+')) {
        i += 2;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    }
    while (i < s.size() && s[i] == ' ') ++i;
    return i < s.size() ? i : std::string::npos;
}
}  // namespace

std::vector<double> parse_temperature_list(const std::string& text, const char* what) {
    constexpr const char* kExample = "20,40,60,80degC";
    std::vector<std::string> items;
    for (size_t a = 0; a <= text.size();) {
        const size_t e = std::min(text.find(',', a), text.size());
        items.push_back(trimmed(text.substr(a, e - a)));
        a = e + 1;
    }
    // An item may be a range START:STOP:STEP ("20:100:20degC", units/ranges.hpp): counted in the
    // written unit, so its STEP is in degrees of that scale.
    const auto is_range = [](const std::string& item) { return item.find(':') != std::string::npos; };
    const auto unit_of = [&](const std::string& item) {
        if (is_range(item)) return units::range_unit(item);
        const size_t u = unit_start(item);
        return u == std::string::npos ? std::string() : item.substr(u);
    };
    const std::string unit = unit_of(items.back());
    if (unit.empty())
        throw InputError("", 0, 0, what, fmt::format("'{}': give a unit on the last item (e.g. '{}')", io::excerpt(text), kExample));
    std::vector<double> out;
    const auto read = [&](const std::string& q) {
        units::Quantity v;
        try {
            v = units::parse_quantity(q);
            v.value = units::absolute_temperature(v, q);
        } catch (const units::UnitError& e) {
            throw InputError("", 0, 0, what, e.message + fmt::format(" (expected e.g. '{}')", kExample));
        }
        if (!out.empty() && v.value <= out.back())
            throw InputError("", 0, 0, what, fmt::format("'{}': the temperatures must be strictly ascending", io::excerpt(text)));
        out.push_back(v.value);
    };
    for (const auto& item : items) {
        if (item.empty()) throw InputError("", 0, 0, what, fmt::format("empty item in '{}' (expected e.g. '{}')", io::excerpt(text), kExample));
        if (!is_range(item)) {
            read(unit_start(item) == std::string::npos ? item + " " + unit : item);
            continue;
        }
        std::vector<std::string> expanded;
        try {
            expanded = units::expand_range(item, unit);
        } catch (const units::UnitError& e) {
            throw InputError("", 0, 0, what, e.message + fmt::format(" (expected e.g. '{}' or '20:100:20degC')", kExample));
        }
        for (const auto& q : expanded) read(q);
        if (out.size() > units::kMaxListItems)
            throw InputError("", 0, 0, what, fmt::format("'{}': more than {} values", io::excerpt(text), units::kMaxListItems));
    }
    return out;
}

std::vector<double> default_table_temperatures(const solver::Model& m) {
    const double top = m.oil.max_temperature;
    std::vector<double> T;
    for (double t = kZeroCelsius + 20.0; t < top - 1e-9; t += 20.0) T.push_back(t);
    if (T.empty() || top > T.back()) T.push_back(top);
    return T;
}

LossTableAxes loss_table_axes(const io::Case& k, std::vector<std::string> ratios, std::vector<double> oil_temperatures) {
    if (!k.grid.is_grid) {
        const SourceLocation at = io::case_location(k, "operating");
        throw InputError(at.file, at.line, at.column, "operating",
                         "a loss table needs a speeds x torques grid (or --speed and --torque), not a list of points");
    }
    LossTableAxes a;
    if (ratios.empty()) {
        if (k.model.gearbox.ratios.empty()) ratios.push_back(k.model.ratio);
        else ratios = k.model.ratio_names();
    }
    a.ratios = std::move(ratios);
    for (double w : k.grid.speeds)
        if (!(w > 0))
            throw InputError(k.file, 0, 0, "operating.speeds",
                             fmt::format("{} rpm: a loss table's speeds must be positive (the loss torque is P/omega; "
                                         "the sense of rotation is the case's)", w * kRpm));
    a.speeds = k.grid.speeds;
    std::sort(a.speeds.begin(), a.speeds.end());
    a.speeds.erase(std::unique(a.speeds.begin(), a.speeds.end()), a.speeds.end());
    a.torques = vecto_torque_axis(k.grid.torques);
    for (double T : oil_temperatures)
        if (auto f = solver::oil_temperature_fault(k.model.oil, T))
            throw InputError("", 0, 0, "--oil-temps", fmt::format("{:.2f} degC: {}", T - kZeroCelsius, *f));
    a.oil_temperatures = std::move(oil_temperatures);
    if (a.size() > kMaxTablePoints)
        throw InputError("", 0, 0, "--format table",
                         fmt::format("{} points ({} ratios x {} speeds x {} torques x {} temperatures); a table holds at most {}",
                                     a.size(), a.ratios.size(), a.speeds.size(), a.torques.size(),
                                     a.oil_temperatures.size(), kMaxTablePoints));
    return a;
}

size_t LossTable::holes() const {
    return static_cast<size_t>(std::count_if(total.begin(), total.end(), [](double v) { return !std::isfinite(v); }));
}

std::string loss_table_csv_header(const solver::Model& m) {
    std::string h = "ratio,ratio_value,speed_in_rpm,torque_in_Nm,oil_temp_C,torque_loss_Nm,P_total_W";
    for (size_t i = 0; i < m.mechanisms.size(); ++i) h += fmt::format(",{}", m.mechanisms[i].column());
    return h + ",efficiency,status\n";
}

namespace {
// The efficiency in the direction the power flows: P_out / P_in in drive, P_in / P_out in
// overrun (the output drives, the input receives); none at zero input power.
double flow_efficiency(const solver::PointResult& r) {
    if (r.power_in > 0.0) return r.has_efficiency ? r.efficiency : std::nan("");
    if (r.power_in < 0.0 && r.power_out < 0.0) return r.power_in / r.power_out;
    return std::nan("");
}
}  // namespace

LossTable run_loss_table(const solver::Model& base, const LossTableAxes& axes, const MapOptions& opt,
                         const TextSink& write) {
    LossTable t;
    t.axes = axes;
    for (size_t i = 0; i < base.mechanisms.size(); ++i) t.columns.emplace_back(base.mechanisms[i].column());
    const size_t n = axes.size();
    t.total.assign(n, std::nan(""));
    t.power.assign(t.columns.size(), std::vector<double>(n, std::nan("")));
    t.status.assign(n, "");
    io::OperatingGrid grid;
    grid.speeds = axes.speeds;
    grid.torques = axes.torques;
    const TextSink sink = write ? write : [](std::string_view) {};
    for (size_t ir = 0; ir < axes.ratios.size(); ++ir) {
        solver::Model m = base;
        if (!axes.ratios[ir].empty()) m.select_ratio(axes.ratios[ir]);
        t.ratio_values.push_back(m.layout.ratio);
        std::string lead = axes.ratios[ir] + ",";
        io::append_csv_number(lead, m.layout.ratio);
        lead += ',';
        for (size_t iT = 0; iT < axes.oil_temperatures.size(); ++iT) {
            m.thermal.mode = solver::ThermalMode::fixed;
            m.thermal.oil_temperature = axes.oil_temperatures[iT];
            const double T_C = axes.oil_temperatures[iT] - kZeroCelsius;
            // Rows of distinct points write distinct slots of the table: no lock needed.
            auto format = [&](const solver::PointResult& r, size_t row, std::string& out) {
                const size_t is = row / grid.torques.size(), iq = row % grid.torques.size();
                const size_t at = t.index(ir, is, iq, iT);
                const bool ok = solver::has_values(r.status);
                t.status[at] = solver::status_text(r);
                out += lead;
                io::append_csv_number(out, r.speed_in * kRpm);
                out += ',';
                io::append_csv_number(out, r.torque_in);
                out += ',';
                io::append_csv_fixed(out, T_C, 2);
                out += ',';
                if (ok) {
                    const double P = r.losses.total();
                    t.total[at] = P;
                    io::append_csv_number(out, P / r.speed_in);
                    out += ',';
                    io::append_csv_number(out, P);
                    for (size_t i = 0; i < r.losses.power.size(); ++i) {
                        t.power[i][at] = r.losses.power[i];
                        out += ',';
                        io::append_csv_number(out, r.losses.power[i]);
                    }
                    out += ',';
                    io::append_csv_fixed(out, flow_efficiency(r), 6);
                    out += ',';
                } else {
                    out.append(t.columns.size() + 3, ',');
                }
                out += t.status[at];
                out += '\n';
            };
            stream_rows(m, grid, 0, grid.size(), opt, format, sink, nullptr);
            io::throw_if_interrupted();
        }
    }
    return t;
}

namespace {
// values[index(r, s, q, T)] as nested arrays [r][s][q][T]; non-finite values as null.
template <class Value>
nlohmann::ordered_json nested(const LossTable& t, const Value& value) {
    const auto& a = t.axes;
    nlohmann::ordered_json by_ratio = nlohmann::ordered_json::array();
    for (size_t r = 0; r < a.ratios.size(); ++r) {
        nlohmann::ordered_json by_speed = nlohmann::ordered_json::array();
        for (size_t s = 0; s < a.speeds.size(); ++s) {
            nlohmann::ordered_json by_torque = nlohmann::ordered_json::array();
            for (size_t q = 0; q < a.torques.size(); ++q) {
                nlohmann::ordered_json by_T = nlohmann::ordered_json::array();
                for (size_t T = 0; T < a.oil_temperatures.size(); ++T) {
                    const double v = value(t.index(r, s, q, T), s);
                    by_T.push_back(io::json_number(v));
                }
                by_torque.push_back(std::move(by_T));
            }
            by_speed.push_back(std::move(by_torque));
        }
        by_ratio.push_back(std::move(by_speed));
    }
    return by_ratio;
}
}  // namespace

std::string loss_table_json(const LossTable& t) {
    using J = nlohmann::ordered_json;
    const auto& a = t.axes;
    J j;
    j["format"] = "gearloss-loss-table/1";
    j["index_order"] = {"ratio", "speed_in_rpm", "torque_in_Nm", "oil_temp_C"};
    J bp;
    bp["ratio"] = a.ratios;
    bp["ratio_value"] = t.ratio_values;
    J gear = J::array();
    for (size_t r = 0; r < a.ratios.size(); ++r) gear.push_back(r + 1);
    bp["gear"] = gear;
    J speeds = J::array(), temps = J::array();
    // rpm as given in the case (rad/s and back: 3000.0000000000005 without the rounding).
    for (double w : a.speeds) speeds.push_back(std::round(w * kRpm * 1e6) / 1e6);
    for (double T : a.oil_temperatures) temps.push_back(T - kZeroCelsius);
    bp["speed_in_rpm"] = speeds;
    bp["torque_in_Nm"] = a.torques;
    bp["oil_temp_C"] = temps;
    j["breakpoints"] = bp;
    j["units"] = {{"ratio_value", "omega_out/omega_in"}, {"speed_in_rpm", "rpm"}, {"torque_in_Nm", "N m"},
                  {"oil_temp_C", "degC"}, {"torque_loss_Nm", "N m"}, {"P_W", "W"}};
    j["sign_convention"] = "torque_in_Nm > 0: drive (power enters at the input); < 0: overrun (the output drives). "
                           "torque_loss_Nm = P_total_W / omega_in > 0 in both directions";
    j["fill"] = "null where a point has no value (see the CSV's status column); MATLAB jsondecode reads null as NaN";
    j["holes"] = t.holes();
    J tables;
    tables["torque_loss_Nm"] = nested(t, [&](size_t i, size_t s) { return t.total[i] / a.speeds[s]; });
    tables["P_total_W"] = nested(t, [&](size_t i, size_t) { return t.total[i]; });
    for (size_t m = 0; m < t.columns.size(); ++m)
        tables[t.columns[m]] = nested(t, [&](size_t i, size_t) { return t.power[m][i]; });
    j["tables"] = std::move(tables);
    return j.dump() + "\n";
}

}  // namespace gearloss::map
