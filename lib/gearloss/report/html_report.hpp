#pragma once
// `gearloss report`: one self-contained HTML page about a case (no network, no other file:
// the style, the pictures as inline SVG, the data as embedded JSON and a small inline script
// are all in the page). Sections, the results first: the summary (report_summary.hpp), the
// maps (report_maps.hpp, their values printed: map_values.hpp), the oil comparison, the
// model-form spread, the loss mechanisms' forms and parameters, the case as given (assumed
// values flagged, collapsed), derived geometry and checks (the plausibility warnings; the text
// of io::check_report collapsed), and a footer with the program version, command line and case
// hash. A print style (@media print) lays it out on A4 for paper and for --pdf (pdf_print.hpp).
#include <string>

#include "gearloss/report/report_data.hpp"

namespace gearloss::report {

// The page. Every text from the user (file names, names, YAML values, messages) is escaped.
// The inline script records script errors and console errors, checks the embedded data and
// the pictures, and sets the element #gl-status to data-status="ok" data-errors="0" when the
// page loaded without any (tests render the page headless and read it).
std::string html_report(const ReportData& d);

}  // namespace gearloss::report
