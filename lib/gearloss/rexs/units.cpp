// REXS units to SI (units.hpp). The unit names are those of the REXS data model's unit list
// (FVA REXS schema, versions 1.0 to 1.6); "°" and "deg" both occur for angles.
#include "gearloss/rexs/units.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace gearloss::rexs {

const char* to_string(Quantity q) {
    switch (q) {
        case Quantity::length: return "a length";
        case Quantity::angle: return "an angle";
        case Quantity::temperature: return "a temperature";
        case Quantity::kinematic_viscosity: return "a kinematic viscosity";
        case Quantity::density: return "a density";
        case Quantity::pressure: return "a stress or pressure";
        case Quantity::rotational_speed: return "a rotational speed";
        case Quantity::torque: return "a torque";
        case Quantity::force: return "a force";
        case Quantity::power: return "a power";
        case Quantity::dimensionless: return "a dimensionless number";
    }
    return "a quantity";
}

namespace {

struct UnitRow {
    const char* unit;
    Quantity q;
    double factor;  // SI = factor * value (+ offset)
    double offset;
};

constexpr double kPi = std::numbers::pi;
constexpr std::array<UnitRow, 25> kUnits{{
    {"mm", Quantity::length, 1e-3, 0},
    {"mum", Quantity::length, 1e-6, 0},
    {"m", Quantity::length, 1.0, 0},
    {"deg", Quantity::angle, kPi / 180, 0},
    {"\u00b0", Quantity::angle, kPi / 180, 0},
    {"rad", Quantity::angle, 1.0, 0},
    {"C", Quantity::temperature, 1.0, 273.15},
    {"K", Quantity::temperature, 1.0, 0},
    {"mm^2 / s", Quantity::kinematic_viscosity, 1e-6, 0},
    {"kg / dm^3", Quantity::density, 1e3, 0},
    {"kg / m^3", Quantity::density, 1.0, 0},
    {"N / mm^2", Quantity::pressure, 1e6, 0},
    {"MPa", Quantity::pressure, 1e6, 0},
    {"Pa", Quantity::pressure, 1.0, 0},
    {"1 / min", Quantity::rotational_speed, 2 * kPi / 60, 0},
    {"rad / s", Quantity::rotational_speed, 1.0, 0},
    {"N m", Quantity::torque, 1.0, 0},
    {"N mm", Quantity::torque, 1e-3, 0},
    {"N", Quantity::force, 1.0, 0},
    {"kN", Quantity::force, 1e3, 0},
    {"W", Quantity::power, 1.0, 0},
    {"kW", Quantity::power, 1e3, 0},
    {"", Quantity::dimensionless, 1.0, 0},
    {"none", Quantity::dimensionless, 1.0, 0},
    {"%", Quantity::dimensionless, 1e-2, 0},
}};

}  // namespace

std::optional<double> to_si(double value, const std::string& unit, Quantity q) {
    for (const auto& r : kUnits)
        if (r.q == q && unit == r.unit) return value * r.factor + r.offset;
    return std::nullopt;
}

std::optional<double> quantity(const Model& m, const Component& c, const std::string& attribute, Quantity q) {
    const Attribute* a = c.find(attribute);
    if (!a) return std::nullopt;
    const auto v = number(m, c, attribute);
    if (!v) return std::nullopt;
    const auto si = to_si(*v, a->unit, q);
    if (!si) m.fail(c, *a, "unit '" + a->unit + "' is not the unit of " + to_string(q) + " gearloss reads");
    // No quantity of a gearbox reaches 1e13 in SI units (steel's modulus is 2.1e11 Pa): a larger
    // value is corrupt, and would overflow when written back in mm or um.
    if (!(std::abs(*si) <= 1e13))
        m.fail(c, *a, "'" + a->text.substr(0, 40) + " " + a->unit + "' is out of the range of " + to_string(q));
    return si;
}

double required_quantity(const Model& m, const Component& c, const std::string& attribute, Quantity q) {
    const auto v = quantity(m, c, attribute, q);
    if (!v) m.fail(c, "attribute '" + attribute + "' is missing (" + to_string(q) + " gearloss needs)");
    return *v;
}

}  // namespace gearloss::rexs
