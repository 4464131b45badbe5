#include "gearloss/thermal/network.hpp"

namespace gearloss::thermal {

NodeTemperatures node_rates(const Network& n, const NodeTemperatures& T, double P_oil, double P_clutch, double Q_amb) {
    NodeTemperatures d{0, 0, 0};
    double to_oil = P_oil;
    if (n.has_clutch()) {
        const double q_co = n.G_clutch_oil * (T[2] - T[0]);
        d[2] = (P_clutch - q_co) / n.C_clutch;
        to_oil += q_co;
    } else {
        to_oil += P_clutch;
    }
    if (n.has_housing()) {
        const double q_oh = n.G_oil_housing * (T[0] - T[1]);
        d[1] = (q_oh - Q_amb) / n.C_housing;
        to_oil -= q_oh;
    } else {
        to_oil -= Q_amb;
    }
    d[0] = to_oil / n.C_oil;
    return d;
}

double stored_heat(const Network& n, const NodeTemperatures& T, double T_ref) {
    double E = n.C_oil * (T[0] - T_ref);
    if (n.has_housing()) E += n.C_housing * (T[1] - T_ref);
    if (n.has_clutch()) E += n.C_clutch * (T[2] - T_ref);
    return E;
}

}  // namespace gearloss::thermal
