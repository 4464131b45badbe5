#pragma once
// Bearing catalogue files (configs/bearings/catalogue.yaml, docs/config.md "Bearing designations"):
// series blocks of rows [designation, d, D, B (or T, B), C, C0 (, e, Y)] in mm and kN, each series
// with its bearing type, SKF (2004) constants row and sources. The shipped file is found in the
// data folder (gearloss/io/data_dir.hpp); a case adds its own with `bearing_catalogue:`.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/bearings/skf_constants.hpp"

namespace gearloss::io {

struct CatalogueEntry {
    std::string designation;  // as printed in the catalogue: "NJ 309 ECP"
    std::string key;          // bearings::designation_key of it
    bearings::BearingType type = bearings::BearingType::deep_groove_ball;
    std::string series;       // the block's series: "NJ 3"
    std::string skf_series;   // row of the SKF (2004) constants: "3"
    double d = 0, D = 0, B = 0;  // m; B: the width the friction model uses (T for tapered)
    std::optional<double> T, cone_width;  // tapered: total width T and cone width B [m]
    std::optional<double> C, C0;          // N
    std::optional<double> e, Y;           // tapered calculation factors
    std::optional<double> contact_angle;  // rad, when the series states it
    std::string location;     // "file:line" of the row, file as shown (load_file)
    std::string ratings;      // the block's `ratings` source
    std::string verified;     // the block's `verified` text
};

class BearingCatalogue {
public:
    // Adds the rows of a catalogue file; a row replaces an earlier file's row of the same key, and
    // the same key twice in one file is an error.
    // InputError naming file:line:col and key for anything malformed. `shown` names the file in
    // the rows' locations and in files() (what `check` prints; machine independent), default path.
    void load_file(const std::string& path, const std::string& shown = "");
    const CatalogueEntry* find(const std::string& key) const;
    // Up to n printed designations whose keys are closest to `key`.
    std::vector<std::string> closest(const std::string& key, size_t n) const;
    size_t size() const { return by_key_.size(); }
    // Every row by key (for a search by type and bore: the REXS importer's assumed bearings).
    const std::map<std::string, CatalogueEntry>& entries() const { return by_key_; }
    const std::vector<std::string>& files() const { return files_; }
    // The same files as paths to read (for the case hash): files() shows them machine-independently.
    const std::vector<std::string>& paths() const { return paths_; }
    // "875 rows from <gearloss data>/bearings/catalogue.yaml and own.yaml" (for messages).
    std::string summary() const;

private:
    std::map<std::string, CatalogueEntry> by_key_;
    std::vector<std::string> files_, paths_;
};

// How the shipped catalogue is named in row locations, whatever folder it was found in.
inline constexpr const char* kShippedCatalogueName = "<gearloss data>/bearings/catalogue.yaml";

// The shipped catalogue (bearings/catalogue.yaml of the data folder), read once per process.
// `key` names the case key that needed it, for the error when the data folder is not found.
const BearingCatalogue& shipped_bearing_catalogue(const std::string& key);

// What `check` prints for a bearing: each value and where it came from.
struct ResolvedValue {
    std::string name;    // "d", "D", "B", "T", "C", "C0", "Y", "e", "series"
    std::string text;    // value with unit: "35 mm", "35.1 kN", "1.9", "63"
    double si = 0;       // the value in SI (0 for text values)
    std::string source;  // "catalogue configs/bearings/catalogue.yaml:123", "explicit case.yaml:19:45", ...
};
struct BearingResolution {
    std::string bearing;      // the bearing's name
    std::string designation;  // as written in the case ("" when none)
    std::string suffix;       // its suffix ("2RS1"): seals, cage, clearance, tolerance; not in the row
    std::string entry;        // the catalogue row's printed designation
    std::string entry_location, verified, ratings;
    std::string type, type_source;
    std::vector<ResolvedValue> values;
};

}  // namespace gearloss::io
