// The HTML report's renderer (lib/gearloss/report/): escaping, colour sense, the flags of
// assumed values, the embedded data against the map machinery, self-containment. The CLI
// and the rendering in a browser are tested by tests/report_content.py and report_render.sh.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <regex>

#include "gearloss/map/map_runner.hpp"
#include "gearloss/report/html.hpp"
#include "gearloss/report/html_report.hpp"
#include "gearloss/report/map_values.hpp"
#include "gearloss/report/pdf_print.hpp"
#include "gearloss/report/report_summary.hpp"
#include "gearloss/report/report_run.hpp"
#include "gearloss/report/svg_map.hpp"
#include "test_support.hpp"

using namespace gearloss;

namespace {

// The report data of the transfer box on a 3 x 3 grid at a fixed 80 degC (fast), without spread.
report::ReportData small_report(std::vector<std::string> oils = {}) {
    report::ReportRequest q;
    q.config = test_support::source_path("configs/transfer-box.yaml");
    q.oils = std::move(oils);
    q.spread = false;
    q.prepare = [](io::Case c, const std::string&) {
        c.grid = test_support::rpm_grid({500, 1500, 3000}, {50, 150, 300});
        c.model.thermal.mode = solver::ThermalMode::fixed;
        c.model.thermal.oil_temperature = 353.15;
        return c;
    };
    q.command_line = {"gearloss", "report", "x.yaml", "-o", "r.html"};
    return report::collect_report(q);
}

}  // namespace

TEST_CASE("report: user text is escaped for HTML and for embedded JSON", "[report]") {
    CHECK(report::escape_html("<script>alert('x')</script> & \"q\"") ==
          "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;q&quot;");
    const std::string j = report::json_for_script(nlohmann::ordered_json{{"name", "</script><b>&"}});
    CHECK(j.find('<') == std::string::npos);
    CHECK(j.find('>') == std::string::npos);
    CHECK(j.find('&') == std::string::npos);
    // The escapes decode to the same text (a JSON reader sees the user's string unchanged).
    CHECK(nlohmann::json::parse(j)["name"] == "</script><b>&");
    CHECK(nlohmann::json::parse(report::json_for_script(nlohmann::ordered_json{{"x", NAN}}))["x"].is_null());
}

TEST_CASE("report: differences use one colour sense, red worse and blue better", "[report]") {
    // The RdBu scheme's ends (Harrower & Brewer 2003): red #b2182b, blue #2166ac; zero difference is white-ish.
    CHECK(report::scale_colour(report::ColourSense::higher_is_worse, 1.0) == "#b2182b");   // more loss
    CHECK(report::scale_colour(report::ColourSense::higher_is_worse, 0.0) == "#2166ac");   // less loss
    CHECK(report::scale_colour(report::ColourSense::higher_is_better, 1.0) == "#2166ac");  // more efficiency
    CHECK(report::scale_colour(report::ColourSense::higher_is_better, 0.0) == "#b2182b");
    CHECK(report::scale_colour(report::ColourSense::higher_is_worse, 0.5) == "#f7f7f7");
}

TEST_CASE("report: nice ticks are 1, 2, 2.5 or 5 times a power of ten inside the range", "[report]") {
    const auto t = report::nice_ticks(0.13, 0.97, 6);  // step 0.2 by hand: 0.2 .. 0.8
    REQUIRE(t.size() == 4);
    CHECK(t.front() == Approx(0.2));
    CHECK(t.back() == Approx(0.8));
    CHECK(report::nice_ticks(80, 80, 6).size() == 1);
}

TEST_CASE("report: the page's data are the map machinery's numbers", "[report]") {
    const auto d = small_report();
    const std::string page = report::html_report(d);
    // Another route to the same points: run_map on the case loaded by load_case.
    io::Case k = test_support::load_shipped("configs/transfer-box.yaml");
    k.grid = test_support::rpm_grid({500, 1500, 3000}, {50, 150, 300});
    k.model.thermal.mode = solver::ThermalMode::fixed;
    k.model.thermal.oil_temperature = 353.15;
    const auto rs = map::run_map(k.model, k.grid, {});
    const auto at = page.find("id=\"gl-data\">");
    REQUIRE(at != std::string::npos);
    const auto end = page.find("</script>", at);
    const auto data = nlohmann::json::parse(page.substr(at + 13, end - at - 13));
    const auto& cols = data["oils"][0]["map"];
    REQUIRE(cols["P_total_W"].size() == rs.size());
    for (size_t i = 0; i < rs.size(); ++i) {
        CHECK(cols["P_total_W"][i].get<double>() == Approx(rs[i].losses.total()).epsilon(1e-12));
        CHECK(cols["efficiency"][i].get<double>() == Approx(rs[i].efficiency).epsilon(1e-12));
        CHECK(cols["status"][i] == solver::status_text(rs[i]));
    }
    // One map per mechanism that has a loss somewhere besides efficiency, temperature and total
    // loss; no spread, no oil.
    size_t lossy = 0;
    for (size_t q = 0; q < k.model.mechanisms.size(); ++q)
        lossy += std::any_of(rs.begin(), rs.end(), [q](const auto& r) { return r.losses.power[q] != 0; });
    CHECK(lossy < k.model.mechanisms.size());  // the transfer box has no windage, clutch or auxiliary loss
    CHECK(data["map_count"] == 3 + lossy);
    CHECK(page.find("fixed at 80.0 degC") != std::string::npos);
}

TEST_CASE("report: assumed values are flagged where they are listed and where the case gives the key", "[report]") {
    auto d = small_report();
    d.assumed = {{"name", "Transfer gearbox", "a test <reason>", "case.yaml:5:1"}};
    const std::string page = report::html_report(d);
    CHECK(page.find("a test &lt;reason&gt;") != std::string::npos);
    // The table row of the listed value and the row of the given key `name` both carry the flag.
    const std::regex flagged_row("<tr class=\"gl-assumed\"><td><code>name</code></td><td>[^<]*<span class=\"gl-flag\">ASSUMED</span>");
    CHECK(std::regex_search(page, flagged_row));
}

TEST_CASE("report: the page names no external resource", "[report]") {
    const std::string page = report::html_report(small_report({test_support::source_path("configs/oils/75W140-A.yaml")}));
    CHECK(page.find("http://") == std::string::npos);
    CHECK(page.find("https://") == std::string::npos);
    CHECK(!std::regex_search(page, std::regex(R"((src|href)\s*=\s*["']?\s*[a-zA-Z]*:?//)")));
    CHECK(page.find("<link") == std::string::npos);
    CHECK(page.find("oil k &#8722; reference") != std::string::npos);
}

TEST_CASE("report: a grid beyond 32 x 32 points is down-sampled evenly, ends kept, and the page says so", "[report]") {
    // 100 speeds x 50 torques = 5000 points > 1024: 32 speeds (indices round(k 99 / 31), the
    // first 500 and last 3470 rpm kept) x 32 torques (round(k 49 / 31): 20 and 314 N m kept).
    std::vector<double> sp, tq;
    for (int i = 0; i < 100; ++i) sp.push_back(500 + 30 * i);
    for (int i = 0; i < 50; ++i) tq.push_back(20 + 6 * i);
    report::ReportRequest q;
    q.config = test_support::source_path("configs/transfer-box.yaml");
    q.spread = false;
    q.prepare = [&](io::Case c, const std::string&) {
        c.grid = test_support::rpm_grid(sp, tq);
        c.model.thermal.mode = solver::ThermalMode::fixed;
        c.model.thermal.oil_temperature = 353.15;
        return c;
    };
    q.command_line = {"gearloss", "report", "x.yaml", "-o", "r.html"};
    const auto d = report::collect_report(q);
    REQUIRE(d.reference_map.results.size() == 32 * 32);
    const auto& g = d.reference.grid;
    REQUIRE(g.speeds.size() == 32);
    CHECK(g.speeds.front() * 30 / M_PI == Approx(500));
    CHECK(g.speeds[1] * 30 / M_PI == Approx(500 + 30 * 3));  // round(99 / 31) = 3
    CHECK(g.speeds.back() * 30 / M_PI == Approx(3470));
    REQUIRE(g.torques.size() == 32);
    CHECK(g.torques.front() == Approx(20));
    CHECK(g.torques.back() == Approx(314));
    bool noted = false;
    for (const auto& n : d.sweep_notes) noted |= n.find("5000 points (100 speeds x 50 torques)") != std::string::npos;
    CHECK(noted);
    CHECK(report::html_report(d).find("computes every point") != std::string::npos);
}

TEST_CASE("report: printed cell values and whether they fit their cells", "[report]") {
    CHECK(report::label_text(97.8349, 4) == "97.83");
    CHECK(report::label_text(1234.4, 3) == "1234");  // no decimals at or above the digits asked
    CHECK(report::label_text(45.67, 3) == "45.7");
    CHECK(report::label_text(0.012345, 3) == "0.012");  // at most 3 decimals
    CHECK(report::label_text(-0.0001, 3) == "0.000");   // no "-0.000"
    CHECK(report::label_text(NAN, 3).empty());
    // "97.83": 5 characters of 0.6 x 9.5 px plus 4 px of margin = 32.5 px wide, 12.5 px high.
    report::MapField f;
    f.values = {97.8349, NAN};
    f.label_digits = 4;
    CHECK(report::labels_fit(f, 33, 13));
    CHECK(!report::labels_fit(f, 32, 13));
    CHECK(!report::labels_fit(f, 33, 12));
    // 3 x 3 points on a 380 x 260 px plot: cells of 127 x 87 px, labels fit; 40 speeds: 9.5 px, they do not.
    report::MapAxes a;
    a.speeds_rpm = {500, 1500, 3000};
    a.torques_Nm = {50, 150, 300};
    for (double n : a.speeds_rpm)
        for (double T : a.torques_Nm) a.points.emplace_back(n, T);
    f.values.assign(9, 97.5);
    f.states.assign(9, report::CellState::value);
    f.id = "m";
    CHECK(report::cell_labels_shown(a, f));
    CHECK(report::values_table(a, f).empty());
    const std::string svg = report::svg_map(a, f);
    CHECK(std::regex_search(svg, std::regex(R"(class="gl-cell" fill="#[0-9a-f]{3}" data-i="8">97\.50</text>)")));
    a.speeds_rpm.clear();
    a.points.clear();
    for (int i = 0; i < 40; ++i) a.speeds_rpm.push_back(500 + 100 * i);
    for (double n : a.speeds_rpm)
        for (double T : a.torques_Nm) a.points.emplace_back(n, T);
    f.values.assign(120, 97.5);
    f.states.assign(120, report::CellState::value);
    CHECK(!report::cell_labels_shown(a, f));
    const std::string table = report::values_table(a, f);
    CHECK(table.find("12 of 40 speeds and 3 of 3 torques") != std::string::npos);
    CHECK(table.find("<th>500</th>") != std::string::npos);   // the first speed kept
    CHECK(table.find("<th>4400</th>") != std::string::npos);  // and the last
}

TEST_CASE("report: the summary's ratio, key points, zero mechanisms and oils against the solved points", "[report]") {
    const auto d = small_report({test_support::source_path("configs/oils/75W140-A.yaml")});
    const auto s = report::summarise(d);
    // 'low' by hand from the teeth: 17 -> 28 then 23 -> 32, n_out/n_in = 17/28 * 23/32 = 0.4363839,
    // i = 2.291560.
    CHECK(s.ratio_i == Approx(28.0 / 17 * 32 / 23).epsilon(1e-9));
    CHECK(s.ratio_name == "low");
    // At a fixed 80 degC every point has values; rated: 3000 rpm x 300 N m, the last point,
    // which is also the best (one row, named so); the worst is another.
    const auto& rs = d.reference_map.results;
    size_t best = 0, worst = 0;
    for (size_t i = 0; i < rs.size(); ++i) {
        if (rs[i].efficiency > rs[best].efficiency) best = i;
        if (rs[i].efficiency < rs[worst].efficiency) worst = i;
    }
    REQUIRE(best == 8);
    REQUIRE(worst != 8);
    REQUIRE(s.key_points.size() == 2);
    CHECK(s.key_points[0].index == 8);
    CHECK(s.key_points[0].role == "rated (highest input power), best efficiency");
    CHECK(s.key_points[0].speed_rpm == Approx(3000));
    CHECK(s.key_points[0].torque_Nm == Approx(300));
    CHECK(s.key_points[1].index == worst);
    CHECK(s.key_points[1].role == "worst efficiency");
    // Zero mechanisms: those whose loss is 0 at all nine points, and only those.
    const auto& m = d.reference_map.model;
    for (size_t k = 0; k < m.mechanisms.size(); ++k) {
        const bool zero = std::all_of(rs.begin(), rs.end(), [k](const auto& r) { return r.losses.power[k] == 0; });
        CHECK(zero == (std::find(s.zero_mechanisms.begin(), s.zero_mechanisms.end(), k) != s.zero_mechanisms.end()));
    }
    const std::string page = report::html_report(d);
    CHECK(page.find("windage: 0 W everywhere") != std::string::npos);
    CHECK(page.find("id=\"map-loss-windage\"") == std::string::npos);
    // Two oils, ranked by their mean total loss over the nine points.
    REQUIRE(s.oils.size() == 2);
    double a = 0, b = 0;
    for (size_t i = 0; i < rs.size(); ++i) a += rs[i].losses.total(), b += d.comparisons[0].results[i].losses.total();
    CHECK(s.oils[0].mean_total_W == Approx(std::min(a, b) / 9).epsilon(1e-12));
    CHECK(s.oils[0].reference == (a <= b));
    CHECK(page.find("<td>oils compared</td><td><b>2</b>: 75W90-A") != std::string::npos);
}

TEST_CASE("report: --pdf without Chromium is an error naming the option", "[report]") {
    const char* old = std::getenv("CHROMIUM");
    const std::string saved = old ? old : "";
    ::setenv("CHROMIUM", "/no/such/chromium", 1);
    CHECK(report::find_chromium().empty());
    try {
        report::print_pdf("<html></html>", "--pdf");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.key == "--pdf");
        CHECK(std::string(e.what()).find("CHROMIUM=/no/such/chromium") != std::string::npos);
    }
    if (old) ::setenv("CHROMIUM", saved.c_str(), 1);
    else ::unsetenv("CHROMIUM");
}
