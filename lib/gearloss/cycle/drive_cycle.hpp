#pragma once
// Drive cycles: vehicle speed traces (read from 1 Hz CSV `time_s,speed_kmh[,gear]`, and the
// named regulatory cycles shipped in configs/cycles/, by gearloss/case/drive_cycle_csv.hpp).
#include <string>
#include <vector>

namespace gearloss::cycle {

struct DriveCycle {
    std::string name;
    std::vector<double> time;   // s, strictly increasing
    std::vector<double> speed;  // m/s
    std::vector<int> gear;      // prescribed gear per sample (0 = neutral); empty = shift schedule
    // Where each sample was read: the CSV file and each sample's 1-based line in it (empty for a
    // cycle joined from several files), so that an error at a row names the user's row.
    std::string file;
    std::vector<int> line;
    double duration() const { return time.empty() ? 0.0 : time.back() - time.front(); }
    double distance() const;    // m, trapezoid rule
};

// `a` followed by `b`, b starting one time step after a's last sample.
DriveCycle concatenate(const DriveCycle& a, const DriveCycle& b, const std::string& name);

// Reading cycle files and the named cycles: gearloss/case/drive_cycle_csv.hpp.

}  // namespace gearloss::cycle
