#include "gearloss/duty/duty_report.hpp"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/io/json_text.hpp"

namespace gearloss::duty {

namespace {

constexpr double kRpm = std::numbers::pi / 30.0;
constexpr double kWh = 3.6e6;  // J per kWh

// "E_mesh_kWh" from "P_mesh_W".
std::string energy_column(const std::string& power_column) {
    std::string c = power_column;
    if (c.size() > 4 && c.compare(0, 2, "P_") == 0 && c.compare(c.size() - 2, 2, "_W") == 0)
        c = c.substr(2, c.size() - 4);
    return "E_" + c + "_kWh";
}

std::string number(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : std::string(); }

const char* kind_name(SpectrumKind k) { return k == SpectrumKind::time_at_level ? "time_at_level" : "time_series"; }

}  // namespace

std::string duty_csv_header(const DutyResult& d) {
    std::string h = d.kind == SpectrumKind::time_at_level ? "line,speed_in_rpm,torque_in_Nm,duration_h,power_in_W,oil_temp_C"
                                                          : "line,time_s,speed_in_rpm,torque_in_Nm,duration_s,power_in_W,oil_temp_C";
    for (const auto& c : d.power_columns) h += "," + c;
    h += ",P_total_W,efficiency";
    for (const auto& c : d.power_columns) h += "," + energy_column(c);
    h += ",E_loss_kWh,above_oil_limit\n";
    return h;
}

std::string duty_csv(const DutyResult& d) {
    std::string out = duty_csv_header(d);
    const bool level = d.kind == SpectrumKind::time_at_level;
    for (const auto& r : d.rows) {
        out += std::to_string(r.line);
        if (!level) out += "," + number(r.time);
        out += "," + number(r.speed / kRpm) + "," + number(r.torque) + "," + number(level ? r.duration / 3600 : r.duration);
        out += "," + number(r.speed * r.torque) + "," + number(r.oil_temperature - 273.15);
        double P = 0, E = 0;
        for (double x : r.power) {
            out += "," + number(x);
            P += x;
        }
        out += "," + number(P) + "," + number(r.efficiency);
        for (double x : r.energy) {
            out += "," + number(x / kWh);
            E += x;
        }
        out += "," + number(E / kWh) + (r.above_oil_limit ? ",1\n" : ",0\n");
    }
    return out;
}

namespace {
// An energy for the reader: kWh, MWh or GWh, whichever keeps it below 10 000, four figures.
std::string energy_text(double joules) {
    const double kwh = joules / kWh;
    const double a = std::abs(kwh);
    if (a >= 1e7) return fmt::format("{:.4g} GWh", kwh / 1e6);
    if (a >= 1e4) return fmt::format("{:.4g} MWh", kwh / 1e3);
    return fmt::format("{:.4g} kWh", kwh);
}
}  // namespace

std::string duty_summary_text(const DutyResult& d, const Spectrum& s) {
    const bool level = d.kind == SpectrumKind::time_at_level;
    std::string t = fmt::format("duty {} ({}, {} {}): {:.6g} h\n", s.file,
                                level ? "time at level" : "time series", d.rows.size(), level ? "bins" : "intervals",
                                d.duration / 3600);
    if (level && s.from_share) t += "  shares scaled to the total time given (--total-time)\n";
    if (!level)
        t += d.transient ? fmt::format("  oil from {:.1f} degC at ambient {:.1f} degC, integrated in time\n",
                                       d.start_temperature - 273.15, d.ambient - 273.15)
                         : fmt::format("  oil held at {:.1f} degC (fixed)\n", d.start_temperature - 273.15);
    t += fmt::format("  energy supplied {}, delivered {}, lost {}\n", energy_text(d.E_supplied),
                     energy_text(d.E_delivered), energy_text(d.loss()));
    t += fmt::format("  energy-weighted efficiency {}\n", std::isfinite(d.efficiency()) ? fmt::format("{:.5f}", d.efficiency()) : "-");
    for (size_t j = 0; j < d.mechanisms.size(); ++j)
        t += fmt::format("    {:<14} {:>12}  {:5.1f} %\n", d.mechanisms[j], energy_text(d.E_mech[j]),
                         d.loss() > 0 ? 100 * d.E_mech[j] / d.loss() : 0.0);
    if (std::isfinite(d.T_oil_min))
        t += fmt::format("  oil {:.1f} .. {:.1f} degC{}; permissible {:.1f} degC\n", d.T_oil_min - 273.15,
                         d.T_oil_max - 273.15,
                         std::isfinite(d.T_oil_end) ? fmt::format(", {:.1f} degC at the end", d.T_oil_end - 273.15) : "",
                         d.oil_limit - 273.15);
    if (level)
        t += fmt::format("  bins above the oil's limit: {} ({:.6g} h)\n", d.bins_above_limit, d.time_above_limit / 3600);
    else
        t += fmt::format("  time above the oil's limit: {:.6g} s\n", d.time_above_limit);
    if (d.transient)
        t += fmt::format("  heat to ambient {}, stored {} (loss = ambient + stored)\n", energy_text(d.E_ambient),
                         energy_text(d.stored_change));
    return t;
}

std::string duty_summary_json(const DutyResult& d, const Spectrum& s) {
    nlohmann::ordered_json j;
    j["spectrum"] = s.file;
    j["kind"] = kind_name(d.kind);
    j["rows"] = d.rows.size();
    j["duration_h"] = io::json_number(d.duration / 3600);
    if (d.kind == SpectrumKind::time_series) {
        j["transient"] = d.transient;
        j["start_oil_temp_C"] = io::json_number(d.start_temperature - 273.15);
        j["ambient_C"] = io::json_number(d.ambient - 273.15);
    }
    j["energy_supplied_kWh"] = io::json_number(d.E_supplied / kWh);
    j["energy_delivered_kWh"] = io::json_number(d.E_delivered / kWh);
    j["energy_loss_kWh"] = io::json_number(d.loss() / kWh);
    j["efficiency"] = io::json_number(d.efficiency());
    auto& e = j["energy_loss_by_mechanism_kWh"];
    e = nlohmann::ordered_json::object();
    for (size_t k = 0; k < d.mechanisms.size(); ++k) e[d.mechanisms[k]] = io::json_number(d.E_mech[k] / kWh);
    j["oil_limit_C"] = io::json_number(d.oil_limit - 273.15);
    j["oil_temp_min_C"] = io::json_number(d.T_oil_min - 273.15);
    j["oil_temp_max_C"] = io::json_number(d.T_oil_max - 273.15);
    if (std::isfinite(d.T_oil_end)) j["oil_temp_end_C"] = io::json_number(d.T_oil_end - 273.15);
    if (d.kind == SpectrumKind::time_at_level) {
        j["bins_above_oil_limit"] = d.bins_above_limit;
        auto& lines = j["lines_above_oil_limit"];
        lines = nlohmann::ordered_json::array();
        for (const auto& r : d.rows)
            if (r.above_oil_limit && r.duration > 0) lines.push_back(r.line);
    }
    j["time_above_oil_limit_h"] = io::json_number(d.time_above_limit / 3600);
    if (d.transient) {
        j["heat_to_ambient_kWh"] = io::json_number(d.E_ambient / kWh);
        j["heat_stored_kWh"] = io::json_number(d.stored_change / kWh);
    }
    return io::json_line(j);
}

}  // namespace gearloss::duty
