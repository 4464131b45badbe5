#pragma once
// `gearloss report`: one self-contained HTML page about a case (no network, no other file:
// the style, the pictures as inline SVG, the data as embedded JSON and a small inline script
// are all in the page). Sections: the case as given (assumed values flagged), derived
// geometry and checks (io::check_report, the plausibility warnings), the loss mechanisms'
// forms and parameters, the maps (report_maps.hpp), the model-form spread, the oil
// comparison, and a footer with the program version, command line and case hash.
#include <string>

#include "gearloss/report/report_data.hpp"

namespace gearloss::report {

// The page. Every text from the user (file names, names, YAML values, messages) is escaped.
// The inline script records script errors and console errors, checks the embedded data and
// the pictures, and sets the element #gl-status to data-status="ok" data-errors="0" when the
// page loaded without any (tests render the page headless and read it).
std::string html_report(const ReportData& d);

}  // namespace gearloss::report
