#include "gearloss/report/html_report.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "gearloss/io/json_text.hpp"
#include "gearloss/results/reports.hpp"
#include "gearloss/report/html.hpp"
#include "gearloss/report/report_maps.hpp"
#include "gearloss/report/report_summary.hpp"

namespace gearloss::report {
namespace {

using nlohmann::ordered_json;

constexpr const char* kStyle = R"css(
body{font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;margin:0;color:#222;background:#fafafa}
header,main,footer{max-width:1280px;margin:0 auto;padding:0 24px}
header{padding-top:16px}h1{font-size:22px;margin:8px 0}h2{font-size:18px;border-bottom:1px solid #ccc;padding-bottom:4px;margin-top:32px}
h3{font-size:15px;margin-top:20px}nav a{margin-right:14px}code,pre{font-family:ui-monospace,Menlo,Consolas,monospace;font-size:12.5px}
pre{background:#fff;border:1px solid #ddd;padding:10px;white-space:pre-wrap;overflow-wrap:anywhere}
details{margin:8px 0}details>summary{cursor:pointer;font-weight:600}
.gl-table{border-collapse:collapse;background:#fff;margin:8px 0}.gl-table td,.gl-table th{border:1px solid #ddd;padding:3px 8px;text-align:left;vertical-align:top}
.gl-table th{background:#f0f0f0}.gl-summary td:first-child{color:#555}
.gl-flag{display:inline-block;background:#fff3cd;color:#7a5a00;border:1px solid #e0c060;border-radius:3px;padding:0 5px;font-size:11px;font-weight:600}
tr.gl-assumed td{background:#fffbea}.gl-warn{color:#8a4b00}.gl-note{color:#555;font-style:italic}.gl-muted{color:#777}
.gl-grid{display:flex;flex-wrap:wrap;gap:10px}.gl-figure{margin:0;background:#fff;border:1px solid #ddd;padding:4px;max-width:600px}
.gl-figure figcaption{font-size:12px;color:#555;padding:0 8px 6px}.gl-map text{font-family:system-ui,sans-serif}
.gl-title{font-size:14px;font-weight:600}.gl-tick{font-size:11px}.gl-axis{font-size:12px}.gl-legend{font-size:11px}
.gl-worse{color:#b2182b;font-weight:600}.gl-better{color:#2166ac;font-weight:600}
footer{margin-top:40px;padding-bottom:30px;color:#555;font-size:12px;border-top:1px solid #ccc}
#gl-status[data-status=error]{color:#b00;font-weight:600}
.gl-table td{overflow-wrap:break-word}.gl-table td.gl-path,.gl-summary code{overflow-wrap:anywhere}.gl-keypoints td,.gl-ranking td{white-space:nowrap}
.gl-zero{background:#fff;border-left:3px solid #999;padding:4px 10px}
.gl-cell{font-size:9.5px;font-family:system-ui,sans-serif;pointer-events:none}
.gl-values{padding:0 8px 6px}.gl-values p{margin:2px 0;font-size:11px}
.gl-values-table{font-size:11px;margin:0}.gl-values-table td,.gl-values-table th{padding:1px 5px;text-align:right}
.gl-values-table td.gl-limit{outline:1.5px solid #d00;outline-offset:-2px}
@media print{
@page{size:A4;margin:12mm}
*{-webkit-print-color-adjust:exact;print-color-adjust:exact}
body{background:#fff;font-size:11px}header,main,footer{max-width:none;padding:0}nav{display:none}
h2{margin-top:18px;break-after:avoid}h3{break-after:avoid}
.gl-figure{break-inside:avoid;max-width:100%;border-color:#bbb}svg.gl-map{max-width:100%;height:auto}
.gl-table tr{break-inside:avoid}.gl-keypoints,.gl-ranking,.gl-summary{font-size:10px}
#summary{break-after:page}
}
)css";

// First in <head>: every script error and console error from here on is recorded.
constexpr const char* kErrorCapture = R"js(
window.__glErrors = [];
window.addEventListener('error', function (e) {
  window.__glErrors.push('error: ' + (e.message || (e.target && e.target.tagName) || 'unknown'));
}, true);
(function () {
  var original = console.error;
  console.error = function () {
    window.__glErrors.push('console: ' + Array.prototype.join.call(arguments, ' '));
    return original.apply(console, arguments);
  };
})();
)js";

// Last in <body>: checks the embedded data against the pictures and reports in #gl-status.
constexpr const char* kStatusScript = R"js(
(function () {
  function finish() {
    var errors = window.__glErrors || ['the error recorder did not run'];
    try {
      var d = JSON.parse(document.getElementById('gl-data').textContent);
      var maps = document.querySelectorAll('svg.gl-map').length;
      if (maps !== d.map_count) errors.push('expected ' + d.map_count + ' maps, found ' + maps);
      var n = d.oils[0].map.status.length;
      if (n !== d.grid.points) errors.push('expected ' + d.grid.points + ' points, found ' + n);
    } catch (e) {
      errors.push('data: ' + e.message);
    }
    var s = document.getElementById('gl-status');
    s.setAttribute('data-errors', String(errors.length));
    s.setAttribute('data-status', errors.length ? 'error' : 'ok');
    s.textContent = errors.length ? 'page errors: ' + errors.join('; ') : 'page loaded without errors';
  }
  if (document.readyState === 'complete') finish(); else window.addEventListener('load', finish);
})();
)js";

std::string case_name(const ReportData& d) { return d.reference.model.name; }

std::string case_section(const ReportData& d) {
    std::string s = "<section id=\"case\"><h2>The case</h2>\n";
    if (d.assumed.empty()) {
        s += "<p>Assumed values: none; every value the model needs is given by the case or its oil file.</p>\n";
    } else {
        s += fmt::format("<details id=\"assumed\"><summary>Assumed values: {} values the case does not give, filled in by the "
                         "loader (<span class=\"gl-flag\">ASSUMED</span>)</summary>",
                         d.assumed.size());
        s += "<table class=\"gl-table\"><thead><tr><th></th><th>key</th><th>value</th><th>reason</th><th>where</th></tr></thead><tbody>";
        for (const auto& a : d.assumed)
            s += fmt::format("<tr class=\"gl-assumed\"><td><span class=\"gl-flag\">ASSUMED</span></td><td><code>{}</code></td>"
                             "<td>{}</td><td>{}</td><td class=\"gl-path\">{}</td></tr>",
                             escape_html(a.key), escape_html(a.value), escape_html(a.reason), escape_html(a.location));
        s += "</tbody></table></details>\n";
    }
    s += fmt::format("<details><summary>Values as given in <code>{}</code> ({} values)</summary>\n", escape_html(d.reference.file),
                     d.given.size());
    s += "<table class=\"gl-table\"><thead><tr><th>key</th><th>value</th><th>line</th></tr></thead><tbody>";
    for (const auto& g : d.given) {
        const bool assumed = std::any_of(d.assumed.begin(), d.assumed.end(), [&](const AssumedValue& a) { return a.key == g.key; });
        s += fmt::format("<tr{}><td><code>{}</code></td><td>{}{}</td><td>{}</td></tr>", assumed ? " class=\"gl-assumed\"" : "",
                         escape_html(g.key), escape_html(g.value), assumed ? " <span class=\"gl-flag\">ASSUMED</span>" : "",
                         g.line > 0 ? std::to_string(g.line) : "");
    }
    return s + "</tbody></table></details></section>\n";
}

std::string checks_section(const ReportData& d) {
    std::string s = "<section id=\"checks\"><h2>Derived geometry and checks</h2>\n";
    const auto& w = d.reference.warnings;
    if (w.empty()) s += "<p>No plausibility warning.</p>\n";
    else {
        s += fmt::format("<p class=\"gl-warn\">{} plausibility warning{}:</p><ul>", w.size(), w.size() == 1 ? "" : "s");
        for (const auto& x : w) s += "<li class=\"gl-warn\">" + escape_html(x) + "</li>";
        s += "</ul>\n";
    }
    s += "<details id=\"check-dump\"><summary>As <code>gearloss check</code> prints it</summary><pre class=\"gl-dump\">" +
         escape_html(io::check_report(d.reference)) + "</pre></details></section>\n";
    return s;
}

std::string model_section(const ReportData& d) {
    const auto& m = d.reference.model;
    std::string s = "<section id=\"model\"><h2>Model forms and parameters</h2>\n"
                    "<p>Each loss mechanism with its alternative published forms (the case's choice in bold; the axes of "
                    "the model-form spread) and its parameters (SI).</p>\n"
                    "<table class=\"gl-table\"><thead><tr><th>mechanism</th><th>column</th><th>on</th><th>forms</th>"
                    "<th>parameters</th></tr></thead><tbody>";
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        const auto& mech = m.mechanisms[i];
        std::string forms, params;
        for (const auto& a : mech.forms(m)) {
            const std::string chosen = mech.form(m, a.axis);
            std::string list;
            for (const auto& f : a.forms) list += (list.empty() ? "" : ", ") + (f == chosen ? "<b>" + escape_html(f) + "</b>" : escape_html(f));
            forms += fmt::format("<div><code>{}.{}</code>: {}</div>", escape_html(mech.name()), escape_html(a.axis), list);
        }
        for (const auto& p : mech.parameters())
            params += fmt::format("<div><code>{}</code> = {}{}{} <span class=\"gl-muted\">({})</span></div>", escape_html(p.name),
                                  display_number(mech.value_in(m, p.name), 6), p.calibration ? " [calibration]" : "",
                                  mech.value_source(m, p.name) == losses::LossMechanism::Source::oil ? " [from the oil]" : "",
                                  escape_html(p.description));
        s += fmt::format("<tr><td>{}</td><td><code>{}</code></td><td>{}</td><td>{}</td><td>{}</td></tr>", escape_html(mech.label()),
                         escape_html(mech.column()), mech.enabled() ? "yes" : "off", forms.empty() ? "&#8211;" : forms,
                         params.empty() ? "&#8211;" : params);
    }
    return s + "</tbody></table></section>\n";
}

std::string footer(const ReportData& d) {
    std::string cmd;
    for (const auto& a : d.command_line) {
        const bool plain = !a.empty() && a.find_first_of(" \t'\"\\$`") == std::string::npos;
        std::string quoted = "'";
        for (char c : a) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
        cmd += (cmd.empty() ? "" : " ") + (plain ? a : quoted + "'");
    }
    return fmt::format("<footer><p>gearloss {} &#183; command line: <code>{}</code> &#183; case hash <code>{}</code> &#183; "
                       "maps solved in {} s</p><p id=\"gl-status\" data-status=\"pending\" data-errors=\"-1\">"
                       "page script did not run</p></footer>\n",
                       escape_html(d.version), escape_html(cmd), escape_html(d.case_hash), display_number(d.seconds, 3));
}

// The data behind the page, for its own check and for readers who want the numbers.
ordered_json summary_json(const ReportData& d, const ReportSummary& s) {
    ordered_json j;
    j["ratio_i"] = io::json_number(s.ratio_i);
    j["ratio_name"] = s.ratio_name;
    j["oil_limit_C"] = io::json_number(s.oil_limit_C);
    ordered_json points = ordered_json::array();
    for (const auto& p : s.key_points)
        points.push_back({{"role", p.role}, {"index", p.index}, {"speed_in_rpm", p.speed_rpm}, {"torque_in_Nm", p.torque_Nm},
                          {"efficiency", io::json_number(p.efficiency)}, {"oil_temp_C", p.oil_temp_C}, {"P_total_W", p.total_W}});
    j["key_points"] = std::move(points);
    ordered_json zero = ordered_json::array();
    for (size_t k : s.zero_mechanisms) zero.push_back(d.reference_map.model.mechanisms[k].name());
    j["zero_mechanisms"] = std::move(zero);
    ordered_json oils = ordered_json::array();
    for (const auto& o : s.oils)
        oils.push_back({{"name", o.name}, {"source", o.source}, {"reference", o.reference},
                        {"mean_P_total_W", io::json_number(o.mean_total_W)}, {"points", o.points}});
    j["oil_ranking"] = std::move(oils);
    return j;
}

ordered_json page_data(const ReportData& d, const ReportSummary& summary, size_t map_count) {
    ordered_json j;
    j["format"] = "gearloss-report/1";
    j["gearloss_version"] = d.version;
    j["command_line"] = d.command_line;
    j["case"] = {{"file", d.reference.file}, {"name", case_name(d)}, {"title", d.title}, {"hash", d.case_hash}};
    j["thermal"] = {{"mode", d.fixed_oil_temperature ? "fixed" : "stabilised"}, {"description", d.thermal}};
    j["grid"] = {{"is_grid", d.reference.grid.is_grid}, {"points", d.reference.grid.size()}};
    j["map_count"] = map_count;
    j["summary"] = summary_json(d, summary);
    ordered_json oils = ordered_json::array();
    const auto add = [&](const OilMap& m, const char* role) {
        oils.push_back({{"name", m.oil_name}, {"source", m.source}, {"role", role}, {"map", map_columns(m)}});
    };
    add(d.reference_map, "reference");
    for (const auto& k : d.comparisons) add(k, "comparison");
    j["oils"] = std::move(oils);
    j["assumed"] = io::assumed_json(d.assumed);
    j["check"] = ordered_json::parse(io::check_json(d.reference));
    return j;
}

}  // namespace

std::string html_report(const ReportData& d) {
    const MapAxes axes = map_axes(d.reference.grid);
    // The results first (summary, maps, oils, spread), then what they rest on (forms, the case, checks).
    const ReportSummary summary = summarise(d);
    std::string body = summary_section(d, summary) + maps_section(d, axes, summary) + comparison_section(d, axes) +
                       spread_section(d, axes) + model_section(d) + case_section(d) + checks_section(d);
    size_t maps = 0;
    for (size_t at = body.find("class=\"gl-map\""); at != std::string::npos; at = body.find("class=\"gl-map\"", at + 1)) ++maps;
    const std::string name = escape_html(case_name(d));
    std::string page = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
                       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    page += "<title>gearloss report: " + name + "</title>\n<script>" + kErrorCapture + "</script>\n<style>" + kStyle + "</style>\n";
    page += "</head><body>\n" + svg_pattern_defs() + "\n<header><h1>gearloss report: " + name + "</h1>\n";
    page += "<nav><a href=\"#summary\">summary</a><a href=\"#maps\">maps</a><a href=\"#oils\">oil comparison</a>"
            "<a href=\"#spread\">form spread</a><a href=\"#model\">model forms</a><a href=\"#case\">case</a>"
            "<a href=\"#checks\">geometry and checks</a></nav></header>\n";
    page += "<main>\n" + body + "</main>\n" + footer(d);
    page += "<script type=\"application/json\" id=\"gl-data\">" + json_for_script(page_data(d, summary, maps)) + "</script>\n";
    page += std::string("<script>") + kStatusScript + "</script>\n</body></html>\n";
    return page;
}

}  // namespace gearloss::report
