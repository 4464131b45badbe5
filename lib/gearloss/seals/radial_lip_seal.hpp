#pragma once
// Radial shaft (lip) seal friction.
namespace gearloss::seals {

// ISO/TR 14179-2 (same expression credited to Simrit/Freudenberg):
// P = 7.69e-6 d_sh^2 n [W] with d_sh in mm and n in r/min; here in SI.
inline double radial_seal_power(double shaft_diameter_m, double omega_rad_s) {
    constexpr double pi = 3.14159265358979323846;
    const double d_mm = shaft_diameter_m * 1e3;
    const double n_rpm = (omega_rad_s < 0 ? -omega_rad_s : omega_rad_s) * 30.0 / pi;
    return 7.69e-6 * d_mm * d_mm * n_rpm;
}

}  // namespace gearloss::seals
