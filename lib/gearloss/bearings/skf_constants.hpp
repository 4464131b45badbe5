#pragma once
// Constants of the SKF (2004) frictional moment model by bearing type and series (R/S, K_Z/K_L), in
// the catalogue's units (mm, r/min, mm^2/s, N*mm): skf_model.hpp takes SI and converts (skf_model.cpp).
#include <optional>
#include <string>
#include <vector>

namespace gearloss::bearings {

enum class BearingType {
    deep_groove_ball,
    angular_contact_ball,         // single row
    angular_contact_ball_double,  // double row
    four_point_contact,
    self_aligning_ball,
    cylindrical_roller,
    cylindrical_roller_full,      // full complement
    needle_roller,
    tapered_roller,
    spherical_roller,
    thrust_ball,
    cylindrical_roller_thrust,
};

const char* to_string(BearingType t);
std::optional<BearingType> bearing_type_from_string(const std::string& s);
bool is_roller(BearingType t);
std::vector<std::string> bearing_type_names();

struct SkfConstants {
    double R1 = 0, R2 = 0, R3 = 0, R4 = 0;
    double S1 = 0, S2 = 0, S3 = 0, S4 = 0;
    double K_Z = 0, K_L = 0;
    int rows = 1;  // i_rw, rows of balls
};

// Constants for a type and series ("62", "NU 22", "322", "other"...) or a full designation
// ("NJ 406", "6307-2RS1": its series, gearloss/bearings/designation.hpp). Returns
// nullopt when the series is not in the table; `series_names` lists the known ones.
std::optional<SkfConstants> skf_constants(BearingType t, const std::string& series);
std::vector<std::string> series_names(BearingType t);

// Seal constants of the SKF (2004) seal moment M_seal = K_S1 d_s^beta + K_S2 (N*mm, d_s in mm),
// stated for a bearing sealed on both sides, for a seal code ("RS1", "LS", "CS"...) on a type;
// D in mm selects the deep groove row. Shields (Z, RZ, 2Z) give zeros; nullopt: no constants.
struct SealConstants {
    double beta = 2.0, K_S1 = 0, K_S2 = 0;
};
std::optional<SealConstants> skf_seal_constants(BearingType t, const std::string& code, double D_mm);

// SKF mu_EHL default by bearing type and base oil (mineral / synthetic / transmission fluid).
double default_mu_ehl(BearingType t, bool synthetic, bool transmission_fluid);

}  // namespace gearloss::bearings
