#include "gearloss/torque_converter/torque_converter.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>

namespace gearloss::torque_converter {

double hi_viscosity_parameter(double nu_cSt, double head_m, double flow_m3s, double speed_rad_s) {
    const double H_ft = head_m / 0.3048;
    const double Q_gpm = flow_m3s / 6.30901964e-5;  // US gallon per minute
    const double N_rpm = std::abs(speed_rad_s) * 30.0 / 3.14159265358979323846;
    if (!(nu_cSt > 0 && H_ft > 0 && Q_gpm > 0 && N_rpm > 0)) return 0.0;
    return 16.5 * std::sqrt(nu_cSt) * std::pow(H_ft, 0.0625) / (std::pow(Q_gpm, 0.375) * std::pow(N_rpm, 0.25));
}

double hi_efficiency_correction(double B) {
    if (!(B > 1.0)) return 1.0;
    const double lnB = std::log(std::min(B, 40.0));
    return std::exp(-0.0547 * std::exp(0.69 * lnB) * lnB);  // B^(-0.0547 B^0.69)
}

namespace {
double interp(const std::vector<double>& x, const std::vector<double>& y, double v) {
    if (v <= x.front()) return y.front();
    if (v >= x.back()) return y.back();
    const size_t i = static_cast<size_t>(std::upper_bound(x.begin(), x.end(), v) - x.begin());
    const double t = (v - x[i - 1]) / (x[i] - x[i - 1]);
    return y[i - 1] + t * (y[i] - y[i - 1]);
}
}  // namespace

TcState operate(const TorqueConverter& tc, double turbine_speed, double turbine_torque, double idle_speed,
                double nu_cSt, bool lockup) {
    TcState s;
    s.turbine_speed = std::abs(turbine_speed);
    s.turbine_torque = turbine_torque;
    const auto& c = tc.curve;
    if (lockup) {
        s.locked = true;
        s.pump_speed = s.turbine_speed;
        s.pump_torque = turbine_torque;
        return s;
    }
    const double SR_max = c.speed_ratio.back();
    if (turbine_torque <= 0.0 && s.turbine_speed >= idle_speed * SR_max) {
        // Overrun at speed: coupled, the small slip loss neglected.
        s.pump_speed = s.turbine_speed;
        s.pump_torque = turbine_torque;
        return s;
    }
    // B = B_1rpm N^-0.25: the speed-independent part once per call (the root solve varies N).
    const double B_1rpm = tc.impeller_head > 0
                              ? hi_viscosity_parameter(nu_cSt, tc.impeller_head, tc.impeller_flow, 3.14159265358979323846 / 30)
                              : 0.0;
    auto C_eta_at = [&](double pump_speed) {
        if (B_1rpm == 0.0 || pump_speed <= 0.0) return 1.0;
        const double N = pump_speed * 30.0 / 3.14159265358979323846;
        return hi_efficiency_correction(B_1rpm / std::sqrt(std::sqrt(N)));
    };
    // Turbine torque the converter delivers at speed ratio SR (pump speed wt/SR).
    auto delivered = [&](double SR) {
        const double wp = s.turbine_speed / SR;
        const double K = interp(c.speed_ratio, c.capacity, SR);
        return interp(c.speed_ratio, c.torque_ratio, SR) * C_eta_at(wp) * (wp / K) * (wp / K);
    };
    double SR;
    bool coupling_end = false;
    if (s.turbine_speed == 0.0 || turbine_torque <= 0.0) {
        SR = 0.0;  // stall, or no drive demand at crawling speed: the engine idles below
    } else if (delivered(SR_max) >= turbine_torque) {
        SR = SR_max;  // the demand is met at the coupling end of the curve (clutch-like slip)
        coupling_end = true;
    } else {
        // delivered(SR) falls monotonically from infinity (SR -> 0) to delivered(SR_max).
        double lo = std::min(1e-3, SR_max), hi = SR_max;
        auto f = [&](double x) { return delivered(x) - turbine_torque; };
        while (f(lo) < 0 && lo > 1e-9) lo *= 0.1;
        std::uintmax_t it = 80;
        const auto [a, b] = boost::math::tools::toms748_solve(
            f, lo, hi, [](double x, double y) { return std::abs(y - x) < 1e-10; }, it);
        SR = 0.5 * (a + b);
    }
    // The engine does not idle below idle speed: when creeping the converter delivers more
    // than the demand and the brakes hold the difference.
    const double wp = std::max(SR > 0 ? s.turbine_speed / SR : 0.0, idle_speed);
    SR = wp > 0 ? s.turbine_speed / wp : 0.0;
    const double K = interp(c.speed_ratio, c.capacity, SR);
    s.pump_speed = wp;
    s.pump_torque = (wp / K) * (wp / K);
    if (coupling_end && wp > idle_speed) {
        s.C_eta = C_eta_at(wp);
        s.speed_ratio = SR;
        s.torque_ratio = interp(c.speed_ratio, c.torque_ratio, SR) * s.C_eta;
        s.pump_torque = turbine_torque / s.torque_ratio;
        s.loss = std::max(0.0, s.pump_torque * wp - turbine_torque * s.turbine_speed);
        return s;
    }
    s.speed_ratio = SR;
    s.C_eta = C_eta_at(wp);
    s.torque_ratio = interp(c.speed_ratio, c.torque_ratio, SR) * s.C_eta;
    // Power in minus the power the turbine delivers (to the gearbox and, when creeping, the brakes).
    s.loss = std::max(0.0, s.pump_torque * wp - s.torque_ratio * s.pump_torque * s.turbine_speed);
    return s;
}

}  // namespace gearloss::torque_converter
