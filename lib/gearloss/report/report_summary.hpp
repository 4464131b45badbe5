#pragma once
// The report's first screen (html_report.hpp places it under the title): what a reader who
// will not scroll needs, with every number printed in the page. The figures come from the
// solved maps (report_data.hpp); nothing here solves.
//  - the ratio as i = n_in/n_out of the gear train (and the named ratio of a multi-speed box);
//  - the rated point (the highest input power among the points with values), the best and
//    the worst efficiency, each with its oil temperature, total loss and the loss split per
//    mechanism (W and share of the total);
//  - the oil temperature over the map and the thermal limit (the oil's permissible sump
//    temperature, the points above it and those without an equilibrium);
//  - the oils compared (the case's plus each other), ranked by their mean total loss over the
//    points where every oil has values;
//  - the mechanisms that are zero at every point, named in one line instead of drawn.
#include <optional>
#include <string>
#include <vector>

#include "gearloss/report/report_data.hpp"

namespace gearloss::report {

// One operating point of the reference map as the summary shows it.
struct KeyPoint {
    std::string role;  // "rated (highest input power)", "best efficiency", "worst efficiency"
    size_t index = 0;  // in grid order
    double speed_rpm = 0, torque_Nm = 0, power_in_W = 0;
    double efficiency = 0;  // fraction; NaN where not defined (zero torque)
    double oil_temp_C = 0, total_W = 0;
    bool above_oil_limit = false;
};

// One oil in the ranking.
struct OilRank {
    std::string name, source;
    bool reference = false;
    double mean_total_W = 0;      // over the points where every oil has values
    double mean_efficiency = 0;   // fraction, over those points that define it
    double max_oil_temp_C = 0;    // over those points
    size_t points = 0;            // how many points the means are over
};

struct ReportSummary {
    double ratio_i = 0;           // n_in / n_out (signed: negative when the output turns the other way)
    std::string ratio_name;       // gearbox.ratio of a multi-speed case, or empty
    std::vector<KeyPoint> key_points;  // rated, best, worst (those that exist; a point that is two is one row)
    std::vector<size_t> split_mechanisms;  // mechanisms in the loss split (not zero everywhere)
    std::vector<size_t> zero_mechanisms;   // mechanisms at 0 W at every point with values
    // Oil temperature over the points with values [degC], and the limit.
    double oil_temp_min_C = 0, oil_temp_max_C = 0, oil_limit_C = 0;
    size_t with_values = 0, above_limit = 0, no_equilibrium = 0, out_of_range = 0;
    // The highest input power among the admissible points (ok) and the lowest among the points
    // above the oil's limit or without equilibrium [W]; NaN when there is none.
    double highest_admissible_W = 0, lowest_beyond_W = 0;
    std::vector<OilRank> oils;    // ranked, lowest mean loss first; the reference is in it
};

ReportSummary summarise(const ReportData& d);

// "windage: 0 W everywhere; clutch drag: 0 W everywhere (switched off)"; empty when none.
std::string zero_mechanisms_line(const ReportData& d, const ReportSummary& s);

// The summary section's HTML (id="summary").
std::string summary_section(const ReportData& d, const ReportSummary& s);

}  // namespace gearloss::report
