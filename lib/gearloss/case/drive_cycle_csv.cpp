#include "gearloss/case/drive_cycle_csv.hpp"

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <map>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"

namespace gearloss::io {

namespace {
constexpr double kMaxCycleAcceleration = 9.81;  // m/s^2: 1 g
}  // namespace

namespace fs = std::filesystem;
using cycle::DriveCycle;

DriveCycle load_cycle_csv(const std::string& file) {
    // A regular file of at most 64 MiB (a FIFO or a device is refused by name, unread).
    const std::string text = read_input_file(file, kMaxCsvFileBytes);
    CsvReader csv(text, file);
    CsvRecord rec;
    DriveCycle c;
    c.name = fs::path(file).stem().string();
    c.file = file;
    int ln = 0;
    int it = -1, iv = -1, ig = -1;
    size_t ncol = 0;
    // The detected separator, when it is not ',', for the messages about the layout.
    const auto noted = [&](const std::string& msg) {
        const std::string note = separator_note(csv.separator());
        return note.empty() ? msg : msg + "; " + note;
    };
    while (csv.next(rec)) {
        ln = rec.line;
        const auto& cells = rec.cells;
        if (it < 0) {
            for (size_t k = 0; k < cells.size(); ++k) {
                int* slot = cells[k] == "time_s" ? &it : cells[k] == "speed_kmh" ? &iv : cells[k] == "gear" ? &ig : nullptr;
                if (!slot) continue;
                if (*slot >= 0)
                    throw InputError(file, ln, static_cast<int>(k + 1), cells[k], "column '" + cells[k] + "' given twice");
                *slot = static_cast<int>(k);
            }
            if (it < 0 || iv < 0) {
                const std::string hint = cells.size() == 1 ? separator_hint(std::string(rec.text)) : std::string();
                throw InputError(file, ln, 1, "",
                                 hint.empty() ? noted("header must name the columns 'time_s' and 'speed_kmh' (optional 'gear')") : hint);
            }
            ncol = cells.size();
            continue;
        }
        if (cells.size() != ncol) {
            const std::string hint = separator_hint(std::string(rec.text), csv.separator());
            const std::string msg = "expected " + std::to_string(ncol) + " cells, found " + std::to_string(cells.size());
            throw InputError(file, ln, 1, "", hint.empty() ? noted(msg) : msg + "; " + hint);
        }
        const char sep = csv.separator();
        const double t = csv_cell_number(cells[it], file, ln, it + 1, "time_s", sep);
        const double v = csv_cell_number(cells[iv], file, ln, iv + 1, "speed_kmh", sep);
        if (v < 0 || v > 500) throw InputError(file, ln, iv + 1, "speed_kmh", "speed must be in [0, 500] km/h");
        if (!c.time.empty() && !(t > c.time.back()))
            throw InputError(file, ln, it + 1, "time_s", "time must increase from row to row");
        // A road vehicle neither gains nor loses speed faster than about 1 g (tyre grip); beyond it
        // the rows are not a drive (0 and 200 km/h alternating every second is 56 m/s^2).
        if (!c.time.empty()) {
            const double accel = (v / 3.6 - c.speed.back()) / (t - c.time.back());
            if (std::abs(accel) > kMaxCycleAcceleration)
                throw InputError(file, ln, iv + 1, "speed_kmh",
                                 fmt::format("{} from {:.4g} to {:.4g} km/h in {:.4g} s is {:.3g} m/s^2, beyond 1 g "
                                             "(9.81 m/s^2): not a road drive; check the speeds and times",
                                             accel > 0 ? "accelerating" : "braking", c.speed.back() * 3.6, v,
                                             t - c.time.back(), std::abs(accel)));
        }
        c.time.push_back(t);
        c.speed.push_back(v / 3.6);
        c.line.push_back(ln);
        if (ig >= 0) {
            const double g = csv_cell_number(cells[ig], file, ln, ig + 1, "gear", sep);
            if (g < 0 || g > 20 || g != std::floor(g)) throw InputError(file, ln, ig + 1, "gear", "gear must be 0-20");
            // Neutral while the wheels turn leaves the output shaft turning the gearbox, which the
            // model cannot represent (it would count no loss at all).
            if (g == 0 && v > 0)
                throw InputError(file, ln, ig + 1, "gear",
                                 fmt::format("gear 0 (neutral) at {:.4g} km/h: give the gear engaged while moving "
                                             "(0 only at standstill)", v));
            c.gear.push_back(static_cast<int>(g));
        }
    }
    if (c.time.size() < 2) throw InputError(file, ln, 0, "", "a cycle needs at least two samples");
    return c;
}

namespace {
const std::map<std::string, std::vector<std::string>>& named() {
    // Seed 003's ARTEMIS run (§4.2: urban + highway, 2061 s, 33 605 m) is urban followed by motorway 130
    // (the seed does not name the motorway variant: 130 assumed).
    static const std::map<std::string, std::vector<std::string>> m = {
        {"nedc", {"nedc"}},
        {"wltc", {"wltc-class3b"}},
        {"wltc-class3b", {"wltc-class3b"}},
        {"artemis", {"artemis-urban", "artemis-motorway-130"}},
        {"artemis-urban", {"artemis-urban"}},
        {"artemis-rural", {"artemis-rural"}},
        {"artemis-motorway-130", {"artemis-motorway-130"}},
        {"artemis-motorway-150", {"artemis-motorway-150"}},
    };
    return m;
}
}  // namespace

std::vector<std::string> cycle_names() {
    std::vector<std::string> v;
    for (const auto& [k, _] : named()) v.push_back(k);
    return v;
}

DriveCycle resolve_cycle(const std::string& name_or_file, const std::vector<std::string>& dirs,
                         const std::function<std::string()>& shipped, std::vector<std::string>* files_read) {
    const auto it = named().find(name_or_file);
    if (it == named().end()) {
        std::error_code ec;
        // Any existing path is read as a file: a FIFO, a device or a directory is then refused by name.
        if (fs::exists(fs::status(name_or_file, ec))) {
            if (files_read) files_read->push_back(name_or_file);
            return load_cycle_csv(name_or_file);
        }
        std::string names;
        for (const auto& n : cycle_names()) names += (names.empty() ? "" : ", ") + n;
        throw InputError("", 0, 0, "--cycle", "'" + excerpt(name_or_file) + "' is neither a cycle file nor one of: " + names);
    }
    std::vector<std::string> search = dirs;
    bool asked_shipped = false;
    DriveCycle out;
    for (size_t k = 0; k < it->second.size(); ++k) {
        std::string found;
        for (size_t i = 0; found.empty(); ++i) {
            if (i == search.size()) {
                if (asked_shipped || !shipped) break;
                asked_shipped = true;
                search.push_back(shipped());
            }
            const fs::path p = fs::path(search[i]) / (it->second[k] + ".csv");
            std::error_code ec;
            if (fs::is_regular_file(p, ec)) found = p.string();
        }
        if (found.empty()) {
            std::string searched;
            for (const auto& d : search) searched += (searched.empty() ? "" : ", ") + d;
            throw InputError("", 0, 0, "--cycle", "cycle file '" + it->second[k] + ".csv' not found in " +
                                                      (searched.empty() ? std::string("any folder") : searched));
        }
        if (files_read) files_read->push_back(found);
        DriveCycle part = load_cycle_csv(found);
        out = k == 0 ? part : cycle::concatenate(out, part, name_or_file);
    }
    out.name = name_or_file;
    return out;
}

}  // namespace gearloss::io
