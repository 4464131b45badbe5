#include "gearloss/churning/mauz_1987.hpp"

#include <algorithm>
#include <cmath>

namespace gearloss::churning {

namespace {
// Reference values of the quoted form: e_0 = b_0 = 10 mm, v_t0 = 10 m/s.
constexpr double e0 = 0.010, b0 = 0.010, v_t0 = 10.0;
}  // namespace

double mauz_splash_factor(double e_max, const SplashSump& sump) {
    if (!(sump.h_c > 0) || !(sump.l_h > 0) || !(e_max > 0)) return 1.0;
    // Mauz (1987) as quoted: C_Sp = (4 e_max / (3 h_c))^1.5 (2 h_c / l_h).
    return std::pow(4.0 * e_max / (3.0 * sump.h_c), 1.5) * (2.0 * sump.h_c / sump.l_h);
}

double mauz_splash_torque(const SplashPair& pair, double splash_factor) {
    const double e = std::max(pair.e1, 0.0) + std::max(pair.e2, 0.0);
    if (!(e > 0)) return 0.0;
    // Mauz (1987) as quoted: C_1 = 0.063 (e_1 + e_2)/e_0 + 0.0128 (b/b_0)^3 [N m],
    // C_2 = (e_1 + e_2)/(80 e_0) + 0.2, T_VZ0 = C_Sp C_1 exp(C_2 v_t/v_t0).
    const double bb = pair.b / b0;
    const double C1 = 0.063 * e / e0 + 0.0128 * bb * bb * bb;
    const double C2 = e / (80.0 * e0) + 0.2;
    return splash_factor * C1 * std::exp(C2 * std::abs(pair.v_t) / v_t0);
}

}  // namespace gearloss::churning
