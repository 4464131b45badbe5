#pragma once
// The data of a report (report_data.hpp) from a case file and the command line's choices:
// the case parsed once (io::Sweep, as `gearloss map` does), its values as written, the map
// of its oil, the model-form spread and the map of each oil compared, all through the map
// machinery (map::run_map, map::run_spread); the oils compared are validated as `compare`
// validates its two.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/case/config.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/report/report_data.hpp"

namespace gearloss::report {

// A report shows at most kMaxReportPoints operating points: a larger grid is down-sampled to
// at most kMaxReportAxis speeds x kMaxReportAxis torques (a point list to kMaxReportPoints
// points), evenly with the ends kept, and the page says so (docs/report.md).
inline constexpr size_t kMaxReportAxis = 32;
inline constexpr size_t kMaxReportPoints = kMaxReportAxis * kMaxReportAxis;

struct ReportRequest {
    std::string config;
    std::optional<std::string> ratio;    // --ratio
    std::vector<std::string> oils;       // --oil FILE, once per oil compared with the case's
    // The command line's options applied to a loaded case (--oil-temp, --speed/--torque) and
    // the case checked with them, as every command does; called for the case and for each
    // variant of an oil sweep. `note` names the variant in its errors.
    std::function<io::Case(io::Case, const std::string& note)> prepare;
    map::CaseOverrides overrides;        // what the command line set (for the compared oils' checks)
    bool spread = true;                  // compute the model-form spread (when the case has forms)
    std::vector<std::string> spread_axes;  // restrict it to these axes (empty: all)
    map::MapOptions map_options;
    std::vector<std::string> command_line;
};

ReportData collect_report(const ReportRequest& q);

// The scalars of a parsed case document as written, depth first in the file's order, with
// key paths as a sweep names them ("gears.w1.face_width"; list items without a name by index).
std::vector<GivenValue> given_values(const io::YamlNode& root);

}  // namespace gearloss::report
