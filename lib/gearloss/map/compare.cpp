#include "gearloss/map/compare.hpp"

#include "gearloss/io/csv_format.hpp"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace gearloss::map {

namespace {
std::string num(double v) { return io::csv_number(v); }
}  // namespace

std::string compare_header(const std::string& name_a, const std::string& name_b) {
    // Oil names are titles (commas and quotes allowed): made safe as parts of column names,
    // and told apart when the two oils carry the same name.
    auto column_safe = [](std::string s) {
        for (char& c : s)
            if (c == ',' || c == '"') c = '_';
        return s;
    };
    std::string a = column_safe(name_a), b = column_safe(name_b);
    if (a == b) {
        a += "_A";
        b += "_B";
    }
    return fmt::format(
        "speed_in_rpm,torque_in_Nm,P_total_{0}_W,P_total_{1}_W,dP_loss_W,oil_temp_{0}_C,oil_temp_{1}_C,dT_oil_K,"
        "efficiency_{0},efficiency_{1},d_efficiency,status_{0},status_{1}\n",
        a, b);
}

std::string compare_row(const solver::PointResult& a, const solver::PointResult& b) {
    const bool oa = solver::has_values(a.status), ob = solver::has_values(b.status);
    const double Pa = oa ? a.losses.total() : NAN, Pb = ob ? b.losses.total() : NAN;
    const double Ta = oa ? a.oil_temperature - 273.15 : NAN, Tb = ob ? b.oil_temperature - 273.15 : NAN;
    const double ea = oa && a.has_efficiency ? a.efficiency : NAN, eb = ob && b.has_efficiency ? b.efficiency : NAN;
    return fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{}\n", num(a.speed_in * 30 / std::numbers::pi),
                       num(a.torque_in), num(Pa), num(Pb), num(Pb - Pa), num(Ta), num(Tb), num(Tb - Ta), num(ea), num(eb),
                       num(eb - ea), solver::status_text(a), solver::status_text(b));
}

}  // namespace gearloss::map
