// Thermal rating and the cooler against published worked examples: the thermal power capacity
// of a gear box from its housing (CareerRide 2015) through `rating`'s search, and two
// effectiveness-NTU examples of Som (2008) through the cooler heat path.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gearloss/mechanisms/empirical_mechanism.hpp"
#include "gearloss/rating/thermal_rating.hpp"
#include "gearloss/thermal/cooler.hpp"
#include "gearloss/thermal/heat_rejection.hpp"
#include "test_support.hpp"

using namespace gearloss;
using Approx = Catch::Detail::Approx;

namespace {
constexpr double kRpm = std::numbers::pi / 30.0;
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kZeroC = 273.15;
}  // namespace

TEST_CASE("published: the thermal power capacity of a worm gear box (CareerRide 2015)", "[rating][published]") {
    // CareerRide (2015), "power transmitting capacity of gear box", worked problem: a worm gear
    // box of housing surface A = 0.30 m^2 with an overall heat transfer coefficient C = 23 W/(m^2 K)
    // (a fan on the worm shaft blowing over the fins); the oil may rise 50 K above the ambient;
    // lead angle 6 deg, normal pressure angle 22 deg, friction coefficient 0.05. The book-style
    // solution (the balance of Jiang 2019, eq. 9.25, and of ISO/TR 14179-1: the losses at the
    // limit equal the heat the housing dissipates):
    //   phi_v = atan(0.05 / cos 22 deg) = 3.086 deg;  eta = tan 6 / tan(6 + 3.086) = 0.657;
    //   (1 - eta) P_i = C A dt = 23 x 0.30 x 50 = 345 W  ->  P_i = 345 / 0.343 = 1.006 kW (printed).
    // The same in gearloss: the housing as the resistance 1/(C A) = 1/6.9 K/W, and as the only loss
    // the worm mesh's (1 - eta) P_i, written as an empirical term (1 - eta) W x (omega / 1 rad/s)
    // x (T / 1 N m); `rating` then searches the input torque at which the stabilised oil is 50 K
    // above the ambient. What is the same: the heat balance and the limit search; what is not:
    // gearloss has no worm-mesh model, so the efficiency enters as the problem's given value.
    const double phi_v = std::atan(0.05 / std::cos(22 * kDeg));
    const double eta = std::tan(6 * kDeg) / std::tan(6 * kDeg + phi_v);
    REQUIRE(phi_v / kDeg == Approx(3.086).margin(1e-3));  // printed truncated: 3.0868
    REQUIRE(eta == Approx(0.657).margin(5e-4));

    auto c = test_support::load_shipped("configs/transfer-box.yaml");
    auto& m = c.model;
    thermal::ThermalResistance housing;
    housing.R0 = 1.0 / (23.0 * 0.30);  // K/W
    m.thermal.rejection.model = housing;
    for (size_t i = 0; i < m.mechanisms.size(); ++i)
        if (m.mechanisms[i].name() != "empirical") m.mechanisms[i].set_enabled(false);
    losses::EmpiricalTerm worm;
    worm.coefficient = 1.0 - eta;  // W at 1 rad/s and 1 N m
    worm.factors = {{.variable = losses::EmpiricalVariable::speed, .reference = 1.0, .exponent = 1.0},
                    {.variable = losses::EmpiricalVariable::torque, .reference = 1.0, .exponent = 1.0}};
    dynamic_cast<losses::EmpiricalMechanism&>(m.mechanisms.at("empirical")).set_terms({worm});

    rating::RatingOptions o;
    o.ambient = m.thermal.ambient = 25.0 + kZeroC;
    o.oil_limit = o.ambient + 50.0;
    o.start_torque = 1.0;
    o.max_torque = 1000.0;
    for (double rpm : {720.0, 1440.0}) {  // any worm speed: the capacity is a power
        CAPTURE(rpm);
        const auto p = rating::rate_speed(m, rpm * kRpm, o);
        REQUIRE(p.status == rating::RatingStatus::limit);
        CHECK(p.point.oil_temperature == Approx(o.oil_limit).margin(0.01));
        CHECK(p.housing_heat == Approx(345.0).margin(0.1));            // C A dt
        CHECK(p.point.losses.total() == Approx(345.0).margin(0.1));     // the balance closes
        CHECK(p.point.power_in == Approx(1006.0).margin(0.5));          // 1.006 kW as printed
    }
}

TEST_CASE("published: a counterflow oil-water exchanger by effectiveness-NTU (Som 2008, Example 10.6)",
          "[rating][cooler][published]") {
    // Som (2008), Example 10.6: water (c = 4.18 kJ/(kg K), 0.8 kg/s) enters a counterflow double-pipe
    // exchanger at 35 degC and is heated by oil (c = 1.88 kJ/(kg K), 1.5 kg/s) entering at 120 degC;
    // A = 15 m^2, U = 350 W/(m^2 K). The book's solution:
    //   C_water = 3344 W/K, C_oil = 2820 W/K = C_min, C_r = 0.8433, NTU = 5250/2820 = 1.8617,
    //   eps = (1 - e^(-NTU(1 - C_r))) / (1 - C_r e^(-NTU(1 - C_r))) = 0.6837,
    //   Q = eps C_min (120 - 35) = 163.9 kW.
    // As a gearbox cooler: the oil leaves the sump at 120 degC, the coolant (the water) enters at
    // 35 degC. gearloss takes the oil flow as a volume and rho c_p at the oil temperature: any
    // density gives C_oil = rho c_p V = 2820 W/K (850 kg/m^3 here).
    thermal::Cooler k;
    k.kind = thermal::Cooler::Kind::exchanger;
    const double rho = 850.0, rho_cp = rho * 1880.0;
    k.oil_flow = 1.5 / rho;
    k.ua = 350.0 * 15.0;
    k.coolant_temperature = 35.0 + kZeroC;
    k.coolant_capacity_rate = 0.8 * 4180.0;
    CHECK(k.heat_flow(120.0 + kZeroC, rho_cp) == Approx(163.9e3).margin(50.0));
    CHECK(k.conductance(rho_cp) / 2820.0 == Approx(0.6837).margin(5e-5));  // eps
    // Without the coolant's capacity rate the coolant stays at its inlet temperature (C_r = 0):
    // eps = 1 - e^-1.8617 = 0.8446, 202.4 kW: 24 % more heat than the exchanger can pass.
    k.coolant_capacity_rate = 0;
    CHECK(k.heat_flow(120.0 + kZeroC, rho_cp) == Approx(0.84462 * 2820.0 * 85.0).epsilon(1e-4));
}

TEST_CASE("published: the coolant as the smaller stream, effectiveness-NTU against the LMTD method (Som 2008, "
          "Example 10.5)",
          "[rating][cooler][published]") {
    // Som (2008), Example 10.5: water (4.18 kJ/(kg K), 1.2 kg/s) is heated from 30 to 90 degC in a
    // counterflow double pipe by a geothermal fluid (4.31 kJ/(kg K), 2 kg/s) entering at 160 degC;
    // U = 600 W/(m^2 K). The book finds the area by the LMTD method and again by NTU:
    //   Q = 1.2 x 4180 x 60 = 300.96 kW;  hot outlet 160 - 300960/8620 = 125.09 degC;
    //   LMTD = (95.09 - 70) / ln(95.09/70) = 81.90 K;  A = 300960 / (600 x 81.90) = 6.124 m^2.
    // Here the hot stream stands for the oil (C = 8620 W/K) and the water, now the smaller stream
    // (C_min = 5016 W/K, C_r = 0.5819), for the coolant: given the book's A, the cooler must pass
    // the 300.96 kW the water takes up (the LMTD method is independent of the code's eps-NTU).
    thermal::Cooler k;
    k.kind = thermal::Cooler::Kind::exchanger;
    const double rho_cp = 1000.0 * 4310.0;  // the hot fluid taken at 1000 kg/m^3: 2 kg/s = 2 L/s
    k.oil_flow = 2.0 / 1000.0;
    const double A = 300960.0 / (600.0 * ((95.0858 - 70.0) / std::log(95.0858 / 70.0)));
    REQUIRE(A == Approx(6.124).margin(5e-4));
    k.ua = 600.0 * A;
    k.coolant_temperature = 30.0 + kZeroC;
    k.coolant_capacity_rate = 1.2 * 4180.0;
    CHECK(k.heat_flow(160.0 + kZeroC, rho_cp) == Approx(300960.0).epsilon(2e-4));
}

TEST_CASE("counterflow cooler: the limits C_r -> 0 and C_r = 1", "[rating][cooler]") {
    // A coolant of far larger capacity rate is the C_r = 0 form, eps = 1 - e^-NTU; equal capacity
    // rates give eps = NTU/(1 + NTU) (Incropera et al. 2007, Table 11.3): NTU = 2 -> eps = 2/3, and
    // the quotient just below C_r = 1 tends to the same value (no cancellation near it).
    thermal::Cooler k;
    k.kind = thermal::Cooler::Kind::exchanger;
    const double rho_cp = 1.7e6;
    k.oil_flow = 1e-4;  // C_oil = 170 W/K
    k.ua = 340.0;       // NTU = 2
    k.coolant_temperature = 300.0;
    k.coolant_capacity_rate = 1e12;
    CHECK(k.conductance(rho_cp) == Approx(170.0 * (1.0 - std::exp(-2.0))).epsilon(1e-9));
    k.coolant_capacity_rate = 170.0;
    CHECK(k.conductance(rho_cp) == Approx(170.0 * 2.0 / 3.0).epsilon(1e-12));
    k.coolant_capacity_rate = 170.0 * (1.0 + 1e-12);
    CHECK(k.conductance(rho_cp) == Approx(170.0 * 2.0 / 3.0).epsilon(1e-9));
    k.coolant_capacity_rate = 170.0 * (1.0 + 1e-6);
    CHECK(k.conductance(rho_cp) == Approx(170.0 * 2.0 / 3.0).epsilon(1e-6));
}
