#include "units/units.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <numbers>

namespace gearloss::units {

Dimension make_dim(int L, int M, int T, int Th) { return Dimension{{L, M, T, Th}}; }

std::string to_string(const Dimension& d) {
    static const char* names[4] = {"m", "kg", "s", "K"};
    std::string num, den;
    for (int i = 0; i < 4; ++i) {
        int p = d.e[i];
        if (p == 0) continue;
        std::string& s = p > 0 ? num : den;
        if (!s.empty()) s += "*";
        s += names[i];
        if (std::abs(p) != 1) s += "^" + std::to_string(std::abs(p));
    }
    if (num.empty() && den.empty()) return "dimensionless";
    if (num.empty()) num = "1";
    return den.empty() ? num : num + "/" + (den.find('*') != std::string::npos ? "(" + den + ")" : den);
}

namespace dim {
const Dimension none = make_dim(0, 0, 0, 0);
const Dimension length = make_dim(1, 0, 0, 0);
const Dimension mass = make_dim(0, 1, 0, 0);
const Dimension time = make_dim(0, 0, 1, 0);
const Dimension temperature = make_dim(0, 0, 0, 1);
const Dimension angle = none;  // radians are dimensionless
const Dimension angular_speed = make_dim(0, 0, -1, 0);
const Dimension force = make_dim(1, 1, -2, 0);
const Dimension torque = make_dim(2, 1, -2, 0);
const Dimension energy = torque;
const Dimension pressure = make_dim(-1, 1, -2, 0);
const Dimension power = make_dim(2, 1, -3, 0);
const Dimension area = make_dim(2, 0, 0, 0);
const Dimension volume = make_dim(3, 0, 0, 0);
const Dimension density = make_dim(-3, 1, 0, 0);
const Dimension kinematic_viscosity = make_dim(2, 0, -1, 0);
const Dimension dynamic_viscosity = make_dim(-1, 1, -1, 0);
const Dimension per_kelvin = make_dim(0, 0, 0, -1);
const Dimension per_pascal = make_dim(1, -1, 2, 0);
const Dimension velocity = make_dim(1, 0, -1, 0);
const Dimension thermal_resistance = make_dim(-2, -1, 3, 1);
const Dimension heat_transfer_coefficient = make_dim(0, 1, -3, -1);
const Dimension thermal_conductivity = make_dim(1, 1, -3, -1);
const Dimension specific_heat = make_dim(2, 0, -2, -1);
const Dimension heat_capacity = make_dim(2, 1, -2, -1);
}  // namespace dim

namespace {

struct Unit {
    double scale;
    Dimension d;
    // What the expression names besides its dimension, for rotational speeds
    // (radians are dimensionless, so "Hz" and "rad/s" share the dimension 1/s):
    bool angle = false;      // rad, deg, rev, rpm: the angle is explicit
    bool rotation = false;   // Hz or a time unit other than the second (1/min, min^-1): revolutions per time
};

const std::map<std::string, Unit, std::less<>>& unit_table() {
    using namespace dim;
    constexpr double pi = std::numbers::pi;
    static const std::map<std::string, Unit, std::less<>> t = {
        // length
        {"m", {1.0, length}}, {"mm", {1e-3, length}}, {"cm", {1e-2, length}}, {"um", {1e-6, length}},
        {"µm", {1e-6, length}}, {"nm", {1e-9, length}}, {"km", {1e3, length}}, {"in", {0.0254, length}},
        {"ft", {0.3048, length}},
        // mass
        {"kg", {1.0, mass}}, {"g", {1e-3, mass}}, {"t", {1e3, mass}},
        // time
        {"s", {1.0, time}}, {"ms", {1e-3, time}}, {"min", {60.0, time, false, true}}, {"h", {3600.0, time, false, true}},
        // temperature (as a unit inside expressions: kelvin; degC as a scale is a difference)
        {"K", {1.0, temperature}},
        // angle
        {"rad", {1.0, none, true}}, {"deg", {pi / 180.0, none, true}}, {"rev", {2.0 * pi, none, true}},
        // rotational speed; Hz is a frequency: as a rotational speed it counts revolutions (DIN 1301)
        {"rpm", {2.0 * pi / 60.0, angular_speed, true}}, {"Hz", {1.0, angular_speed, false, true}},
        {"kHz", {1e3, angular_speed, false, true}},
        // force, torque, pressure, energy, power
        {"N", {1.0, force}}, {"Nm", {1.0, torque}}, {"kNm", {1e3, torque}}, {"kN", {1e3, force}}, {"MN", {1e6, force}},
        {"Pa", {1.0, pressure}}, {"kPa", {1e3, pressure}}, {"MPa", {1e6, pressure}}, {"GPa", {1e9, pressure}},
        {"bar", {1e5, pressure}},
        {"J", {1.0, energy}}, {"kJ", {1e3, energy}}, {"MJ", {1e6, energy}}, {"Wh", {3600.0, energy}}, {"kWh", {3.6e6, energy}},
        {"W", {1.0, power}}, {"kW", {1e3, power}}, {"MW", {1e6, power}},
        // volume
        {"L", {1e-3, volume}}, {"l", {1e-3, volume}}, {"mL", {1e-6, volume}}, {"ml", {1e-6, volume}},
        // viscosity
        {"St", {1e-4, kinematic_viscosity}}, {"cSt", {1e-6, kinematic_viscosity}},
        {"P", {0.1, dynamic_viscosity}}, {"cP", {1e-3, dynamic_viscosity}},
        // dimensionless
        {"percent", {0.01, none}}, {"%", {0.01, none}}, {"1", {1.0, none}},
    };
    return t;
}

Dimension add(const Dimension& a, const Dimension& b, int sign) {
    Dimension r;
    for (int i = 0; i < 4; ++i) r.e[i] = a.e[i] + sign * b.e[i];
    return r;
}
Dimension mul(const Dimension& a, int p) {
    Dimension r;
    for (int i = 0; i < 4; ++i) r.e[i] = a.e[i] * p;
    return r;
}

// Recursive-descent parser for unit expressions:
//   expr   := factor (('*' | '/' | '.') factor)*
//   factor := atom ('^' int)?
//   atom   := name | '(' expr ')' | '1'
class UnitParser {
public:
    explicit UnitParser(std::string_view s) : s_(s) {}
    Unit parse() {
        Unit u = expr();
        skip_ws();
        if (pos_ != s_.size()) fail("unexpected '" + std::string(s_.substr(pos_, 1)) + "'");
        return u;
    }

private:
    std::string_view s_;
    size_t pos_ = 0;

    [[noreturn]] void fail(const std::string& what) const {
        throw UnitError("cannot read unit '" + std::string(s_) + "': " + what);
    }
    void skip_ws() {
        while (pos_ < s_.size() && s_[pos_] == ' ') ++pos_;
    }
    Unit expr() {
        Unit u = factor();
        for (;;) {
            skip_ws();
            if (pos_ >= s_.size()) break;
            char c = s_[pos_];
            if (c == '*' || c == '.') {
                ++pos_;
                Unit v = factor();
                u = {u.scale * v.scale, add(u.d, v.d, +1), u.angle || v.angle, u.rotation || v.rotation};
            } else if (c == '/') {
                ++pos_;
                Unit v = factor();
                u = {u.scale / v.scale, add(u.d, v.d, -1), u.angle || v.angle, u.rotation || v.rotation};
            } else {
                break;
            }
        }
        return u;
    }
    Unit factor() {
        Unit u = atom();
        skip_ws();
        if (pos_ < s_.size() && s_[pos_] == '^') {
            ++pos_;
            skip_ws();
            int sign = 1;
            if (pos_ < s_.size() && (s_[pos_] == '-' || s_[pos_] == '+')) {
                sign = s_[pos_] == '-' ? -1 : 1;
                ++pos_;
            }
            size_t start = pos_;
            while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
            if (start == pos_) fail("exponent after '^' must be an integer");
            if (pos_ - start > 2) fail("exponent out of range");
            int p = std::stoi(std::string(s_.substr(start, pos_ - start))) * sign;
            if (p > 6 || p < -6) fail("exponent out of range");
            u = {std::pow(u.scale, p), mul(u.d, p), u.angle, u.rotation};
        } else {
            // "m2" / "m3" shorthand for squared / cubed units
            size_t start = pos_;
            while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
            if (pos_ > start) {
                if (pos_ - start > 2) fail("exponent out of range");
                int p = std::stoi(std::string(s_.substr(start, pos_ - start)));
                if (p > 6) fail("exponent out of range");
                u = {std::pow(u.scale, p), mul(u.d, p), u.angle, u.rotation};
            }
        }
        return u;
    }
    Unit atom() {
        skip_ws();
        if (pos_ >= s_.size()) fail("unit expected");
        if (s_[pos_] == '(') {
            ++pos_;
            Unit u = expr();
            skip_ws();
            if (pos_ >= s_.size() || s_[pos_] != ')') fail("missing ')'");
            ++pos_;
            return u;
        }
        if (s_[pos_] == '1') {
            ++pos_;
            return {1.0, dim::none};
        }
        size_t start = pos_;
        // unit names: letters, µ (2 bytes in UTF-8) and '%'
        while (pos_ < s_.size()) {
            unsigned char c = static_cast<unsigned char>(s_[pos_]);
            if (std::isalpha(c) || c == '%' || c >= 0x80) ++pos_;
            else break;
        }
        if (start == pos_) fail("unit name expected at '" + std::string(s_.substr(pos_)) + "'");
        std::string_view name = s_.substr(start, pos_ - start);
        auto it = unit_table().find(name);
        if (it == unit_table().end()) fail("unknown unit '" + std::string(name) + "'");
        return it->second;
    }
};

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

}  // namespace

UnitFactor parse_unit(std::string_view expr) {
    expr = trim(expr);
    if (expr == "degC" || expr == "°C" || expr == "C")
        return {1.0, 273.15, dim::temperature, true};
    if (expr == "degF" || expr == "°F")
        return {5.0 / 9.0, 273.15 - 32.0 * 5.0 / 9.0, dim::temperature, true};
    if (expr == "K") return {1.0, 0.0, dim::temperature, true};
    if (expr.empty()) return {1.0, 0.0, dim::none, false};
    Unit u = UnitParser(expr).parse();
    return {u.scale, 0.0, u.d, false, u.angle, u.rotation};
}

Quantity parse_quantity(std::string_view text) {
    std::string_view s = trim(text);
    if (s.empty()) throw UnitError("empty value");
    double v = 0.0;
    const char* b = s.data();
    const char* e = s.data() + s.size();
    auto [ptr, ec] = std::from_chars(b, e, v);
    if (ec != std::errc() || ptr == b) throw UnitError("'" + std::string(s) + "' does not start with a number");
    if (!std::isfinite(v)) throw UnitError("'" + std::string(s) + "' is not a finite number");
    std::string_view rest = trim(std::string_view(ptr, static_cast<size_t>(e - ptr)));
    // "10/s" reads as 10 (1/s).
    const UnitFactor f = !rest.empty() && rest.front() == '/' ? parse_unit("1" + std::string(rest)) : parse_unit(rest);
    Quantity q;
    q.value = v * f.scale + f.offset;
    q.dim = f.dim;
    q.absolute_temperature = f.affine;
    q.explicit_angle = f.angle;
    q.rotation = f.rotation;
    return q;
}

double as_rotational_speed(const Quantity& q, std::string_view text) {
    if (q.dim != dim::angular_speed) return q.value;
    if (q.explicit_angle) return q.value;                     // rpm, rev/min, rad/s, deg/s
    if (q.rotation) return 2.0 * std::numbers::pi * q.value;  // Hz, 1/min, min^-1: revolutions per time
    // "1/s" is the angular velocity in rad/s to some and revolutions per second (DIN 1301) to others.
    throw UnitError("'" + std::string(trim(text)) +
                    "' is ambiguous as a rotational speed: write 'rad/s' for an angular velocity, or 'Hz', 'rev/s', "
                    "'rpm' or '1/min' for revolutions per time");
}



}  // namespace gearloss::units
