#include "gearloss/vehicle/vehicle.hpp"

#include <algorithm>
#include <cmath>

namespace gearloss::vehicle {

namespace {
// Index i with x[i] <= v < x[i+1] (clamped) and the weight of x[i+1].
std::pair<size_t, double> bracket(const std::vector<double>& x, double v) {
    if (x.size() < 2 || v <= x.front()) return {0, 0.0};
    if (v >= x.back()) return {x.size() - 2, 1.0};
    const size_t i = static_cast<size_t>(std::upper_bound(x.begin(), x.end(), v) - x.begin()) - 1;
    return {i, (v - x[i]) / (x[i + 1] - x[i])};
}
}  // namespace

double FuelMap::rate_at(double omega, double torque) const {
    if (speeds.size() < 2 || torques.size() < 2) return rate.empty() || rate[0].empty() ? 0.0 : rate[0][0];
    const auto [i, s] = bracket(speeds, omega);
    const auto [j, t] = bracket(torques, torque);
    const double r00 = rate[i][j], r01 = rate[i][j + 1], r10 = rate[i + 1][j], r11 = rate[i + 1][j + 1];
    return std::max(0.0, (1 - s) * ((1 - t) * r00 + t * r01) + s * ((1 - t) * r10 + t * r11));
}

namespace {
double envelope(double torque, double power, double w) {
    const double a = std::abs(w);
    return a * torque > power ? power / a : torque;
}
}  // namespace

double Motor::drive_limit(double w) const { return envelope(max_torque, max_power, w); }
double Motor::recuperation_limit(double w) const { return envelope(recuperation_torque, recuperation_power, w); }

double Vehicle::tractive_force(double v, double a, double grade) const {
    constexpr double g = 9.81;
    return f0 * (v > 0 ? 1.0 : 0.0) + f1 * v + f2 * v * v + mass * (1.0 + rotating_mass_factor) * a +
           mass * g * std::sin(grade);
}

int select_gear(const Vehicle& v, const std::vector<double>& input_per_wheel, double wheel_speed, int gear) {
    const int n = static_cast<int>(input_per_wheel.size());
    if (n == 0) return 0;
    gear = std::clamp(gear, 1, n);
    if (wheel_speed <= 0.0) return 1;
    // Up while this gear spins the input too fast; down while too slow (not below first).
    while (gear < n && input_per_wheel[gear - 1] * wheel_speed > v.shift.upshift_speed &&
           input_per_wheel[gear] * wheel_speed >= v.shift.downshift_speed)
        ++gear;
    while (gear > 1 && input_per_wheel[gear - 1] * wheel_speed < v.shift.downshift_speed) --gear;
    return gear;
}

}  // namespace gearloss::vehicle
