// Case loader: the `options:` block (the loss mechanisms' choices) and the `thermal:` block (heat path, docs/config.md).
#include "gearloss/case/config_internal.hpp"
#include "gearloss/mechanisms/mesh_friction_mechanism.hpp"

#include <fmt/format.h>

namespace gearloss::io::detail {

void load_options(const YamlNode& n, solver::Model& m) {
    n.allow_keys({"losses", "gear_loss_factor", "mesh_friction", "film_thermal_correction", "lambda_roughness",
                  "gear_friction"});
    // The loss mechanisms own these choices; `options:` is their spelling of earlier versions
    // (the mechanisms block, read after it, sets the same).
    if (auto l = n.get("losses")) {
        l->allow_keys({"mesh", "churning", "bearings", "seals"});
        for (const char* name : {"mesh", "churning", "bearings", "seals"})
            if (auto v = l->get(name)) m.mechanisms.at(name).set_enabled(v->as_bool());
    }
    auto& f = mesh::mesh_forms(m);
    if (auto v = n.get("gear_loss_factor"))
        f.loss_factor = v->as_enum<mesh::LossFactorModel>({{"ohlendorf", mesh::LossFactorModel::ohlendorf},
                                                          {"buckingham", mesh::LossFactorModel::buckingham},
                                                          {"wimmer", mesh::LossFactorModel::wimmer}});
    if (auto v = n.get("mesh_friction"))
        f.friction = v->as_enum<mesh::FrictionModel>({{"schlenk", mesh::FrictionModel::schlenk},
                                                      {"iso_6336_20", mesh::FrictionModel::iso_6336_20},
                                                      {"fernandes_mixed", mesh::FrictionModel::fernandes_mixed},
                                                      {"ehl_local", mesh::FrictionModel::ehl_local},
                                                      {"ehl_maxwell", mesh::FrictionModel::ehl_maxwell}});
    if (auto v = n.get("film_thermal_correction"))
        f.film_correction = v->as_enum<mesh::ThermalFilmCorrection>({{"gupta", mesh::ThermalFilmCorrection::gupta},
                                                                     {"simplified", mesh::ThermalFilmCorrection::simplified},
                                                                     {"none", mesh::ThermalFilmCorrection::none}});
    if (auto v = n.get("lambda_roughness"))
        f.lambda_roughness = v->as_enum<mesh::LambdaRoughness>({{"average_Ra", mesh::LambdaRoughness::average_Ra},
                                                                {"composite_Rq", mesh::LambdaRoughness::composite_Rq}});
    if (auto gf = n.get("gear_friction")) {
        gf->allow_keys({"mu_bl", "mu_ehl"});
        // Only the values written become the case's (the other stays the oil's or the default).
        // The order of the pair in force is the mechanism's check (validate), once the form is known.
        auto& mesh = m.mechanisms.at("mesh");
        auto read = [&](const char* key) {
            if (auto v = gf->get(key)) {
                const double x = v->as_number();
                if (!(x >= 0 && x < 1)) v->fail("must be in [0, 1)");
                mesh.set_parameter(key, x);
            }
        };
        read("mu_bl");
        read("mu_ehl");
    }
}

// thermal.cooler (gearloss/thermal/cooler.hpp): `duty`, or `oil_flow` with `inlet_temperature`
// (injection), or `ua` with `coolant_temperature` (and `oil_flow`: the effectiveness-NTU form;
// and `coolant_capacity_rate`: a counterflow exchanger with a coolant stream of that m c_p).
static thermal::Cooler load_cooler_kind(const YamlNode& c);
static thermal::Cooler load_cooler(const YamlNode& c) {
    c.allow_keys({"duty", "oil_flow", "inlet_temperature", "ua", "coolant_temperature", "coolant_capacity_rate",
                  "thermostat", "note"});
    thermal::Cooler k = load_cooler_kind(c);
    if (auto t = c.get("thermostat")) {
        t->allow_keys({"opens", "full"});
        k.valve_opens = t->at("opens").as_temperature();
        k.valve_full = t->at("full").as_temperature();
        if (!(k.valve_full > k.valve_opens)) t->at("full").fail("the valve must be fully open above the temperature it opens at");
    }
    return k;
}

static thermal::Cooler load_cooler_kind(const YamlNode& c) {
    thermal::Cooler k;
    const auto flow = units::make_dim(3, 0, -1, 0);
    const auto conductance = units::make_dim(2, 1, -3, -1);
    const auto temperature = [&](const char* key) {
        const double T = c.at(key).as_temperature();
        if (!(T > 0 && T < 1000)) c.at(key).fail("temperature outside 0..1000 K");
        return T;
    };
    const bool duty = c.has("duty"), flow_given = c.has("oil_flow"), ua = c.has("ua");
    if (duty) {
        if (flow_given || ua || c.has("inlet_temperature") || c.has("coolant_temperature") ||
            c.has("coolant_capacity_rate"))
            c.fail("give either 'duty' (fixed heat removal) or the cooler's data (oil_flow, inlet_temperature, ua, "
                   "coolant_temperature), not both");
        k.kind = thermal::Cooler::Kind::duty;
        k.duty = c.at("duty").as_quantity(units::dim::power, "20 kW");
        if (!(k.duty >= 0 && k.duty <= 1e8)) c.at("duty").fail("duty must be in 0..100 MW");
        return k;
    }
    if (flow_given) {
        k.oil_flow = c.positive_quantity("oil_flow", flow, "10 L/min");
        if (!(k.oil_flow <= 1.0)) c.at("oil_flow").fail("oil flow above 1 m^3/s");
    }
    if (ua) {
        if (c.has("inlet_temperature"))
            c.at("inlet_temperature").fail("with 'ua' give 'coolant_temperature' (the inlet follows from the exchanger)");
        k.ua = c.positive_quantity("ua", conductance, "500 W/K");
        if (!(k.ua <= 1e8)) c.at("ua").fail("UA above 100 MW/K");
        k.coolant_temperature = temperature("coolant_temperature");
        k.kind = flow_given ? thermal::Cooler::Kind::exchanger : thermal::Cooler::Kind::conductance;
        if (c.has("coolant_capacity_rate")) {
            if (!flow_given)
                c.at("coolant_capacity_rate").fail("'coolant_capacity_rate' needs 'oil_flow' (the oil's capacity rate)");
            k.coolant_capacity_rate = c.positive_quantity("coolant_capacity_rate", conductance, "3 kW/K");
            if (!(k.coolant_capacity_rate <= 1e8)) c.at("coolant_capacity_rate").fail("capacity rate above 100 MW/K");
        }
        return k;
    }
    if (c.has("coolant_capacity_rate")) c.at("coolant_capacity_rate").fail("'coolant_capacity_rate' needs 'ua'");
    if (!flow_given) c.fail("give 'duty', or 'oil_flow' with 'inlet_temperature', or 'ua' with 'coolant_temperature'");
    if (c.has("coolant_temperature")) c.at("coolant_temperature").fail("'coolant_temperature' needs 'ua'");
    k.inlet_temperature = temperature("inlet_temperature");
    k.kind = thermal::Cooler::Kind::injection;
    return k;
}

void load_thermal(const YamlNode& n, solver::ThermalSettings& t, std::vector<AssumedValue>* assumed) {
    n.allow_keys({"mode", "oil_temperature", "ambient", "heat_rejection", "max_oil_temperature", "heat_capacity",
                  "network", "cooler"});
    if (auto c = n.get("cooler")) t.cooler = load_cooler(*c);
    if (auto net = n.get("network")) {
        if (n.has("heat_capacity")) net->fail("give either 'heat_capacity' (one node) or 'network', not both");
        net->allow_keys({"oil", "housing", "oil_to_housing", "clutch_packs", "clutch_to_oil", "note"});
        auto& w = t.network;
        w.C_oil = net->positive_quantity("oil", units::dim::heat_capacity, "2 kJ/K");
        const auto conductance = units::make_dim(2, 1, -3, -1);
        if (net->has("housing")) {
            w.C_housing = net->positive_quantity("housing", units::dim::heat_capacity, "5 kJ/K");
            w.G_oil_housing = net->positive_quantity("oil_to_housing", conductance, "30 W/K");
        } else if (net->has("oil_to_housing")) {
            net->at("oil_to_housing").fail("'oil_to_housing' needs a 'housing' node");
        }
        if (net->has("clutch_packs")) {
            w.C_clutch = net->positive_quantity("clutch_packs", units::dim::heat_capacity, "1 kJ/K");
            w.G_clutch_oil = net->positive_quantity("clutch_to_oil", conductance, "40 W/K");
        } else if (net->has("clutch_to_oil")) {
            net->at("clutch_to_oil").fail("'clutch_to_oil' needs a 'clutch_packs' node");
        }
        t.heat_capacity = w.total_capacity();
    }
    if (auto hc = n.get("heat_capacity")) {
        t.heat_capacity = hc->as_quantity(units::dim::heat_capacity, "25 kJ/K");
        if (!(t.heat_capacity > 0)) hc->fail("heat capacity must be positive");
        t.network = {};
        t.network.C_oil = t.heat_capacity;
    }
    t.ambient = n.at("ambient").as_temperature();
    t.mode = n.has("mode") ? n.at("mode").as_enum<solver::ThermalMode>({{"stabilised", solver::ThermalMode::stabilised},
                                                                        {"stabilized", solver::ThermalMode::stabilised},
                                                                        {"fixed", solver::ThermalMode::fixed}})
                           : solver::ThermalMode::stabilised;
    if (!n.has("mode")) assume(assumed, n, "thermal.mode", "stabilised", "the oil temperature is solved from the heat balance");
    if (t.mode == solver::ThermalMode::fixed) t.oil_temperature = n.at("oil_temperature").as_temperature();
    else if (n.has("oil_temperature")) t.oil_temperature = n.at("oil_temperature").as_temperature();
    if (!n.has("max_oil_temperature") && t.mode == solver::ThermalMode::stabilised)
        assume(assumed, n, "thermal.max_oil_temperature", number_text(t.equilibrium.T_max - 273.15) + " degC",
               "search limit of the heat balance: no equilibrium is reported above it");
    if (auto m = n.get("max_oil_temperature")) {
        t.equilibrium.T_max = m->as_temperature();
        if (t.equilibrium.T_max <= t.ambient + 1) m->fail("must be above the ambient temperature");
    }
    if (t.mode == solver::ThermalMode::stabilised || n.has("heat_rejection")) {
        const YamlNode h = n.at("heat_rejection");
        h.allow_keys({"resistance", "reference_speed", "speed_exponent", "housing"});
        if (h.has("resistance") == h.has("housing"))
            h.fail("give exactly one of 'resistance' (equivalent thermal resistance) or 'housing' (surface model)");
        if (h.has("resistance")) {
            thermal::ThermalResistance r;
            r.R0 = h.positive_quantity("resistance", units::dim::thermal_resistance, "0.12 K/W");
            if (h.has("reference_speed")) {
                r.n_ref = h.positive_quantity("reference_speed", units::dim::angular_speed, "600 rpm");
                r.exponent = h.at("speed_exponent").as_number();
                if (!(r.exponent >= 0 && r.exponent < 2)) h.at("speed_exponent").fail("exponent outside 0..2");
            }
            t.rejection.model = r;
        } else {
            const YamlNode s = h.at("housing");
            s.allow_keys({"area", "emissivity", "height", "length", "air_speed"});
            thermal::HousingSurface hs;
            hs.area = s.positive_quantity("area", units::dim::area, "0.5 m^2");
            const auto unless_given = [&](const char* k, const std::string& value, const char* why) {
                if (!s.has(k)) assume(assumed, s, std::string("thermal.heat_rejection.housing.") + k, value, why);
            };
            unless_given("emissivity", number_text(hs.emissivity), "painted housing");
            unless_given("height", number_text(hs.height) + " m", "characteristic length of free convection");
            if (!s.has("length"))
                assume(assumed, s, "thermal.heat_rejection.housing.length",
                       s.has("height") ? "the height" : number_text(hs.height) + " m", "taken equal to the height");
            unless_given("air_speed", "0 m/s", "still air (free convection only)");
            if (s.has("emissivity")) {
                hs.emissivity = s.at("emissivity").as_number();
                if (!(hs.emissivity >= 0 && hs.emissivity <= 1)) s.at("emissivity").fail("emissivity must be in [0, 1]");
            }
            if (s.has("height")) hs.height = s.positive_quantity("height", units::dim::length, "0.3 m");
            hs.length = s.has("length") ? s.positive_quantity("length", units::dim::length, "0.3 m") : hs.height;
            if (s.has("air_speed")) {
                hs.air_speed = s.at("air_speed").as_quantity(units::dim::velocity, "2 m/s");
                if (hs.air_speed < 0) s.at("air_speed").fail("air speed cannot be negative");
            }
            t.rejection.model = hs;
        }
    }
}

// A setting that only one form reads (Parameter::used_by) matters once that form is selected:
// left at its nominal value there, by neither the case nor the oil, it is an assumption.
void note_mechanism_settings(Case& c) {
    std::erase_if(c.assumed, [](const AssumedValue& a) { return a.key.starts_with("mechanisms."); });
    const auto& m = c.model;
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        const auto& mech = m.mechanisms[i];
        if (!mech.enabled()) continue;
        for (const auto& p : mech.parameters()) {
            if (p.calibration || p.used_by.empty() || !mech.reads(m, p) ||
                mech.value_source(m, p.name) != losses::LossMechanism::Source::nominal)
                continue;
            const auto blank = p.example.find(' ');
            const std::string unit = p.dimension && blank != std::string::npos ? p.example.substr(blank) : "";
            // At the mechanism's block when the case has one, else the mechanisms block, else the
            // options block (the earlier spelling of the forms), else the file's first line.
            SourceLocation at = case_location(c, "mechanisms", "", std::string(mech.name()));
            if (!at.known()) at = case_location(c, "options");
            if (!at.known()) at = {c.file, 1, 1};
            c.assumed.push_back({fmt::format("mechanisms.{}.{}", mech.name(), p.name),
                                 number_text(mech.parameter(p.name)) + unit,
                                 fmt::format("{}: the default value, read by the selected {} form {}", p.description,
                                             mech.name(), p.used_by),
                                 located_at(at)});
        }
    }
}

}  // namespace gearloss::io::detail
