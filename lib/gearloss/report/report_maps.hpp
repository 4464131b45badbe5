#pragma once
// The report's map sections (html_report.cpp assembles the page): the reference oil's maps
// (efficiency, oil temperature, total loss, each mechanism's loss), the model-form spread,
// and per compared oil the differences against the reference (oil k - reference; red =
// worse, blue = better), plus the columns embedded as JSON for readers of the page.
#include <string>

#include <nlohmann/json.hpp>

#include "gearloss/report/report_data.hpp"
#include "gearloss/report/report_summary.hpp"
#include "gearloss/report/svg_map.hpp"

namespace gearloss::report {

// The case's operating points in display units.
MapAxes map_axes(const io::OperatingGrid& grid);

// The HTML (headings, notes and inline SVG pictures) of each section.
// The maps of the mechanisms that are zero everywhere (summary.zero_mechanisms) are not drawn:
// one line names them.
std::string maps_section(const ReportData& d, const MapAxes& axes, const ReportSummary& summary);
std::string spread_section(const ReportData& d, const MapAxes& axes);
std::string comparison_section(const ReportData& d, const MapAxes& axes);

// One oil's map as columns named as gearloss map's CSV names them ("speed_in_rpm", "torque_in_Nm",
// "oil_temp_C", "P_mesh_W", ..., "P_total_W", "efficiency", "status"); values without a
// number are null.
nlohmann::ordered_json map_columns(const OilMap& m);

}  // namespace gearloss::report
