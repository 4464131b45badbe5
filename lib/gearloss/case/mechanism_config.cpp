#include "gearloss/case/mechanism_config.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "gearloss/io/csv_read.hpp"
#include "gearloss/case/empirical_config.hpp"
#include "gearloss/losses/loss_mechanism.hpp"
#include "gearloss/losses/registry.hpp"
#include "gearloss/units/units.hpp"

namespace gearloss::io {
namespace {

// Flat keys of earlier versions: key -> mechanism, parameter.
struct LegacyKey {
    const char* key;
    const char* mechanism;
    const char* parameter;
};
constexpr LegacyKey kLegacy[] = {{"windage", "windage", "empirical_W_at_1000rpm"},
                                 {"churning_factor", "churning", "factor"},
                                 {"bearing_drag_f0", "bearings", "drag_f0"},
                                 {"seal_factor", "seals", "factor"},
                                 {"mesh_friction_factor", "mesh", "friction_factor"},
                                 {"auxiliary", "auxiliary", "power"}};

double read_value(const YamlNode& x, const losses::Parameter& p) {
    const double v = p.dimension ? x.as_quantity(*p.dimension, p.example.c_str()) : x.as_number();
    if (!(v >= p.lower && v <= p.upper)) x.fail(fmt::format("must be in [{}, {}]", p.lower, p.upper));
    return v;
}

void set_parameter(const YamlNode& x, losses::LossMechanism& mech, const std::string& key, bool calibration) {
    for (const auto& p : mech.parameters())
        if (p.name == key) {
            if (p.calibration != calibration)
                x.fail(fmt::format("'{}' of mechanism '{}' belongs under '{}:'", key, mech.name(),
                                   p.calibration ? "calibration" : "mechanisms"));
            mech.set_parameter(key, read_value(x, p));
            return;
        }
    x.fail(fmt::format("mechanism '{}' has no parameter '{}'", mech.name(), key));
}

std::string allowed_keys(const losses::LossMechanism& mech, const solver::Model& m, bool calibration) {
    std::string s;
    auto add = [&](const std::string& k) { s += (s.empty() ? "" : ", ") + k; };
    if (!calibration)
        for (const auto& a : mech.forms(m)) add(a.axis);
    for (const auto& p : mech.parameters())
        if (p.calibration == calibration) add(p.name);
    return s.empty() ? "(none)" : s;
}

}  // namespace

void load_calibration(const YamlNode& n, solver::Model& m) {
    auto& c = m.calibration;
    for (const auto& [key, x] : n.entries()) {
        if (key == "note") continue;
        // The node is passed in: a lambda capturing a structured binding needs clang >= 16.
        auto factor = [](const YamlNode& node, double& v, double lo, double hi) {
            v = node.as_number();
            if (!(v >= lo && v <= hi)) node.fail(fmt::format("must be in [{}, {}]", lo, hi));
        };
        if (key == "viscosity_factor") { factor(x, c.viscosity_factor, 0.05, 20); continue; }
        if (key == "heat_rejection_factor") { factor(x, c.heat_rejection_factor, 0.05, 20); continue; }
        if (key == "cooling_per_1000rpm") { factor(x, c.cooling_per_1000rpm, -0.95, 50); continue; }
        if (key == "cooling_speed_exponent") { factor(x, c.cooling_speed_exponent, 0.2, 2); continue; }
        if (key == "heat_rejection_rise_slope") { factor(x, c.heat_rejection_rise_slope, -0.2, 0.2); continue; }
        if (auto* mech = m.mechanisms.find(key); mech && x.is_map()) {
            for (const auto& [pk, px] : x.entries()) {
                if (pk == "note") continue;
                // The empirical loss is a list of terms, not parameters.
                if (auto* e = dynamic_cast<losses::EmpiricalMechanism*>(mech); e && pk == "terms") {
                    e->set_terms(read_empirical_terms(px));
                    continue;
                }
                // The empirical drag was churning's before windage became a mechanism.
                if (key == "churning" && pk == "windage_W_at_1000rpm") {
                    set_parameter(px, m.mechanisms.at("windage"), "empirical_W_at_1000rpm", true);
                    continue;
                }
                set_parameter(px, *mech, pk, true);
            }
            continue;
        }
        bool legacy = false;
        for (const auto& l : kLegacy)
            if (key == l.key && x.is_scalar()) {
                set_parameter(x, m.mechanisms.at(l.mechanism), l.parameter, true);
                legacy = true;
            }
        if (legacy) continue;
        if (m.mechanisms.find(key)) x.fail(fmt::format("give the calibration of '{}' as a block, e.g. {}: {{{}}}", key, key,
                                                       allowed_keys(m.mechanisms.at(key), m, true)));
        x.fail(fmt::format("unknown calibration key '{}'; give viscosity_factor, heat_rejection_factor, "
                           "cooling_per_1000rpm, cooling_speed_exponent, heat_rejection_rise_slope or a block per loss mechanism ({})",
                           excerpt(key), losses::registered_names()));
    }
}

void load_mechanism_settings(const YamlNode& n, solver::Model& m) {
    for (const auto& [name, block] : n.entries()) {
        if (name == "note") continue;
        auto* mech = m.mechanisms.find(name);
        if (!mech) block.fail(fmt::format("no loss mechanism '{}' (registered: {})", excerpt(name), losses::registered_names()));
        if (!block.is_map()) block.fail(fmt::format("give a block of settings, e.g. {}: {{{}}}", name, allowed_keys(*mech, m, false)));
        for (const auto& [key, x] : block.entries()) {
            if (key == "note") continue;
            bool is_form = false;
            for (const auto& a : mech->forms(m))
                if (a.axis == key) {
                    is_form = true;
                    std::string list;
                    for (const auto& f : a.forms) list += (list.empty() ? "" : ", ") + f;
                    const std::string v = x.as_string();
                    if (std::find(a.forms.begin(), a.forms.end(), v) == a.forms.end())
                        x.fail(fmt::format("'{}' is not one of: {}", excerpt(v), list));
                    mech->set_form(m, key, v);
                }
            if (is_form) continue;
            bool known = false;
            for (const auto& p : mech->parameters()) known = known || p.name == key;
            if (!known) x.fail(fmt::format("mechanism '{}' has no setting '{}' (settings: {})", name, excerpt(key),
                                           allowed_keys(*mech, m, false)));
            set_parameter(x, *mech, key, false);
        }
    }
}

std::vector<CalibrationEntry> calibration_entries(const losses::MechanismSet& mechanisms, const solver::Calibration& c) {
    std::vector<CalibrationEntry> out;
    for (size_t i = 0; i < mechanisms.size(); ++i) {
        const auto& mech = mechanisms[i];
        for (const auto& p : mech.parameters()) {
            if (!p.calibration) continue;
            const double v = mech.parameter(p.name);
            if (v == p.nominal) continue;
            out.push_back({std::string(mech.name()), p.name, v, p.dimension == &units::dim::power ? "W" : ""});
        }
    }
    if (c.viscosity_factor != 1) out.push_back({"", "viscosity_factor", c.viscosity_factor, ""});
    if (c.heat_rejection_factor != 1) out.push_back({"", "heat_rejection_factor", c.heat_rejection_factor, ""});
    if (c.cooling_per_1000rpm != 0) out.push_back({"", "cooling_per_1000rpm", c.cooling_per_1000rpm, ""});
    if (c.cooling_per_1000rpm != 0 && c.cooling_speed_exponent != 1)
        out.push_back({"", "cooling_speed_exponent", c.cooling_speed_exponent, ""});
    if (c.heat_rejection_rise_slope != 0)
        out.push_back({"", "heat_rejection_rise_slope", c.heat_rejection_rise_slope, ""});
    return out;
}

}  // namespace gearloss::io
