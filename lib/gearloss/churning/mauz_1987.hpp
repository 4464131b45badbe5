#pragma once
// Splash (churning) torque of a dip-lubricated gear pair: the form of Mauz (1987) as it is
// quoted in secondary sources for ISO/TR 14179-2 (Fernandes 2015 compares its data with the
// Mauz model; the text of neither could be read here):
//
//     T_VZ0 = C_Sp C_1 exp(C_2 v_t / v_t0)                                  [N m]
//     C_1   = 0.063 (e_1 + e_2) / e_0 + 0.0128 (b / b_0)^3                  [N m]
//     C_2   = (e_1 + e_2) / (80 e_0) + 0.2
//     C_Sp  = (4 e_max / (3 h_c))^1.5 (2 h_c / l_h)
//     e_0 = b_0 = 10 mm, v_t0 = 10 m/s
//
// e_1, e_2 immersion depths of the two gears of the pair, e_max the larger, b face width,
// v_t pitch-line speed, h_c and l_h lengths of the sump whose exact definitions we could not
// read (docs/config.md "Churning forms and their ranges"). The coefficients are as quoted in
// secondary sources, not checked against the ISO/TR text. The form has no oil property in it
// (it was fitted at one oil and temperature range): the torque does not change as the oil
// warms. Lengths enter as ratios to e_0 = b_0 = 10 mm, so the SI lengths of the library
// give the original ratios; the constants 0.063 and 0.0128 carry N m.

namespace gearloss::churning {

// One dip-lubricated gear pair as the form sees it (SI).
struct SplashPair {
    double e1 = 0, e2 = 0;  // immersion depths of the two gears [m] (0: that gear does not dip)
    double b = 0;           // face width [m]
    double v_t = 0;         // pitch-line speed [m/s]
};

// The sump lengths of the splash factor C_Sp [m]; either <= 0: C_Sp = 1 (not described).
struct SplashSump {
    double h_c = 0;
    double l_h = 0;
};

// C_Sp for the larger immersion e_max [m].
double mauz_splash_factor(double e_max, const SplashSump& sump);

// T_VZ0 [N m] of the pair (0 when neither gear dips).
double mauz_splash_torque(const SplashPair& pair, double splash_factor);

}  // namespace gearloss::churning
