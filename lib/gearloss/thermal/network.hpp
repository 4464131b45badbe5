#pragma once
// Lumped thermal network of a transmission for transient warm-up: an oil node,
// optionally a housing (case) node between the oil and the ambient, and optionally
// a clutch-pack node that receives the drag heat of the open packs.
//   C_oil dT_oil/dt = P_oil - G_oh (T_oil - T_housing) + G_co (T_clutch - T_oil)
//   C_h   dT_h/dt   = G_oh (T_oil - T_housing) - Q_amb(T_housing)
//   C_c   dT_c/dt   = P_clutch - G_co (T_clutch - T_oil)
// Without a housing node Q_amb leaves the oil node directly (one node of capacity C_oil).
#include <array>

namespace gearloss::thermal {

struct Network {
    double C_oil = 0;          // J/K (single node: oil + housing + shafts)
    double C_housing = 0;      // J/K; 0 = no housing node
    double G_oil_housing = 0;  // W/K
    double C_clutch = 0;       // J/K; 0 = no clutch node (drag heat goes into the oil)
    double G_clutch_oil = 0;   // W/K
    bool has_housing() const { return C_housing > 0; }
    bool has_clutch() const { return C_clutch > 0; }
    double total_capacity() const { return C_oil + C_housing + C_clutch; }
};

// Node temperatures [oil, housing, clutch] (unused nodes are carried but ignored).
using NodeTemperatures = std::array<double, 3>;

// Temperature of the surface that rejects heat to the ambient.
inline double surface_temperature(const Network& n, const NodeTemperatures& T) {
    return n.has_housing() ? T[1] : T[0];
}

// dT/dt of each node for heat inputs P_oil, P_clutch [W] and the heat Q_amb [W] leaving the surface.
NodeTemperatures node_rates(const Network& n, const NodeTemperatures& T, double P_oil, double P_clutch, double Q_amb);

// Stored heat relative to T_ref [J] (for energy balances).
double stored_heat(const Network& n, const NodeTemperatures& T, double T_ref);

}  // namespace gearloss::thermal
