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
            // Effectiveness-NTU with C_r -> 0 (Incropera et al. 2007, Table 11.3): the oil is the
            // stream of smaller capacity rate C = rho c_p V.
            const double C = rho_cp * oil_flow;
            if (!(C > 0)) return 0.0;
            const double eps = -std::expm1(-ua / C);
            return eps * C;
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
