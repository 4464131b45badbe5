#include "gearloss/results/rating_report.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <limits>
#include <numbers>

#include "gearloss/io/csv_format.hpp"
#include "gearloss/io/json_text.hpp"
#include "gearloss/losses/loss_mechanism.hpp"

namespace gearloss::io {

namespace {
constexpr double kRpm = 30.0 / std::numbers::pi;
double celsius(double K) { return K - 273.15; }

// The value of a point that carries values, else NaN (an empty cell, a JSON null).
double value_if(const solver::PointResult& r, double v) {
    return solver::has_values(r.status) ? v : std::numeric_limits<double>::quiet_NaN();
}

std::string mechanism_columns(const solver::Model& m) {
    std::string s;
    for (size_t i = 0; i < m.mechanisms.size(); ++i) s += fmt::format(",{}", m.mechanisms[i].column());
    return s;
}

void append_mechanisms(std::string& out, const solver::Model& m, const solver::PointResult& r) {
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        out += ',';
        if (solver::has_values(r.status) && i < r.losses.power.size()) append_csv_number(out, r.losses.power[i]);
    }
}
}  // namespace

std::vector<double> rating_speeds(const OperatingGrid& g) {
    std::vector<double> w;
    if (g.is_grid) w = g.speeds;
    else
        for (const auto& p : g.points) w.push_back(p.first);
    std::erase_if(w, [](double x) { return !(x > 0); });
    std::sort(w.begin(), w.end());
    w.erase(std::unique(w.begin(), w.end()), w.end());
    return w;
}

double largest_torque(const OperatingGrid& g) {
    double t = 0;
    if (g.is_grid)
        for (double x : g.torques) t = std::max(t, x);
    else
        for (const auto& p : g.points) t = std::max(t, p.second);
    return t;
}

std::string rating_csv(const Case& k, const RatingStudy& s) {
    const auto& m = k.model;
    std::string out;
    if (s.target > 0) {
        out = "speed_in_rpm,torque_in_Nm,power_in_W,status,target_oil_temp_C,P_loss_W" + mechanism_columns(m) +
              ",housing_heat_W,cooler_duty_W\n";
        for (const auto& d : s.duty) {
            const auto& r = d.point;
            out += csv_number(d.omega * kRpm) + ',' + csv_number(d.torque) + ',' + csv_number(d.omega * d.torque) + ',' +
                   solver::status_text(r) + ',' + csv_number(celsius(s.target)) + ',' +
                   csv_number(value_if(r, r.losses.total()));
            append_mechanisms(out, m, r);
            out += ',' + csv_number(value_if(r, d.housing_heat)) + ',' + csv_number(value_if(r, d.duty)) + '\n';
        }
        return out;
    }
    out = "speed_in_rpm,rating,torque_in_Nm,power_in_W,oil_temp_C,P_loss_W" + mechanism_columns(m) +
          ",housing_heat_W,cooler_heat_W,efficiency,status\n";
    for (const auto& p : s.curve) {
        const auto& r = p.point;
        out += csv_number(p.omega * kRpm) + ',' + rating::to_string(p.status) + ',' + csv_number(p.torque) + ',' +
               csv_number(p.omega * p.torque) + ',' + csv_number(value_if(r, celsius(r.oil_temperature))) + ',' +
               csv_number(value_if(r, r.losses.total()));
        append_mechanisms(out, m, r);
        out += ',' + csv_number(value_if(r, p.housing_heat)) + ',' + csv_number(value_if(r, p.cooler_heat)) + ',' +
               csv_number(r.has_efficiency ? r.efficiency : std::numeric_limits<double>::quiet_NaN()) + ',' +
               solver::status_text(r) + '\n';
    }
    return out;
}

std::string rating_text(const Case& k, const RatingStudy& s) {
    const auto& m = k.model;
    std::string out = fmt::format("{}: thermal rating, ambient {:.1f} degC", m.name, celsius(s.options.ambient));
    if (s.target > 0) {
        out += fmt::format(", oil held at {:.1f} degC\n", celsius(s.target));
        out += "  speed [rpm]  torque [N m]  power [kW]  losses [kW]  housing [kW]  cooler duty [kW]\n";
        for (const auto& d : s.duty) {
            if (!solver::has_values(d.point.status)) {
                out += fmt::format("  {:11.1f}  {:12.6g}  {}\n", d.omega * kRpm, d.torque, solver::status_text(d.point));
                continue;
            }
            out += fmt::format("  {:11.1f}  {:12.6g}  {:10.4g}  {:11.4g}  {:12.4g}  {:16.4g}\n", d.omega * kRpm, d.torque,
                               d.omega * d.torque / 1e3, d.point.losses.total() / 1e3, d.housing_heat / 1e3, d.duty / 1e3);
        }
        return out;
    }
    out += fmt::format(", permissible oil temperature {:.1f} degC\n", celsius(s.options.oil_limit));
    out += "  speed [rpm]  thermal power limit\n";
    for (const auto& p : s.curve) {
        const double w = p.omega * kRpm;
        switch (p.status) {
            case rating::RatingStatus::limit: {
                std::string split;
                for (size_t i = 0; i < m.mechanisms.size() && i < p.point.losses.power.size(); ++i)
                    if (p.point.losses.power[i] > 0)
                        split += fmt::format("{}{} {:.3g} kW", split.empty() ? "" : ", ", m.mechanisms[i].name(),
                                             p.point.losses.power[i] / 1e3);
                out += fmt::format("  {:11.1f}  {:.4g} kW at {:.6g} N m (losses {:.3g} kW: {})\n", w,
                                   p.omega * p.torque / 1e3, p.torque, p.point.losses.total() / 1e3, split);
                break;
            }
            case rating::RatingStatus::no_limit_below:
                out += fmt::format("  {:11.1f}  no limit below {:.6g} N m ({:.4g} kW; oil {:.1f} degC there)\n", w, p.torque,
                                   p.omega * p.torque / 1e3, celsius(p.point.oil_temperature));
                break;
            case rating::RatingStatus::above_at_zero_torque:
                out += fmt::format("  {:11.1f}  above the limit even at zero torque (oil {:.1f} degC with no load)\n", w,
                                   celsius(p.point.oil_temperature));
                break;
            case rating::RatingStatus::out_of_range:
                out += fmt::format("  {:11.1f}  not found: out of range at {:.6g} N m ({})\n", w, p.torque, p.cause);
                break;
        }
    }
    return out;
}

std::string rating_json(const Case& k, const RatingStudy& s) {
    const auto& m = k.model;
    nlohmann::ordered_json j;
    j["case"] = m.name;
    j["ambient_C"] = json_number(celsius(s.options.ambient));
    auto split = [&](const solver::PointResult& r) {
        nlohmann::ordered_json o = nlohmann::ordered_json::object();
        for (size_t i = 0; i < m.mechanisms.size() && i < r.losses.power.size(); ++i)
            o[std::string(m.mechanisms[i].name())] = json_number(value_if(r, r.losses.power[i]));
        return o;
    };
    if (s.target > 0) {
        j["target_oil_temp_C"] = json_number(celsius(s.target));
        nlohmann::ordered_json rows = nlohmann::ordered_json::array();
        for (const auto& d : s.duty)
            rows.push_back({{"speed_in_rpm", json_number(d.omega * kRpm)},
                            {"torque_in_Nm", json_number(d.torque)},
                            {"status", solver::status_text(d.point)},
                            {"P_loss_W", json_number(value_if(d.point, d.point.losses.total()))},
                            {"losses_W", split(d.point)},
                            {"housing_heat_W", json_number(value_if(d.point, d.housing_heat))},
                            {"cooler_duty_W", json_number(value_if(d.point, d.duty))}});
        j["cooler_duty"] = rows;
        return json_line(j);
    }
    j["oil_limit_C"] = json_number(celsius(s.options.oil_limit));
    j["max_torque_Nm"] = json_number(s.options.max_torque);
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const auto& p : s.curve) {
        const auto& r = p.point;
        nlohmann::ordered_json o{{"speed_in_rpm", json_number(p.omega * kRpm)},
                                 {"rating", rating::to_string(p.status)},
                                 {"torque_in_Nm", json_number(p.torque)},
                                 {"power_in_W", json_number(p.omega * p.torque)},
                                 {"oil_temp_C", json_number(value_if(r, celsius(r.oil_temperature)))},
                                 {"P_loss_W", json_number(value_if(r, r.losses.total()))},
                                 {"losses_W", split(r)},
                                 {"housing_heat_W", json_number(value_if(r, p.housing_heat))},
                                 {"cooler_heat_W", json_number(value_if(r, p.cooler_heat))}};
        if (!p.cause.empty()) o["cause"] = p.cause;
        rows.push_back(std::move(o));
    }
    j["curve"] = rows;
    return json_line(j);
}

}  // namespace gearloss::io
