#pragma once
// Reading drive cycles (gearloss/cycle/drive_cycle.hpp): a 1 Hz CSV `time_s,speed_kmh[,gear]`, or one
// of the named regulatory cycles shipped in configs/cycles/ (installed in the data directory,
// gearloss/io/data_dir.hpp).
#include <functional>
#include <string>
#include <vector>

#include "gearloss/cycle/drive_cycle.hpp"

namespace gearloss::io {

// Reads a cycle CSV; errors name the file, line and column.
cycle::DriveCycle load_cycle_csv(const std::string& file);
// A name (nedc, wltc, wltc-class3b, artemis, artemis-urban, artemis-rural,
// artemis-motorway-130, artemis-motorway-150) resolved in `dirs` (the first folder holding
// its file), then in the folder `shipped` returns (called only when a file of the cycle is in
// none of `dirs`; it may throw), or a CSV file path. `files_read`, when given, receives the
// path of every file read (so that no output of the run lands on one).
cycle::DriveCycle resolve_cycle(const std::string& name_or_file, const std::vector<std::string>& dirs,
                                const std::function<std::string()>& shipped = {},
                                std::vector<std::string>* files_read = nullptr);
// The names resolve_cycle knows.
std::vector<std::string> cycle_names();

}  // namespace gearloss::io
