#pragma once
// Helpers shared by the tests: shipped configs and temporary mutated copies.
#include <algorithm>
#include <atomic>
#include <filesystem>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gearloss/case/config.hpp"

namespace test_support {

inline std::string source_path(const std::string& rel) { return std::string(GEARLOSS_SOURCE_DIR) + "/" + rel; }

// A shipped case by its path under the source tree ("configs/transfer-box.yaml").
inline gearloss::io::Case load_shipped(const std::string& config) { return gearloss::io::load_case(source_path(config)); }

// An operating grid from input speeds in rpm and torques in N m.
inline gearloss::io::OperatingGrid rpm_grid(const std::vector<double>& speeds_rpm, const std::vector<double>& torques) {
    gearloss::io::OperatingGrid g;
    for (double n : speeds_rpm) g.speeds.push_back(n * 3.14159265358979323846 / 30.0);
    g.torques = torques;
    return g;
}

inline std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Writes `text` next to the shipped configs (so relative oil paths resolve)
// under a name unique to this process and instance (ctest runs cases in
// parallel processes), and removes it when the object goes out of scope.
struct TempConfig {
    std::string path;
    explicit TempConfig(const std::string& text) {
        static std::atomic<int> counter{0};
        path = source_path("configs/tmp-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".yaml");
        std::ofstream(path) << text;
    }
    ~TempConfig() { std::filesystem::remove(path); }
};

// Replaces the first occurrence of `from`; fails loudly if it is absent so a
// changed config cannot make a test pass vacuously.
inline std::string replace_once(std::string s, const std::string& from, const std::string& to) {
    const auto p = s.find(from);
    if (p == std::string::npos) throw std::runtime_error("test setup: '" + from + "' not found");
    return s.replace(p, from.size(), to);
}

inline int line_of(const std::string& text, const std::string& needle) {
    const auto p = text.find(needle);
    if (p == std::string::npos) throw std::runtime_error("test setup: '" + needle + "' not found");
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(p), '\n'));
}

// A private temporary directory, removed with everything in it at the end of its scope.
struct TempDir {
    std::filesystem::path path;
    TempDir() {
        std::string tmpl = (std::filesystem::temp_directory_path() / "gearloss-test-XXXXXX").string();
        if (!::mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
        path = tmpl;
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    // Writes `text` to `name` below the directory (creating its folders); returns the path.
    std::string write(const std::string& name, const std::string& text) const {
        const std::filesystem::path p = path / name;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
    // A named pipe `name` in the directory; returns its path.
    std::string fifo(const std::string& name) const {
        const std::filesystem::path p = path / name;
        if (::mkfifo(p.c_str(), 0600) != 0) throw std::runtime_error("mkfifo failed");
        return p.string();
    }
};

// A 23/67 helical reducer, m_n 3 mm, beta 15 deg, no profile shift, the wheel dipping 9 mm
// (3 m_n), fixed oil at 80 degC: the user's case of issue 36, with `extra` appended (a
// mechanisms block).
inline std::string reducer_23_67(const std::string& extra = "") {
    return std::string(R"(name: Reducer 23/67 m_n 3 mm
oil: oils/75W90-syn-A.yaml
shafts: [input, output]
gears:
  - {name: pinion, shaft: input,  position: 0 mm, teeth: 23, module: 3 mm, face_width: 30 mm, helix_angle: 15 deg, hand: right, Ra: 0.4 um}
  - {name: wheel,  shaft: output, position: 0 mm, teeth: 67, module: 3 mm, face_width: 30 mm, helix_angle: 15 deg, hand: left, Ra: 0.4 um, immersion: 9 mm}
meshes:
  - {name: m, gears: [pinion, wheel], angle: 0 deg}
bearings:
  - {name: in_a,  type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, B: 16 mm, C0: 11.2 kN, shaft: input,  position: -50 mm, locating: true}
  - {name: in_b,  type: deep_groove_ball, series: "62", d: 30 mm, D: 62 mm, B: 16 mm, C0: 11.2 kN, shaft: input,  position: 50 mm}
  - {name: out_a, type: deep_groove_ball, series: "62", d: 45 mm, D: 85 mm, B: 19 mm, C0: 21.6 kN, shaft: output, position: -50 mm, locating: true}
  - {name: out_b, type: deep_groove_ball, series: "62", d: 45 mm, D: 85 mm, B: 19 mm, C0: 21.6 kN, shaft: output, position: 50 mm}
housing:
  oil_volume: 1.5 L
thermal:
  mode: fixed
  oil_temperature: 80 degC
  ambient: 20 degC
gearbox:
  input: input
  output: output
operating:
  speeds: [500 rpm, 1000 rpm, 2000 rpm, 3000 rpm]
  torques: [50 N*m, 100 N*m]
)") + extra;
}

}  // namespace test_support
