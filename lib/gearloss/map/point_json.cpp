// `gearloss point --json` (docs/outputs.md).
#include "gearloss/io/json_text.hpp"
#include "gearloss/map/point_json.hpp"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/io/csv_read.hpp"
#include "gearloss/losses/loss_mechanism.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/map/output_metadata.hpp"

namespace gearloss::map {

using nlohmann::ordered_json;

namespace {
constexpr double kRpm = 30.0 / std::numbers::pi;
ordered_json number(double v) { return io::json_number(v); }
}  // namespace

ordered_json row_object(const std::string& header, const std::string& row) {
    const auto names = header_columns(header);
    const auto cells = header_columns(row);  // a row's cells, split the same way
    ordered_json o = ordered_json::object();
    for (size_t i = 0; i < names.size() && i < cells.size(); ++i) {
        double v = 0;
        if (cells[i].empty()) o[names[i]] = nullptr;
        else if (io::read_cell_number(cells[i], v) == io::CellNumber::number) o[names[i]] = v;
        else o[names[i]] = cells[i];
    }
    return o;
}

ordered_json point_json(const io::Case& c, const solver::PointResult& r, ordered_json metadata) {
    const auto& m = c.model;
    const bool values = solver::has_values(r.status);
    ordered_json j;
    j["metadata"] = std::move(metadata);
    j["input"] = {{"speed_rpm", number(r.speed_in * kRpm)}, {"torque_Nm", number(r.torque_in)},
                  {"power_W", number(r.power_in)}};
    j["status"] = solver::status_text(r);
    j["cause"] = r.cause.empty() ? ordered_json(nullptr) : ordered_json(r.cause);
    j["ambient_C"] = number(r.ambient - 273.15);
    if (!values) {  // no equilibrium or out of range: no numbers
        j["oil_temperature_C"] = nullptr;
        j["output"] = nullptr;
        j["mechanisms"] = ordered_json::array();
        j["P_total_W"] = nullptr;
        j["efficiency"] = nullptr;
        j["lambda_min"] = nullptr;
        j["row"] = nullptr;
        return j;
    }
    j["oil_temperature_C"] = number(r.oil_temperature - 273.15);
    const auto os = m.oil_state(r.oil_temperature);  // with the case's viscosity calibration
    j["oil_state"] = {{"nu_cSt", number(os.nu_cSt)},  {"rho_kg_m3", number(os.rho)},
                      {"eta_mPa_s", number(os.eta * 1e3)}, {"alpha_p_1_GPa", number(os.alpha_p * 1e9)},
                      {"k_W_mK", number(os.k)},         {"cp_J_kgK", number(os.cp)}};
    j["output"] = {{"speed_rpm", number(r.omega_out * kRpm)}, {"torque_Nm", number(r.torque_out)},
                   {"power_W", number(r.power_out)}};
    ordered_json mechanisms = ordered_json::array();
    const auto& L = r.losses;
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        const auto& mech = m.mechanisms[i];
        ordered_json e;
        e["name"] = std::string(mech.name());
        e["label"] = std::string(mech.label());
        e["column"] = std::string(mech.column());
        e["enabled"] = mech.enabled();
        e["P_W"] = number(i < L.power.size() ? L.power[i] : NAN);
        // Each component with the quantities of its --detail columns, under those column names
        // (as `map --detail` scales them: h_min in um).
        ordered_json components = ordered_json::array();
        if (i < L.detail.size()) {
            const auto names = mech.components(m);
            const auto quantities = mech.quantities();
            const auto& d = L.detail[i];
            for (size_t k = 0; k < names.size(); ++k) {
                ordered_json comp;
                comp["name"] = names[k];
                for (size_t q = 0; q < quantities.size() && q < d.quantities; ++q) {
                    if (quantities[q].column.empty() || (k + 1) * d.quantities > d.values.size()) continue;
                    std::string col = quantities[q].column;  // "P_churn_{}_W" with the component's name
                    if (const size_t at = col.find("{}"); at != std::string::npos) col.replace(at, 2, names[k]);
                    comp[col] = number(d.at(k, q) * quantities[q].csv_scale);
                }
                components.push_back(comp);
            }
        }
        e["components"] = components;
        mechanisms.push_back(e);
    }
    j["mechanisms"] = mechanisms;
    j["P_total_W"] = number(L.total());
    j["efficiency"] = r.has_efficiency ? number(r.efficiency) : ordered_json(nullptr);
    j["lambda_min"] = L.has_lambda ? number(L.lambda_min) : ordered_json(nullptr);
    j["thermal_residual_W"] = number(r.thermal_residual);
    // The point's row of `map --detail` (its CSV route), by column name.
    j["row"] = row_object(map::header_line(csv_header(m, true)), csv_row(m, r, true));
    return j;
}

}  // namespace gearloss::map
