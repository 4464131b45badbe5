#pragma once
// Drive cycles: vehicle speed traces (1 Hz CSV `time_s,speed_kmh[,gear]`) and the
// named regulatory cycles shipped in configs/cycles/.
#include <string>
#include <vector>

namespace gearloss::cycle {

struct DriveCycle {
    std::string name;
    std::vector<double> time;   // s, strictly increasing
    std::vector<double> speed;  // m/s
    std::vector<int> gear;      // prescribed gear per sample (0 = neutral); empty = shift schedule
    double duration() const { return time.empty() ? 0.0 : time.back() - time.front(); }
    double distance() const;    // m, trapezoid rule
};

// Reads a cycle CSV; errors name the file, line and column.
DriveCycle load_cycle_csv(const std::string& file);
// `a` followed by `b`, b starting one time step after a's last sample.
DriveCycle concatenate(const DriveCycle& a, const DriveCycle& b, const std::string& name);
// A name (nedc, wltc, wltc-class3b, artemis, artemis-urban, artemis-rural,
// artemis-motorway-130, artemis-motorway-150) resolved in `dirs`, or a CSV file path.
DriveCycle resolve_cycle(const std::string& name_or_file, const std::vector<std::string>& dirs);
// The names resolve_cycle knows.
std::vector<std::string> cycle_names();

}  // namespace gearloss::cycle
