#pragma once
// What one HTML report shows (html_report.hpp renders it): the case as given and as derived,
// the map of its oil over the case's operating points, the model-form spread, and the same
// map for each oil it is compared with. Built by collect_report (report_run.hpp), which reuses
// the map machinery (map::run_map, map::run_spread); nothing here solves.
#include <optional>
#include <string>
#include <vector>

#include "gearloss/case/config.hpp"
#include "gearloss/map/form_spread.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::report {

// One value of the case file as the user wrote it: its key path ("gears.w1.face_width"),
// the scalar text ("14 mm") and its line.
struct GivenValue {
    std::string key, value;
    int line = 0;
};

// A value the loader filled in because the case did not give it (key, value, reason, location).
using AssumedValue = io::AssumedValue;

// The map of one oil over the case's operating points (grid order).
struct OilMap {
    std::string oil_name;  // lubricant::Oil::name
    std::string source;    // "the case", "--oil FILE", "sweep oil=FILE"
    solver::Model model;   // the case with this oil (mechanisms, columns, oil data)
    std::vector<solver::PointResult> results;
};

// The model-form spread of the reference oil's map (map::run_spread), or why there is none.
struct SpreadMap {
    std::vector<map::SpreadAxis> axes;
    size_t combinations = 0;
    map::SpreadResult result;
    std::string note;  // combinations that do not apply (map::not_applicable_note), or empty
};

struct ReportData {
    io::Case reference;  // the case with the command line's options applied (the reference oil's)
    std::string title;   // the case's `title:` when it has one, else empty
    std::vector<GivenValue> given;
    // io::Case::assumed of the case as reported, flagged on the page.
    std::vector<AssumedValue> assumed;
    std::vector<std::string> sweep_notes;  // what of a case's sweep, and of a grid beyond kMaxReportPoints, the report shows
    std::string thermal;                   // "stabilised" or "fixed at 80.0 degC (--oil-temp)"
    bool fixed_oil_temperature = false;
    OilMap reference_map;
    std::vector<OilMap> comparisons;  // each against reference_map (oil k - reference)
    std::optional<SpreadMap> spread;
    std::string spread_note;  // why there is no spread, or empty
    // Footer.
    std::string version;
    std::vector<std::string> command_line;
    std::string case_hash;  // map::case_hash, as in the outputs' FILE.meta.json
    double seconds = 0;  // the maps' time (solve), for the page's summary
};

}  // namespace gearloss::report
