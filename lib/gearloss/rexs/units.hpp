#pragma once
// REXS units (the unit list of the REXS data model, versions 1.0 to 1.6: "mm", "mum", "deg",
// "kg / dm^3", "mm^2 / s", "1 / min", "C", ...) converted to SI. Each attribute carries its unit,
// so a quantity is read in the unit the file states, whatever the attribute usually has.
#include <optional>
#include <string>

#include "gearloss/rexs/model.hpp"

namespace gearloss::rexs {

enum class Quantity { length, angle, temperature, kinematic_viscosity, density, pressure, rotational_speed, torque, force,
                      power, dimensionless };
const char* to_string(Quantity q);

// SI value of `value` given in `unit` for a quantity `q`; nullopt when the unit is not one of `q`.
std::optional<double> to_si(double value, const std::string& unit, Quantity q);

// The attribute as a quantity in SI (K for temperatures); nullopt when the component does not
// carry it; InputError naming the file, component and attribute when its unit is not of `q` or
// its value is not a finite number.
std::optional<double> quantity(const Model& m, const Component& c, const std::string& attribute, Quantity q);
double required_quantity(const Model& m, const Component& c, const std::string& attribute, Quantity q);

}  // namespace gearloss::rexs
