// Reading and writing the empirical terms of a calibration (empirical_config.hpp).
#include "gearloss/case/empirical_config.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <string>

#include "gearloss/units/units.hpp"

namespace gearloss::io {

namespace {

using losses::EmpiricalShape;
using losses::EmpiricalVariable;

const units::Dimension& dimension_of(EmpiricalVariable v) {
    switch (v) {
        case EmpiricalVariable::speed: return units::dim::angular_speed;
        case EmpiricalVariable::torque: return units::dim::torque;
        case EmpiricalVariable::oil_temperature: return units::dim::temperature;
        case EmpiricalVariable::viscosity: return units::dim::kinematic_viscosity;
    }
    return units::dim::none;
}

const char* example_of(EmpiricalVariable v) {
    switch (v) {
        case EmpiricalVariable::speed: return "1000 rpm";
        case EmpiricalVariable::torque: return "100 N*m";
        case EmpiricalVariable::oil_temperature: return "80 degC";
        case EmpiricalVariable::viscosity: return "100 cSt";
    }
    return "";
}

// A location of the variable (a threshold or a window edge): absolute for a temperature.
double location(const YamlNode& x, EmpiricalVariable v) {
    if (v == EmpiricalVariable::oil_temperature) return x.as_temperature();
    return x.as_quantity(dimension_of(v), example_of(v));
}

// A temperature difference ("10 K"): the unit parses as an absolute temperature, so the number
// and a unit without offset (K, mK) are read apart.
double temperature_difference(const YamlNode& x) {
    const std::string text = x.as_string();
    std::size_t u = 0;
    while (u < text.size() && (std::isdigit(static_cast<unsigned char>(text[u])) || text[u] == '.' || text[u] == ' ' ||
                               text[u] == '+' || text[u] == '-'))
        ++u;
    try {
        const auto f = units::parse_unit(text.substr(u));
        if (f.dim != units::dim::temperature || f.offset != 0 || u == 0) throw units::UnitError("");
        return std::stod(text.substr(0, u)) * f.scale;
    } catch (const std::exception&) {
        x.fail("expected a temperature difference in K, e.g. '10 K'");
    }
}

// A scale of the variable (a reference): positive; a temperature difference in K.
double scale(const YamlNode& x, EmpiricalVariable v) {
    const double s = v == EmpiricalVariable::oil_temperature ? temperature_difference(x)
                                                             : x.as_quantity(dimension_of(v), example_of(v));
    if (!(s > 0)) x.fail("must be positive");
    return s;
}

losses::EmpiricalFactor read_factor(const YamlNode& n) {
    if (!n.is_map()) n.fail("give a factor as a block, e.g. {variable: speed, shape: power, reference: 1000 rpm, exponent: 2}");
    losses::EmpiricalFactor f;
    f.variable = n.at("variable").as_enum<EmpiricalVariable>({{"speed", EmpiricalVariable::speed},
                                                               {"torque", EmpiricalVariable::torque},
                                                               {"oil_temperature", EmpiricalVariable::oil_temperature},
                                                               {"viscosity", EmpiricalVariable::viscosity}});
    f.shape = n.at("shape").as_enum<EmpiricalShape>({{"power", EmpiricalShape::power},
                                                      {"step", EmpiricalShape::step},
                                                      {"threshold", EmpiricalShape::threshold},
                                                      {"window", EmpiricalShape::window}});
    switch (f.shape) {
        case EmpiricalShape::power: {
            n.allow_keys({"variable", "shape", "reference", "exponent"});
            if (f.variable == EmpiricalVariable::oil_temperature)
                n.at("shape").fail("a power of the oil temperature has no physical reference; give a step, threshold or window");
            f.reference = scale(n.at("reference"), f.variable);
            const YamlNode e = n.at("exponent");
            f.exponent = e.as_number();
            if (!(f.exponent >= -6 && f.exponent <= 6)) e.fail("must be in [-6, 6]");
            break;
        }
        case EmpiricalShape::step:
        case EmpiricalShape::threshold: {
            if (f.shape == EmpiricalShape::step) n.allow_keys({"variable", "shape", "above", "below"});
            else n.allow_keys({"variable", "shape", "above", "below", "reference"});
            const auto above = n.get("above"), below = n.get("below");
            if (above.has_value() == below.has_value()) n.fail("give the threshold as either `above` or `below`");
            f.below = below.has_value();
            f.threshold = location(f.below ? *below : *above, f.variable);
            if (f.shape == EmpiricalShape::threshold) f.reference = scale(n.at("reference"), f.variable);
            break;
        }
        case EmpiricalShape::window: {
            n.allow_keys({"variable", "shape", "lower", "upper"});
            f.lower = location(n.at("lower"), f.variable);
            f.upper = location(n.at("upper"), f.variable);
            if (!(f.upper > f.lower)) n.at("upper").fail("must be above `lower`");
            break;
        }
    }
    return f;
}

// Numbers in the units of the case files.
std::string in_unit(double si, EmpiricalVariable v, bool is_location) {
    switch (v) {
        case EmpiricalVariable::speed: return fmt::format("{:.6g} rpm", si * 60 / (2 * M_PI));
        case EmpiricalVariable::torque: return fmt::format("{:.6g} N*m", si);
        case EmpiricalVariable::oil_temperature:
            return is_location ? fmt::format("{:.6g} degC", si - 273.15) : fmt::format("{:.6g} K", si);
        case EmpiricalVariable::viscosity: return fmt::format("{:.6g} cSt", si * 1e6);
    }
    return "";
}

}  // namespace

std::vector<losses::EmpiricalTerm> read_empirical_terms(const YamlNode& terms) {
    if (!terms.is_sequence()) terms.fail("give a list of terms, e.g. - {coefficient: 20 W, factors: [...]}");
    std::vector<losses::EmpiricalTerm> out;
    for (const auto& t : terms.items()) {
        if (!t.is_map()) t.fail("give a term as a block with `coefficient` and `factors`");
        t.allow_keys({"coefficient", "factors", "oil", "note"});
        losses::EmpiricalTerm term;
        const YamlNode c = t.at("coefficient");
        term.coefficient = c.as_quantity(units::dim::power, "20 W");
        if (!(std::abs(term.coefficient) <= 1e9)) c.fail("must be within +/- 1e9 W");
        if (auto f = t.get("factors")) {
            if (!f->is_sequence()) f->fail("give a list of factors (empty: a constant loss)");
            for (const auto& x : f->items()) term.factors.push_back(read_factor(x));
        }
        if (auto o = t.get("oil")) term.oil = o->as_string();
        out.push_back(std::move(term));
    }
    return out;
}

YAML::Node empirical_terms_yaml(const std::vector<losses::EmpiricalTerm>& terms) {
    YAML::Node list(YAML::NodeType::Sequence);
    for (const auto& t : terms) {
        YAML::Node n(YAML::NodeType::Map);
        n["coefficient"] = fmt::format("{:.6g} W", t.coefficient);
        YAML::Node fs(YAML::NodeType::Sequence);
        for (const auto& f : t.factors) {
            YAML::Node x(YAML::NodeType::Map);
            x.SetStyle(YAML::EmitterStyle::Flow);
            x["variable"] = std::string(losses::empirical_name(f.variable));
            x["shape"] = std::string(losses::empirical_name(f.shape));
            switch (f.shape) {
                case EmpiricalShape::power:
                    x["reference"] = in_unit(f.reference, f.variable, false);
                    x["exponent"] = fmt::format("{:.4g}", f.exponent);
                    break;
                case EmpiricalShape::step: x[f.below ? "below" : "above"] = in_unit(f.threshold, f.variable, true); break;
                case EmpiricalShape::threshold:
                    x[f.below ? "below" : "above"] = in_unit(f.threshold, f.variable, true);
                    x["reference"] = in_unit(f.reference, f.variable, false);
                    break;
                case EmpiricalShape::window:
                    x["lower"] = in_unit(f.lower, f.variable, true);
                    x["upper"] = in_unit(f.upper, f.variable, true);
                    break;
            }
            fs.push_back(x);
        }
        n["factors"] = fs;
        if (!t.oil.empty()) n["oil"] = t.oil;
        list.push_back(n);
    }
    return list;
}

}  // namespace gearloss::io
