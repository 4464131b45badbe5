#pragma once
// Quantities with units at the input/output boundary. Everything inside the
// library is SI; this module turns "3.5 mm", "800 rpm", "250 N*m", "40 degC",
// "112.35 cSt" into SI numbers and checks the dimension the caller expects.
#include <array>
#include <string>
#include <string_view>
#include "gearloss/core/errors.hpp"

namespace gearloss::units {

// Exponents of the SI base dimensions: length, mass, time, temperature.
struct Dimension {
    std::array<int, 4> e{0, 0, 0, 0};
    constexpr bool operator==(const Dimension&) const = default;
};

Dimension make_dim(int L, int M, int T, int Th);
std::string to_string(const Dimension& d);

// Named dimensions used by the loaders.
namespace dim {
extern const Dimension none, length, mass, time, temperature, angle, angular_speed, force, torque,
    pressure, power, area, volume, density, kinematic_viscosity, dynamic_viscosity, per_kelvin,
    per_pascal, velocity, thermal_resistance, heat_transfer_coefficient, thermal_conductivity,
    specific_heat, heat_capacity, energy;
}  // namespace dim

struct Quantity {
    double value = 0.0;  // SI
    Dimension dim;
    bool absolute_temperature = false;  // parsed from degC/degF/K alone
    bool explicit_angle = false;        // the unit carries one angle (rad, deg, rev, rpm, rad/s; not rpm/rev)
    bool rotation = false;              // the unit names a frequency (Hz) or a time other than the second (1/min)
    int angle_power = 0;                // power of the angle units in the expression (rad/s: 1, rad^2: 2, rpm/rev: 0)
    bool angle_named = false;           // an angle unit appears at all (rpm/rev: true, though the angles cancel)
    bool energy_named = false;          // an energy or power unit appears (J, Wh, W): the value is not a torque
    int angle_uses = 0;                 // angle units and Hz, each counted |power| times (rpm^2/rpm: 3; rpm: 1)
    bool frequency_named = false;       // Hz or kHz appears: counts revolutions, so only in a rotational speed
    bool force_named = false;           // N, kN, MN, Nm or kNm appears: a torque needs one
    bool unitless = false;              // a number alone
};

// Parses "<number> <unit expression>". Throws UnitError with a message that
// says what was wrong. A bare number parses as dimensionless.
Quantity parse_quantity(std::string_view text);

// Parses a unit expression alone ("N*m", "W/(m^2*K)", "1/K", "cSt").
// Temperature units degC/degF are accepted only as a whole expression and
// then `offset` receives the additive part (K = scale*x + offset).
struct UnitFactor {
    double scale = 1.0;
    double offset = 0.0;
    Dimension dim;
    bool affine = false;
    bool angle = false;     // see Quantity::explicit_angle
    bool rotation = false;  // see Quantity::rotation
    int angle_power = 0;    // see Quantity::angle_power
    bool angle_named = false;
    bool energy_named = false;
    int angle_uses = 0;          // see Quantity::angle_uses
    bool frequency_named = false;
    bool force_named = false;
};
UnitFactor parse_unit(std::string_view expr);
// One of the unit `f` as a quantity (its SI value f.scale + f.offset, with what the unit names), for
// a unit written without a number (a recordings header "torque_in_Nm") to go through checked_value.
Quantity unit_quantity(const UnitFactor& f);

// A quantity of dimension 1/s read as a rotational speed [rad/s]. An explicit
// angle (rpm, rev/min, rad/s, deg/s) is taken as written; a frequency with no
// angle (Hz, 1/min, min^-1, the DIN spellings of a speed of rotation) counts
// revolutions per time; a bare 1/s is ambiguous (rad/s or rev/s) and throws.
// Other dimensions: the SI value unchanged.
double as_rotational_speed(const Quantity& q, std::string_view text);

// What a value is meant to be beyond its dimension: radians are dimensionless and a
// torque has the dimension of an energy, so the dimension alone cannot tell them apart.
enum class Kind {
    plain,  // the dimension says it all, but: no angle unit and no Hz (both count angles); a torque
            // names a force (N*m, Nm, kNm, kN*m, N*mm) and no energy or power (J, Wh, W*s,
            // Pa*m^3 and kg*m^2/s^2 are refused)
    angle,  // an angle: dimensionless, but written with exactly one angle unit (rad, deg, rev)
};

// The SI value of `q` (written as `text`) where a quantity of dimension `expected` and kind
// `kind` is meant. Throws UnitError saying what was wrong (no unit, a wrong dimension, an
// absolute temperature where a difference is meant, an energy for a torque, an angle that
// is missing, repeated or cancelled, an ambiguous rotational speed); the caller adds where
// it was written and an example. Rotational speeds as as_rotational_speed.
double checked_value(const Quantity& q, const Dimension& expected, std::string_view text, Kind kind = Kind::plain);

// The absolute temperature [K] of `q` (written as `text`): written in degC, degF or K alone
// and above absolute zero; else UnitError saying which of the two it is not.
double absolute_temperature(const Quantity& q, std::string_view text);

// At most 60 characters of an input for a message, printable only ('?' for a control byte or a
// byte that is not UTF-8), "..." where it was cut.
std::string message_excerpt(std::string_view s);

// A unit that cannot be read; the caller knows where it was written and rethrows located.
struct UnitError : InputError {
    using InputError::InputError;
};

}  // namespace gearloss::units
