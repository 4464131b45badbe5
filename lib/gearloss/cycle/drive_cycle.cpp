#include "gearloss/cycle/drive_cycle.hpp"

namespace gearloss::cycle {

double DriveCycle::distance() const {
    double d = 0;
    for (size_t i = 1; i < time.size(); ++i) d += 0.5 * (speed[i] + speed[i - 1]) * (time[i] - time[i - 1]);
    return d;
}

DriveCycle concatenate(const DriveCycle& a, const DriveCycle& b, const std::string& name) {
    DriveCycle c = a;
    c.name = name;
    // b starts one time step after a ends (the ARTEMIS parts: 993 s + 1 s + 1067 s = seed 003 §4.2's 2061 s).
    const double step = a.time.size() > 1 ? a.time[a.time.size() - 1] - a.time[a.time.size() - 2] : 1.0;
    const double shift = a.time.back() + step - b.time.front();
    for (size_t i = 0; i < b.time.size(); ++i) {
        c.time.push_back(b.time[i] + shift);
        c.speed.push_back(b.speed[i]);
    }
    if (!a.gear.empty() && !b.gear.empty()) c.gear.insert(c.gear.end(), b.gear.begin(), b.gear.end());
    else c.gear.clear();
    // Rows of different files have no single file to name.
    c.file.clear();
    c.line.clear();
    return c;
}

}  // namespace gearloss::cycle
