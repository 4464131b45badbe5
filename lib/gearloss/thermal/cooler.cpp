#include "gearloss/thermal/cooler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gearloss::thermal {

double Cooler::conductance(double rho_cp) const {
    switch (kind) {
        case Kind::none:
        case Kind::duty: return 0.0;
        // Sensible heat of the circulated oil (ISO/TR 14179-2, the external cooling term).
        case Kind::injection: return rho_cp * oil_flow;
        case Kind::conductance: return ua;
        case Kind::exchanger: {
            const double C_oil = rho_cp * oil_flow;
            if (!(C_oil > 0)) return 0.0;
            if (!(coolant_capacity_rate > 0)) {
                // Effectiveness-NTU with C_r -> 0 (Incropera et al. 2007, Table 11.3): the oil is
                // the stream of smaller capacity rate C = rho c_p V.
                return -std::expm1(-ua / C_oil) * C_oil;
            }
            // Counterflow with both capacity rates finite (Incropera et al. 2007, Table 11.3, the rows
            // of the counterflow exchanger, C_r < 1 and C_r = 1).
            const double C_min = std::min(C_oil, coolant_capacity_rate);
            const double C_max = std::max(C_oil, coolant_capacity_rate);
            const double C_r = C_min / C_max, one_minus_C_r = (C_max - C_min) / C_max;
            const double NTU = ua / C_min;
            // 1 - C_r e^x written as (1 - C_r) - C_r (e^x - 1): no cancellation as C_r -> 1,
            // where eps tends to NTU/(1 + NTU), the value taken at C_r = 1.
            const double em1 = std::expm1(-NTU * one_minus_C_r);
            const double eps = one_minus_C_r > 0 ? -em1 / (one_minus_C_r - C_r * em1) : NTU / (1.0 + NTU);
            return eps * C_min;
        }
    }
    return 0.0;
}

double Cooler::valve_share(double T_oil) const {
    if (!(valve_full > valve_opens)) return 1.0;
    return std::clamp((T_oil - valve_opens) / (valve_full - valve_opens), 0.0, 1.0);
}

double Cooler::heat_flow(double T_oil, double rho_cp) const {
    if (kind == Kind::none) return 0.0;
    const double share = valve_share(T_oil);
    if (kind == Kind::duty) return share * duty;
    return share * conductance(rho_cp) * (T_oil - cold_side_temperature());
}

double Cooler::cold_side_temperature() const {
    switch (kind) {
        case Kind::injection: return inlet_temperature;
        case Kind::conductance:
        case Kind::exchanger: return coolant_temperature;
        default: return std::numeric_limits<double>::infinity();
    }
}

}  // namespace gearloss::thermal
