#include "gearloss/report/html_report.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "gearloss/io/reports.hpp"
#include "gearloss/report/html.hpp"
#include "gearloss/report/report_maps.hpp"

namespace gearloss::report {
namespace {

using nlohmann::ordered_json;

constexpr const char* kStyle = R"css(
body{font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;margin:0;color:#222;background:#fafafa}
header,main,footer{max-width:1280px;margin:0 auto;padding:0 24px}
header{padding-top:16px}h1{font-size:22px;margin:8px 0}h2{font-size:18px;border-bottom:1px solid #ccc;padding-bottom:4px;margin-top:32px}
h3{font-size:15px;margin-top:20px}nav a{margin-right:14px}code,pre{font-family:ui-monospace,Menlo,Consolas,monospace;font-size:12.5px}
pre{background:#fff;border:1px solid #ddd;padding:10px;overflow-x:auto}
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

std::string summary_table(const ReportData& d) {
    const auto& k = d.reference;
    size_t with_values = 0, no_eq = 0, out = 0, above = 0;
    for (const auto& r : d.reference_map.results) {
        with_values += solver::has_values(r.status);
        no_eq += r.status == solver::PointStatus::no_equilibrium;
        out += r.status == solver::PointStatus::out_of_range;
        above += r.status == solver::PointStatus::above_oil_limit;
    }
    std::string s = "<table class=\"gl-table gl-summary\">";
    const auto row = [&](const std::string& a, const std::string& b) { s += "<tr><td>" + a + "</td><td>" + b + "</td></tr>"; };
    row("case file", "<code>" + escape_html(k.file) + "</code>");
    row("name", escape_html(case_name(d)));
    if (!d.title.empty()) row("title", escape_html(d.title));
    row("oil", escape_html(d.reference_map.oil_name) + " <span class=\"gl-muted\">(" + escape_html(d.reference_map.source) + ")</span>");
    row("oil temperature", escape_html(d.thermal));
    row("ratio", k.model.ratio.empty() ? "&#8211;" : escape_html(k.model.ratio) + fmt::format(" (n_out/n_in = {})", display_number(k.model.layout.ratio, 6)));
    row("operating points", fmt::format("{} ({}); {} with values, {} without equilibrium, {} out of range, {} above the oil's limit",
                                        k.grid.size(), k.grid.is_grid ? fmt::format("{} speeds &#215; {} torques", k.grid.speeds.size(), k.grid.torques.size()) : "point list",
                                        with_values, no_eq, out, above));
    row("oils compared", fmt::format("{}", d.comparisons.size()));
    row("case hash", "<code>" + escape_html(d.case_hash) + "</code>");
    return s + "</table>\n";
}

std::string case_section(const ReportData& d) {
    std::string s = "<section id=\"case\"><h2>The case</h2>\n";
    for (const auto& n : d.sweep_notes) s += "<p class=\"gl-note\">" + escape_html(n) + "</p>\n";
    s += "<h3>Assumed values</h3>\n";
    if (d.assumed.empty()) {
        s += "<p>None: every value the model needs is given by the case or its oil file.</p>\n";
    } else {
        s += "<p>Values the case does not give, filled in by the loader (<span class=\"gl-flag\">ASSUMED</span>):</p>"
             "<table class=\"gl-table\"><thead><tr><th></th><th>key</th><th>value</th><th>reason</th><th>where</th></tr></thead><tbody>";
        for (const auto& a : d.assumed)
            s += fmt::format("<tr class=\"gl-assumed\"><td><span class=\"gl-flag\">ASSUMED</span></td><td><code>{}</code></td>"
                             "<td>{}</td><td>{}</td><td>{}</td></tr>",
                             escape_html(a.key), escape_html(a.value), escape_html(a.reason), escape_html(a.location));
        s += "</tbody></table>\n";
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
    s += "<details open><summary>As <code>gearloss check</code> prints it</summary><pre>" +
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
ordered_json page_data(const ReportData& d, size_t map_count) {
    ordered_json j;
    j["format"] = "gearloss-report/1";
    j["gearloss_version"] = d.version;
    j["command_line"] = d.command_line;
    j["case"] = {{"file", d.reference.file}, {"name", case_name(d)}, {"title", d.title}, {"hash", d.case_hash}};
    j["thermal"] = {{"mode", d.fixed_oil_temperature ? "fixed" : "stabilised"}, {"description", d.thermal}};
    j["grid"] = {{"is_grid", d.reference.grid.is_grid}, {"points", d.reference.grid.size()}};
    j["map_count"] = map_count;
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
    std::string body = case_section(d) + checks_section(d) + model_section(d) + maps_section(d, axes) +
                       spread_section(d, axes) + comparison_section(d, axes);
    size_t maps = 0;
    for (size_t at = body.find("class=\"gl-map\""); at != std::string::npos; at = body.find("class=\"gl-map\"", at + 1)) ++maps;
    const std::string name = escape_html(case_name(d));
    std::string page = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
                       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    page += "<title>gearloss report: " + name + "</title>\n<script>" + kErrorCapture + "</script>\n<style>" + kStyle + "</style>\n";
    page += "</head><body>\n" + svg_pattern_defs() + "\n<header><h1>gearloss report: " + name + "</h1>\n" + summary_table(d);
    page += "<nav><a href=\"#case\">case</a><a href=\"#checks\">geometry and checks</a><a href=\"#model\">model forms</a>"
            "<a href=\"#maps\">maps</a><a href=\"#spread\">form spread</a><a href=\"#oils\">oil comparison</a></nav></header>\n";
    page += "<main>\n" + body + "</main>\n" + footer(d);
    page += "<script type=\"application/json\" id=\"gl-data\">" + json_for_script(page_data(d, maps)) + "</script>\n";
    page += std::string("<script>") + kStatusScript + "</script>\n</body></html>\n";
    return page;
}

}  // namespace gearloss::report
