#include "gearloss/units/units.hpp"

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
    // What the expression names besides its dimension (radians are dimensionless, so "Hz" and
    // "rad/s" share the dimension 1/s, and a torque shares the dimension of an energy):
    int angle = 0;              // power of the angle units: rad, deg, rev, rpm 1; rad/s 1; rpm/rev 0
    bool rotation = false;      // Hz or a time unit other than the second (1/min, min^-1): revolutions per time
    bool energy = false;        // J, Wh, W and their multiples: an energy or a power, never a torque
    bool angle_named = false;   // an angle unit appears (rpm/rev: its angles cancel, but it names them)
    // Set by the parser from the names (not in the table):
    int angle_uses = 0;         // angle units and Hz counted with the magnitude of their powers (rpm^2/rpm: 3)
    bool frequency = false;     // Hz or kHz: a frequency, which counts revolutions (DIN 1301)
    bool force = false;         // N, kN, MN, Nm, kNm: a force is named (a torque needs one)
    bool percent = false;       // % or percent
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
        {"s", {1.0, time}}, {"ms", {1e-3, time}}, {"min", {60.0, time, 0, true}}, {"h", {3600.0, time, 0, true}},
        // temperature (as a unit inside expressions: kelvin; degC as a scale is a difference)
        {"K", {1.0, temperature}},
        // degC and degF inside an expression (kJ/degC, W/(m^2*degC)) are temperature differences:
        // a kelvin and 5/9 of a kelvin; alone they are absolute temperatures (parse_unit)
        {"degC", {1.0, temperature}}, {"°C", {1.0, temperature}}, {"degF", {5.0 / 9.0, temperature}},
        {"°F", {5.0 / 9.0, temperature}},
        // angle
        {"rad", {1.0, none, 1, false, false, true}}, {"deg", {pi / 180.0, none, 1, false, false, true}},
        {"rev", {2.0 * pi, none, 1, false, false, true}},
        // rotational speed; Hz is a frequency: as a rotational speed it counts revolutions (DIN 1301)
        {"rpm", {2.0 * pi / 60.0, angular_speed, 1, false, false, true}}, {"Hz", {1.0, angular_speed, 0, true}},
        {"kHz", {1e3, angular_speed, 0, true}},
        // force, torque, pressure, energy, power
        {"N", {1.0, force}}, {"Nm", {1.0, torque}}, {"kNm", {1e3, torque}}, {"kN", {1e3, force}}, {"MN", {1e6, force}},
        {"Pa", {1.0, pressure}}, {"kPa", {1e3, pressure}}, {"MPa", {1e6, pressure}}, {"GPa", {1e9, pressure}},
        {"bar", {1e5, pressure}},
        {"J", {1.0, energy, 0, false, true}}, {"kJ", {1e3, energy, 0, false, true}}, {"MJ", {1e6, energy, 0, false, true}},
        {"Wh", {3600.0, energy, 0, false, true}}, {"kWh", {3.6e6, energy, 0, false, true}},
        {"W", {1.0, power, 0, false, true}}, {"kW", {1e3, power, 0, false, true}}, {"MW", {1e6, power, 0, false, true}},
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

// Bounds of the parser (README "Reliability"): parentheses nest at most kMaxDepth deep
// (the parser recurses once per level), and no base dimension goes beyond kMaxExponent,
// so that neither the stack nor an int can overflow whatever the expression.
constexpr int kMaxDepth = 32;
constexpr int kMaxExponent = 24;
constexpr std::size_t kExcerpt = 60;

// At most kExcerpt characters of an input for a message, printable only ('?' for a
// control byte or a byte that is not UTF-8), "..." where it was cut.
std::string excerpt(std::string_view s) {
    std::string out;
    std::size_t chars = 0;
    for (std::size_t i = 0; i < s.size(); ++chars) {
        if (chars == kExcerpt) return out + "...";
        const unsigned char c = static_cast<unsigned char>(s[i]);
        std::size_t n = c < 0x80 ? 1 : c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
        bool ok = n > 0 && i + n <= s.size();
        for (std::size_t k = 1; ok && k < n; ++k) ok = (static_cast<unsigned char>(s[i + k]) & 0xC0) == 0x80;
        if (ok && n == 1) ok = c >= 0x20 && c != 0x7F;
        if (ok && n == 2) ok = !(c == 0xC2 && static_cast<unsigned char>(s[i + 1]) < 0xA0);  // C1 controls
        if (ok) out.append(s.substr(i, n));
        else out += '?';
        i += ok ? n : 1;
    }
    return out;
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

// The length in bytes of a product sign written as a dot at the start of `s`: U+00B7 MIDDLE DOT
// ("N·m", as the SI brochure prints a product of units) and U+22C5 DOT OPERATOR ("N⋅m"), in UTF-8;
// 0 when `s` starts with neither.
std::size_t product_dot(std::string_view s) {
    if (s.starts_with("\xC2\xB7")) return 2;
    if (s.starts_with("\xE2\x8B\x85")) return 3;
    return 0;
}

// Recursive-descent parser for unit expressions:
//   expr   := factor (('*' | '.' | '·' | '⋅' | ' ' | '/') factor)*
// A space between two units is a product too ("N m", "kg m^2"), as the SI writes it.
//   factor := atom ('^' int)?
//   atom   := name | '(' expr ')' | '1'
class UnitParser {
public:
    explicit UnitParser(std::string_view s) : s_(s) {}
    Unit parse() {
        Unit u = expr();
        skip_ws();
        if (pos_ != s_.size()) fail("unexpected '" + excerpt(s_.substr(pos_, 1)) + "'");
        return u;
    }

private:
    std::string_view s_;
    size_t pos_ = 0;
    int depth_ = 0;  // parentheses open at pos_

    [[noreturn]] void fail(const std::string& what) const {
        throw UnitError("cannot read unit '" + excerpt(s_) + "': " + what);
    }
    // u*v (sign +1) or u/v (sign -1): the scales, dimensions and angle powers combine, the names accumulate.
    static Unit combine(const Unit& u, const Unit& v, int sign) {
        return {sign > 0 ? u.scale * v.scale : u.scale / v.scale, add(u.d, v.d, sign), u.angle + sign * v.angle,
                u.rotation || v.rotation, u.energy || v.energy, u.angle_named || v.angle_named,
                u.angle_uses + v.angle_uses, u.frequency || v.frequency, u.force || v.force, u.percent || v.percent};
    }
    // The result of combining two units: every base exponent within +-kMaxExponent.
    Unit checked(const Unit& u) const {
        for (int e : u.d.e)
            if (e > kMaxExponent || e < -kMaxExponent) fail("exponent out of range");
        if (u.angle > kMaxExponent || u.angle < -kMaxExponent) fail("exponent out of range");
        return u;
    }
    // u^p: the scale, dimension and angle power raised; each angle unit counted |p| times.
    static Unit power(const Unit& u, int p) {
        return {std::pow(u.scale, p), mul(u.d, p), u.angle * p, u.rotation, u.energy, u.angle_named,
                u.angle_uses * std::abs(p), u.frequency, u.force, u.percent};
    }
    void skip_ws() {
        while (pos_ < s_.size() && s_[pos_] == ' ') ++pos_;
    }
    // A unit name or '(' starts at pos_: what may follow a space as the second factor of a product.
    bool at_atom() const {
        if (pos_ >= s_.size() || product_dot(s_.substr(pos_)) > 0) return false;
        const unsigned char c = static_cast<unsigned char>(s_[pos_]);
        return std::isalpha(c) || c == '(' || c >= 0x80;
    }
    Unit expr() {
        Unit u = factor();
        for (;;) {
            skip_ws();
            if (pos_ >= s_.size()) break;
            char c = s_[pos_];
            const size_t dot = product_dot(s_.substr(pos_));
            const bool after_space = pos_ > 0 && s_[pos_ - 1] == ' ';  // factor() skips the spaces after it
            if (c == '*' || c == '.' || dot > 0 || (after_space && at_atom())) {
                pos_ += dot > 0 ? dot : c == '*' || c == '.' ? 1 : 0;
                Unit v = factor();
                u = checked(combine(u, v, +1));
            } else if (c == '/') {
                ++pos_;
                Unit v = factor();
                u = checked(combine(u, v, -1));
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
            u = checked(power(u, p));
        } else {
            // "m2" / "m3" shorthand for squared / cubed units
            size_t start = pos_;
            while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
            if (pos_ > start) {
                if (pos_ - start > 2) fail("exponent out of range");
                int p = std::stoi(std::string(s_.substr(start, pos_ - start)));
                if (p > 6) fail("exponent out of range");
                u = checked(power(u, p));
            }
        }
        return u;
    }
    Unit atom() {
        skip_ws();
        if (pos_ >= s_.size()) fail("unit expected");
        if (s_[pos_] == '(') {
            if (depth_ == kMaxDepth)
                fail("unit nested too deeply (more than " + std::to_string(kMaxDepth) + " levels of parentheses)");
            ++pos_;
            ++depth_;
            Unit u = expr();
            skip_ws();
            if (pos_ >= s_.size() || s_[pos_] != ')') fail("missing ')'");
            ++pos_;
            --depth_;
            return u;
        }
        if (s_[pos_] == '1') {
            ++pos_;
            return {1.0, dim::none};
        }
        size_t start = pos_;
        // unit names: letters, µ (2 bytes in UTF-8) and '%'
        while (pos_ < s_.size() && product_dot(s_.substr(pos_)) == 0) {
            unsigned char c = static_cast<unsigned char>(s_[pos_]);
            if (std::isalpha(c) || c == '%' || c >= 0x80) ++pos_;
            else break;
        }
        if (start == pos_) fail("unit name expected at '" + excerpt(s_.substr(pos_)) + "'");
        std::string_view name = s_.substr(start, pos_ - start);
        auto it = unit_table().find(name);
        if (it == unit_table().end()) fail("unknown unit '" + excerpt(name) + "'");
        Unit u = it->second;
        u.frequency = name == "Hz" || name == "kHz";
        u.angle_uses = u.angle_named || u.frequency ? 1 : 0;
        u.force = name == "N" || name == "kN" || name == "MN" || name == "Nm" || name == "kNm";
        u.percent = name == "%" || name == "percent";
        return u;
    }
};

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

}  // namespace

std::string message_excerpt(std::string_view s) { return excerpt(s); }

UnitFactor parse_unit(std::string_view expr) {
    expr = trim(expr);
    // "C" alone is degrees Celsius as well (recordings headers write oil_temp_C; "70C" on the
    // command line), as docs/config.md states; inside an expression it is unknown (no coulomb).
    if (expr == "degC" || expr == "°C" || expr == "C") return {1.0, 273.15, dim::temperature, true};
    if (expr == "degF" || expr == "°F")
        return {5.0 / 9.0, 273.15 - 32.0 * 5.0 / 9.0, dim::temperature, true};
    if (expr == "K") return {1.0, 0.0, dim::temperature, true};
    if (expr.empty()) return {1.0, 0.0, dim::none, false};
    Unit u = UnitParser(expr).parse();
    // "20 mm*%" would be 0.2 mm: a percent inside a unit is a scale factor nobody means.
    if (u.percent && expr != "%" && expr != "percent")
        throw UnitError("cannot read unit '" + excerpt(expr) + "': '%' stands alone, for a plain ratio ('20 %'), not " +
                        "inside a unit");
    // "((km^6)^4)^6" is 1e144 m^144 before the exponent check stops it; a scale that
    // overflows or underflows would turn every value into inf, 0 or NaN.
    if (!std::isnormal(u.scale))
        throw UnitError("cannot read unit '" + excerpt(expr) + "': its scale to SI units is out of range");
    return {u.scale, 0.0, u.d, false, u.angle == 1, u.rotation, u.angle, u.angle_named, u.energy,
            u.angle_uses, u.frequency, u.force};
}

Quantity parse_quantity(std::string_view text) {
    std::string_view s = trim(text);
    if (s.empty()) throw UnitError("empty value");
    double v = 0.0;
    const char* b = s.data();
    const char* e = s.data() + s.size();
    auto [ptr, ec] = std::from_chars(b, e, v);
    if (ec == std::errc::result_out_of_range)
        throw UnitError("'" + excerpt(s) + "' is out of range (the number is not a finite double)");
    if (ec != std::errc() || ptr == b) throw UnitError("'" + excerpt(s) + "' does not start with a number");
    if (!std::isfinite(v)) throw UnitError("'" + excerpt(s) + "' is not a finite number");
    std::string_view rest = trim(std::string_view(ptr, static_cast<size_t>(e - ptr)));
    // "10/s" reads as 10 (1/s).
    const UnitFactor f = !rest.empty() && rest.front() == '/' ? parse_unit("1" + std::string(rest)) : parse_unit(rest);
    Quantity q = unit_quantity(f);
    q.value = v * f.scale + f.offset;
    // "1e308 km" is 1e311 m: inf, which would pass any "must be positive" check downstream.
    if (!std::isfinite(q.value)) throw UnitError("'" + excerpt(s) + "' is out of range (its value in SI units overflows)");
    q.unitless = rest.empty();
    return q;
}

Quantity unit_quantity(const UnitFactor& f) {
    Quantity q;
    q.value = f.scale + f.offset;
    q.dim = f.dim;
    q.absolute_temperature = f.affine;
    q.explicit_angle = f.angle;
    q.rotation = f.rotation;
    q.angle_power = f.angle_power;
    q.angle_named = f.angle_named;
    q.energy_named = f.energy_named;
    q.angle_uses = f.angle_uses;
    q.frequency_named = f.frequency_named;
    q.force_named = f.force_named;
    return q;
}

double as_rotational_speed(const Quantity& q, std::string_view text) {
    if (q.dim != dim::angular_speed) return q.value;
    // "1000 rpm/rev" is 1000/min with the angle divided out, "800 rpm^2/rpm" and "800 rev*rpm/rev"
    // repeat it, "10 Hz*rev" counts the revolutions twice (Hz counts them): no longer a speed of
    // rotation as written. One angle unit or one Hz, to the first power, and no other.
    if (q.angle_uses > 1 || (q.angle_named && q.angle_power != 1))
        throw UnitError("'" + excerpt(trim(text)) + "' is not a rotational speed: its angle units " +
                        (q.angle_named && q.angle_power == 0 ? "cancel"
                         : q.angle_uses > 1 ? "repeat (an angle unit, or Hz, which counts revolutions, written more than once)"
                                            : "do not reduce to one angle per time") +
                        "; write e.g. '1000 rpm', '1000 rev/min', '100 rad/s' or '10 Hz'");
    if (q.explicit_angle) return q.value;                     // rpm, rev/min, rad/s, deg/s
    if (q.rotation) return 2.0 * std::numbers::pi * q.value;  // Hz, 1/min, min^-1: revolutions per time
    // "1/s" is the angular velocity in rad/s to some and revolutions per second (DIN 1301) to others.
    throw UnitError("'" + excerpt(trim(text)) +
                    "' is ambiguous as a rotational speed: write 'rad/s' for an angular velocity, or 'Hz', 'rev/s', "
                    "'rpm' or '1/min' for revolutions per time");
}

double absolute_temperature(const Quantity& q, std::string_view text) {
    const std::string s = excerpt(trim(text));
    if (!q.absolute_temperature)
        throw UnitError("'" + s + "' is not a temperature" + (q.unitless ? " (no unit)" : "") +
                        "; write it in degC, degF or K alone, e.g. '40 degC' or '313.15 K'");
    if (q.value == 0.0) throw UnitError("'" + s + "' is absolute zero; an oil or air temperature is above 0 K (-273.15 degC)");
    if (!(q.value > 0.0)) throw UnitError("'" + s + "' is below absolute zero (0 K = -273.15 degC)");
    return q.value;
}

double checked_value(const Quantity& q, const Dimension& expected, std::string_view text, Kind kind) {
    const std::string s = excerpt(trim(text));
    if (q.dim != expected) {
        if (q.unitless)
            throw UnitError("'" + s + "' has no unit; a value of dimension " + to_string(expected) +
                            " needs one (a missing unit is an error, not a default)");
        throw UnitError("'" + s + "' has dimension " + to_string(q.dim) + ", expected " + to_string(expected));
    }
    if (q.absolute_temperature)
        throw UnitError("'" + s + "' is an absolute temperature; a temperature difference or rate was expected");
    if (kind == Kind::angle) {
        if (!q.angle_named)
            throw UnitError("'" + s + "' has no angle unit; write the angle with one, e.g. in deg or rad (a bare " +
                            "number is not taken as radians)");
        if (q.angle_power != 1 || q.angle_uses != 1)
            throw UnitError("'" + s + "' is not an angle: its angle units do not reduce to one angle written once");
        return q.value;
    }
    if (expected == dim::angular_speed) return as_rotational_speed(q, text);
    if (q.angle_named)
        throw UnitError("'" + s + "' is written with an angle unit; a value of dimension " + to_string(expected) +
                        " was expected, without one");
    // Hz counts revolutions (as rpm does): "20 Hz*mm*s" is no length, as "20 m*rpm" is none.
    if (q.frequency_named)
        throw UnitError("'" + s + "' is written with Hz, which counts revolutions per time; a value of dimension " +
                        to_string(expected) + " was expected, without one");
    // A torque is a force times a lever arm: its unit names a force (N, kN, MN, Nm, kNm) and no
    // energy or power. "Pa*m^3" and "kg*m^2/s^2" share its dimension but not its meaning.
    if (expected == dim::torque && q.energy_named)
        throw UnitError("'" + s + "' is an energy (J, Wh or W*s), not a torque; write a torque in N*m, Nm or kNm");
    if (expected == dim::torque && !q.force_named)
        throw UnitError("'" + s + "' does not name a force; a torque is a force times a length: write it in N*m, Nm, " +
                        "kNm, kN*m or N*mm");
    return q.value;
}

}  // namespace gearloss::units
