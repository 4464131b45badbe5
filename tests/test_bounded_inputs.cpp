// Issue 13, "Parsers are bounded" and the recordings parts of "diagnose never aborts":
// nesting depth in units and YAML, alias expansion, line and file sizes, only regular
// files, short printable excerpts in messages, component names, and recordings
// (duplicate rows, separators, bad cells, time stamps). Every file is written inside a
// private mkdtemp directory removed at the end; FIFOs are made there with mkfifo.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

#include "gearloss/core/errors.hpp"
#include "gearloss/diagnosis/recordings.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/case/drive_cycle_csv.hpp"
#include "gearloss/results/reports.hpp"
#include "gearloss/case/yaml_reader.hpp"
#include "test_support.hpp"
#include "gearloss/units/units.hpp"

using namespace gearloss;

namespace {
using test_support::TempDir;

namespace fs = std::filesystem;


std::string shipped(const std::string& file) {
    return test_support::read_file(test_support::source_path("configs/" + file));
}
std::string configs_dir() { return test_support::source_path("configs"); }

io::Case load_text(const std::string& text) { return io::load_case_text(text, "case.yaml", configs_dir()); }

// The InputError `f` throws (FAIL if it throws nothing or something else).
InputError input_error(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e;
    }
    FAIL("no InputError raised");
    throw std::logic_error("unreachable");
}

std::string units_error(const std::function<void()>& f) {
    try {
        f();
    } catch (const units::UnitError& e) {
        return e.message;
    }
    FAIL("no UnitError raised");
    return {};
}

std::string repeat(const std::string& s, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += s;
    return out;
}

// 64 levels of `aN: &aN [*aN-1, *aN-1]`: 1.5 KB that expand to 2^66 nodes.
std::string alias_bomb() {
    std::string t = "name: bomb\na0: &a0 [x, x]\n";
    for (int i = 1; i <= 64; ++i) t += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [*a" +
                                       std::to_string(i - 1) + ", *a" + std::to_string(i - 1) + "]\n";
    return t;
}

// Lines of a password/shadow file: every error about them must be told without quoting them.
const std::string kShadow =
    "root:$6$Zq9ab$SECRETHASHSECRETHASH:19000:0:99999:7:::\n"
    "daemon:*:19000:0:99999:7:::\n";
const std::string kPasswd = "root:x:0:0:root:/root:/bin/bash\ndaemon:x:1:1:daemon:/usr/sbin:/usr/sbin/nologin\n";

const std::string kRecHeader = "speed_in_rpm,torque_in_Nm,P_loss_W,oil_temp_C\n";
const std::string kLogHeader = "time_s,speed_in_rpm,speed_out_rpm,torque_in_Nm,torque_out_Nm,oil_temp_C,room_temp_C\n";

}  // namespace

// ---------------------------------------------------------------------------------------
TEST_CASE("units: parentheses nest at most 32 deep, no stack overflow", "[bounded][units]") {
    const auto nested = [](int n, const std::string& inner) { return repeat("(", n) + inner + repeat(")", n); };
    CHECK(units::parse_unit(nested(32, "N*m")).scale == 1.0);  // 32 levels: the bound itself
    CHECK(units::parse_quantity("2 " + nested(32, "mm")).value == Approx(2e-3));
    CHECK_THAT(units_error([&] { units::parse_unit(nested(33, "N*m")); }), Catch::Contains("unit nested too deeply"));
    // ~50 000 levels overflowed the stack of the recursive parser (SIGSEGV).
    const std::string deep = nested(50000, "Nm");
    const std::string msg = units_error([&] { units::parse_quantity("100 " + deep); });
    CHECK_THAT(msg, Catch::Contains("unit nested too deeply"));
    CHECK(msg.size() < 300);  // the expression is quoted as a short excerpt
    // Unbalanced opening parentheses alone: the same error, not a crash.
    CHECK_THAT(units_error([&] { units::parse_unit(repeat("(", 100000)); }), Catch::Contains("unit nested too deeply"));
}

TEST_CASE("units: scaling that overflows is out of range, never inf", "[bounded][units]") {
    for (const char* s : {"1e308 km", "-1e308 km", "1e308 kNm", "1.7e308 kW", "1e300 km^3"}) {
        INFO(s);
        CHECK_THAT(units_error([&] { units::parse_quantity(s); }), Catch::Contains("out of range"));
    }
    CHECK_THAT(units_error([] { units::parse_quantity("1e400 m"); }), Catch::Contains("out of range"));
    // Exponents are bounded (no int overflow in the dimension) and so is the scale:
    // (GPa/Pa) is dimensionless 1e9, raised to 36 it is 1e324 = inf.
    CHECK_THAT(units_error([] { units::parse_unit("((m^6)^6)^6"); }), Catch::Contains("exponent out of range"));
    CHECK_THAT(units_error([] { units::parse_unit("((GPa/Pa)^6)^6"); }), Catch::Contains("scale to SI units is out of range"));
    CHECK_THAT(units_error([] { units::parse_quantity("0 ((GPa/Pa)^6)^6"); }), Catch::Contains("out of range"));
    // The largest finite values still parse.
    CHECK(units::parse_quantity("1e308 m").value == 1e308);
    CHECK(units::parse_quantity("1e300 mm").value == Approx(1e297));
}

TEST_CASE("units: out of range everywhere parse_quantity is used", "[bounded][units]") {
    // Command-line value lists (--speed, --torque).
    const auto e1 = input_error([] { io::parse_value_list("1e308 kNm", units::dim::torque, "--torque", "250Nm"); });
    CHECK(e1.key == "--torque");
    CHECK_THAT(e1.message, Catch::Contains("out of range"));
    // A case file, at the line of the value.
    const std::string text =
        test_support::replace_once(shipped("transfer-box.yaml"), "oil_volume: 2 L", "oil_volume: 1e308 km^3");
    const auto e2 = input_error([&] { load_text(text); });
    CHECK_THAT(e2.message, Catch::Contains("out of range"));
    CHECK(e2.key == "housing.oil_volume");
    CHECK(e2.line == test_support::line_of(text, "oil_volume: 1e308"));
    // A unit nested too deeply in a file, spread over folded lines that each stay short.
    std::string folded = "oil_volume: 2";
    for (int i = 0; i < 5; ++i) folded += "\n    " + repeat("(", 10000);
    folded += "\n    L" + repeat(")", 50000);
    const auto e3 = input_error([&] { load_text(test_support::replace_once(shipped("transfer-box.yaml"), "oil_volume: 2 L", folded)); });
    CHECK_THAT(e3.message, Catch::Contains("unit nested too deeply"));
    CHECK(std::string(e3.what()).size() < 400);
}

// ---------------------------------------------------------------------------------------
TEST_CASE("YAML: nesting depth is bounded at 64 levels", "[bounded][yaml]") {
    const auto nested = [](int n) { return "a: " + repeat("[", n) + repeat("]", n) + "\n"; };
    CHECK_NOTHROW(io::YamlNode::load_text(nested(63), "x.yaml"));  // 63 + the top-level mapping = 64
    const auto e = input_error([&] { io::YamlNode::load_text(nested(64), "x.yaml"); });
    CHECK_THAT(e.message, Catch::Contains("YAML nested too deeply"));
    CHECK(e.line == 1);
    // Far deeper than yaml-cpp's own guard: the same error.
    CHECK_THAT(input_error([&] { io::YamlNode::load_text(nested(5000), "x.yaml"); }).message,
               Catch::Contains("nested too deeply"));
    // Depth reached through aliases counts too.
    std::string t = "a0: &a0 [x]\n";
    for (int i = 1; i <= 70; ++i) t += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [*a" + std::to_string(i - 1) + "]\n";
    CHECK_THAT(input_error([&] { io::YamlNode::load_text(t, "x.yaml"); }).message, Catch::Contains("nested too deeply"));
}

TEST_CASE("YAML: alias expansion is bounded by node count", "[bounded][yaml]") {
    const std::string bomb = alias_bomb();
    CHECK(bomb.size() < 6000);
    const auto e = input_error([&] { io::YamlNode::load_text(bomb, "bomb.yaml"); });
    CHECK_THAT(e.message, Catch::Contains("too many nodes after alias expansion"));
    CHECK(e.line > 1);
    // The same as a case (the path a user takes) and through load_case_text.
    CHECK_THAT(input_error([&] { load_text(bomb); }).message, Catch::Contains("too many nodes after alias expansion"));
    // Aliases in moderation are fine.
    CHECK_NOTHROW(io::YamlNode::load_text("a: &a [1, 2, 3]\nb: *a\nc: [*a, *a]\n", "x.yaml"));
    // An alias inside the node it names is a cycle.
    CHECK_THAT(input_error([] { io::YamlNode::load_text("a: &a [1, *a]\n", "x.yaml"); }).message,
               Catch::Contains("alias refers to a node that contains it"));
}

TEST_CASE("YAML: a second document is an error naming its line", "[bounded][yaml]") {
    struct Case {
        std::string text;
        int line;
    };
    for (const Case& c : {Case{"a: 1\n---\nb: 2\n", 2}, Case{"---\na: 1\n---\n{[broken\n", 3},
                          Case{"a: 1\n\n# comment\n---\n", 4}, Case{"a: 1\n--- ]]]\n", 2}}) {
        INFO(c.text);
        const auto e = input_error([&] { io::YamlNode::load_text(c.text, "two.yaml"); });
        CHECK_THAT(e.message, Catch::Contains("a second YAML document"));
        CHECK(e.line == c.line);
    }
    // An explicit end of the one document is fine.
    CHECK_NOTHROW(io::YamlNode::load_text("---\na: 1\n...\n", "one.yaml"));
    // A shipped case with a second document appended.
    const std::string text = shipped("transfer-box.yaml") + "---\nname: other\n";
    const auto e = input_error([&] { load_text(text); });
    CHECK_THAT(e.message, Catch::Contains("a second YAML document"));
    CHECK(e.line == test_support::line_of(text, "---\nname: other"));
}

TEST_CASE("input text: file size and line length are bounded, binary content refused", "[bounded][yaml][csv]") {
    TempDir dir;
    // A line longer than 64 KiB, at its line.
    const std::string longline = "a: 1\nb: " + std::string(70000, 'x') + "\n";
    auto e = input_error([&] { io::YamlNode::load_text(longline, "long.yaml"); });
    CHECK_THAT(e.message, Catch::Contains("line longer than 65536 bytes"));
    CHECK(e.line == 2);
    CHECK(std::string(e.what()).find("xxxx") == std::string::npos);
    CHECK_NOTHROW(io::YamlNode::load_text("a: " + std::string(60000, 'x') + "\n", "ok.yaml"));
    // More than 16 MiB of YAML text (lines short).
    std::string big;
    big.reserve(io::kMaxYamlFileBytes + 64);
    while (big.size() <= io::kMaxYamlFileBytes) big += "# padding padding padding padding padding padding padding\n";
    CHECK_THAT(input_error([&] { io::YamlNode::load_text(big, "big.yaml"); }).message, Catch::Contains("larger than 16 MiB"));
    // A file larger than the bound is refused from its size (sparse: nothing to read).
    const std::string sparse = dir.write("sparse.yaml", "");
    REQUIRE(::truncate(sparse.c_str(), static_cast<off_t>(io::kMaxYamlFileBytes + 1)) == 0);
    CHECK_THAT(input_error([&] { io::load_case(sparse); }).message, Catch::Contains("larger than 16 MiB"));
    CHECK_THAT(input_error([&] { io::read_input_file(sparse, io::kMaxYamlFileBytes); }).message,
               Catch::Contains("larger than 16 MiB"));
    // Binary content: a control byte, told by position, the bytes not quoted.
    std::string junk = "GIF89a\x01\x02\x03secretsecret";
    junk += std::string(1, '\0') + "more";
    const std::string jf = dir.write("junk.yaml", junk);
    e = input_error([&] { io::load_case(jf); });
    CHECK_THAT(e.message, Catch::Contains("control byte 0x01"));
    CHECK_THAT(e.message, Catch::Contains("not a text"));
    CHECK(std::string(e.what()).find("secret") == std::string::npos);
    CHECK(std::string(e.what()).find("GIF") == std::string::npos);
    CHECK(e.line == 1);
    CHECK(e.column == 7);
    // The same bounds for recordings text.
    CHECK_THAT(input_error([&] { diagnosis::read_recordings_text(kRecHeader + "600,150,210,50\x01\n", "r.csv"); }).message,
               Catch::Contains("control byte"));
}

// ---------------------------------------------------------------------------------------
TEST_CASE("only regular files are read: FIFOs, devices and directories are refused by name", "[bounded][files]") {
    TempDir dir;
    const std::string fifo = dir.fifo("input.fifo");
    const std::string tmp = dir.path.string();
    // Every reader of a user-named file. None may block on the FIFO or read a device.
    const std::vector<std::pair<std::string, std::function<void(const std::string&)>>> readers = {
        {"case", [](const std::string& f) { io::load_case(f); }},
        {"oil", [](const std::string& f) { io::load_oil_file(f); }},
        {"yaml", [](const std::string& f) { io::YamlNode::load_file(f); }},
        {"recordings", [](const std::string& f) { diagnosis::read_recordings(f); }},
        {"cycle", [](const std::string& f) { io::load_cycle_csv(f); }},
        {"cycle by name", [](const std::string& f) { io::resolve_cycle(f, {}); }},
    };
    std::vector<std::pair<std::string, std::string>> paths = {{fifo, "a FIFO"}, {tmp, "a directory"}};
    for (const char* dev : {"/dev/zero", "/dev/urandom", "/dev/null"})
        if (fs::exists(dev)) paths.push_back({dev, "a character device"});
    for (const auto& [name, read] : readers)
        for (const auto& [path, kind] : paths) {
            INFO(name << " " << path);
            const auto e = input_error([&] { read(path); });
            CHECK(e.file == path);
            CHECK_THAT(e.message, Catch::Contains("is not a regular file") && Catch::Contains(kind));
        }
    // A missing file, and a symbolic link to a regular file (read through).
    CHECK_THAT(input_error([&] { io::load_case(tmp + "/missing.yaml"); }).message, Catch::Contains("cannot open file"));
    const std::string oil = test_support::source_path("configs/oils/75W90-A.yaml");
    fs::create_symlink(oil, dir.path / "link.yaml");
    CHECK(io::load_oil_file((dir.path / "link.yaml").string()).name == "75W90-A");
    // A symbolic link to a FIFO is a FIFO.
    fs::create_symlink(fifo, dir.path / "fifo-link.yaml");
    CHECK_THAT(input_error([&] { io::load_case((dir.path / "fifo-link.yaml").string()); }).message,
               Catch::Contains("is not a regular file (a FIFO)"));
}

// ---------------------------------------------------------------------------------------
TEST_CASE("messages never quote a file that is not YAML or CSV, and quote at most 60 characters", "[bounded][excerpt]") {
    TempDir dir;
    for (const std::string& content : {kShadow, kPasswd}) {
        const std::string f = dir.write("secret", content);
        for (const auto& read : std::vector<std::function<void()>>{
                 [&] { io::load_case(f); }, [&] { io::load_oil_file(f); }, [&] { diagnosis::read_recordings(f); },
                 [&] { io::load_cycle_csv(f); }}) {
            const auto e = input_error(read);
            INFO(e.what());
            const std::string w = e.what();
            CHECK(w.find("root") == std::string::npos);
            CHECK(w.find("SECRET") == std::string::npos);
            CHECK(w.find("daemon") == std::string::npos);
            CHECK(w.find("19000") == std::string::npos);
        }
    }
    // A YAML mapping whose keys are not gearloss keys at all: said without quoting them.
    const auto e = input_error([&] { load_text("password: hunter2\nuser: root\n"); });
    CHECK_THAT(e.message, Catch::Contains("does not look like a gearloss file"));
    CHECK(std::string(e.what()).find("hunter2") == std::string::npos);
    // An unknown key that is not a plain name is not quoted, neither in the message nor in the key path.
    const std::string odd = test_support::replace_once(shipped("transfer-box.yaml"), "housing:\n",
                                                       "housing:\n  \"k$y:with/odd=chars\": 1\n");
    const auto e2 = input_error([&] { load_text(odd); });
    CHECK_THAT(e2.message, Catch::Contains("unknown key (not a plain name)"));
    CHECK(std::string(e2.what()).find("odd=chars") == std::string::npos);
    // A long value is quoted as a 60-character excerpt.
    const std::string longval = test_support::replace_once(shipped("transfer-box.yaml"), "teeth: 32",
                                                           "teeth: " + std::string(5000, 'z'));
    const auto e3 = input_error([&] { load_text(longval); });
    CHECK_THAT(e3.message, Catch::Contains("expected a whole number, got '" + std::string(60, 'z') + "...'"));
    CHECK(std::string(e3.what()).size() < 300);
    // Excerpts are printable: control bytes and broken UTF-8 become '?'.
    CHECK(io::excerpt("a\tb\x1b[31mc\xff\xfe" "d") == "a?b?[31mc??d");
    CHECK(io::excerpt("\xc2\xb5m \xc2\xb0""C") == "\xc2\xb5m \xc2\xb0""C");  // µm °C kept
    CHECK(io::excerpt(std::string(100, 'q')) == std::string(60, 'q') + "...");
    // A recordings cell quoted in an error is an excerpt too.
    const auto e4 = input_error([&] { diagnosis::read_recordings_text(kRecHeader + "600," + std::string(3000, 'w') + ",210,50\n", "r.csv"); });
    CHECK_THAT(e4.message, Catch::Contains(std::string(60, 'w') + "..."));
    CHECK(std::string(e4.what()).size() < 300);
}

// ---------------------------------------------------------------------------------------
TEST_CASE("component names: printable UTF-8, not empty, unique within their kind", "[bounded][names]") {
    const std::string tb = shipped("transfer-box.yaml");
    struct Bad {
        std::string from, to, line_of, message;
    };
    const std::vector<Bad> bad = {
        {"{name: w1,", "{name: \"w1\\nx\",", "{name: \"w1\\nx\"", "printable UTF-8"},           // a line break
        {"{name: w1,", "{name: \"w1\\tx\",", "{name: \"w1\\tx\"", "printable UTF-8"},           // a tab
        {"{name: w1,", "{name: \"\",", "{name: \"\"", "cannot be empty"},
        {"{name: w1,", "{name: \"w1,x\",", "{name: \"w1,x\"", "cannot contain ','"},
        {"{name: w1,", "{name: " + std::string(65, 'g') + ",", "{name: ggg", "at most 64 bytes"},
        {"shafts: [III, II, I]", "shafts: [III, II, \"I\\e\"]", "shafts: [III", "printable UTF-8"},  // ESC
        {"{name: output_seal,", "{name: input_seal,", "{name: input_seal, shaft: I", "duplicate seal name 'input_seal'"},
        {"{name: m24,", "{name: m12,", "{name: m12, gears: [w4", "duplicate mesh name 'm12'"},
        {"{name: B2_RMS10,", "{name: B5_NJ309E,", "{name: B5_NJ309E,   type: deep", "duplicate bearing name"},
        {"{name: w2,", "{name: w1,", "{name: w1, shaft: II", "duplicate gear name"},
        {"{name: N_w5,", "{name: N_w4.2,", "{name: N_w4.2", "duplicate bearing name 'N_w4.2'"},
    };
    for (const auto& b : bad) {
        const std::string text = test_support::replace_once(tb, b.from, b.to);
        INFO(b.to);
        const auto e = input_error([&] { load_text(text); });
        CHECK_THAT(e.message, Catch::Contains(b.message));
        CHECK(e.line == test_support::line_of(text, b.line_of));
    }
    // Raw bytes that are not UTF-8 (a Latin-1 name): an error, so check --json stays valid JSON.
    const std::string latin1 = test_support::replace_once(tb, "{name: w1,", "{name: \"w\xe4rme\",");
    const auto e = input_error([&] { load_text(latin1); });
    CHECK_THAT(e.message, Catch::Contains("printable UTF-8"));
    CHECK(e.line == test_support::line_of(latin1, "{name: \"w\xe4rme\""));
    CHECK(std::string(e.what()).find('\xe4') == std::string::npos);
    // Duplicate clutch names (six-speed automatic).
    const std::string at = test_support::replace_once(shipped("automatic-6speed.yaml"), "{name: C2,", "{name: C1,");
    const auto ec = input_error([&] { load_text(at); });
    CHECK_THAT(ec.message, Catch::Contains("duplicate clutch name 'C1'"));
    CHECK(ec.line == test_support::line_of(at, "{name: C1, engages: w2"));
    // UTF-8 names are fine and reach the JSON as written.
    const std::string utf8 = test_support::replace_once(
        test_support::replace_once(tb, "{name: w1,", "{name: \"Rad_\xc3\xbc\","), "[w2, w1]", "[w2, \"Rad_\xc3\xbc\"]");
    const auto c = load_text(utf8);
    CHECK(c.model.gearbox.gears[0].spec.name == "Rad_\xc3\xbc");
    CHECK_THAT(io::check_json(c), Catch::Contains("\"Rad_\xc3\xbc\""));
    // A case name with a line break.
    const std::string title = test_support::replace_once(tb, "name: Transfer gearbox (seed 001)", "name: \"Transfer\\nbox\"");
    CHECK_THAT(input_error([&] { load_text(title); }).message, Catch::Contains("printable UTF-8"));
}

// ---------------------------------------------------------------------------------------
TEST_CASE("recordings: exact duplicate rows are reported and counted once", "[bounded][recordings]") {
    const std::string text = kRecHeader + "600,150,210,50\n700,150,240,55\n600,150,210,50\n600,150,210.0,50\n";
    const auto r = diagnosis::read_recordings_text(text, "dup.csv");
    REQUIRE(r.points.size() == 3);  // 600,150,210.0 is not an exact duplicate
    REQUIRE(r.warnings.size() == 1);
    CHECK(r.warnings[0] == "dup.csv:4: row repeats line 2 exactly; counted once");
    // Rows keep their number in the file (for residuals and outliers).
    CHECK(r.points[0].row == 1);
    CHECK(r.points[1].row == 2);
    CHECK(r.points[2].row == 4);
    CHECK(r.points[2].line == 5);
    // Many duplicates: ten named, the rest counted.
    std::string many = kRecHeader;
    for (int i = 0; i < 25; ++i) many += "600,150,210,50\n";
    const auto m = diagnosis::read_recordings_text(many, "many.csv");
    CHECK(m.points.size() == 1);
    REQUIRE(m.warnings.size() == 11);
    CHECK(m.warnings.back() == "many.csv: 14 more rows repeat an earlier row exactly; each counted once");
    // In a raw log a repeated row (same time stamp) is merged too rather than an error.
    std::string log = kLogHeader;
    for (int i = 0; i < 20; ++i) {
        log += std::to_string(2 * i) + ",600,261,150,340,40,25\n";
        if (i == 5) log += std::to_string(2 * i) + ",600,261,150,340,40,25\n";
    }
    const auto l = diagnosis::read_recordings_text(log, "log.csv");
    REQUIRE(l.warnings.size() >= 1);
    CHECK(l.warnings[0] == "log.csv:8: row repeats line 7 exactly; counted once");
}

TEST_CASE("recordings: semicolon- and tab-separated files are read, decimal commas named", "[bounded][recordings]") {
    // A spreadsheet saved in a locale with decimal commas: ';' between cells is detected from the
    // header, the decimal comma is refused at its cell with the separator named.
    const auto semi = input_error(
        [] { diagnosis::read_recordings_text("speed_in_rpm;torque_in_Nm;P_loss_W\n600;150;210,5\n", "semi.csv"); });
    CHECK_THAT(semi.message, Catch::Contains("'210,5' has a decimal comma") &&
                                 Catch::Contains("the columns are separated by ';' (detected)"));
    CHECK(semi.line == 2);
    CHECK(semi.column == 3);
    // With '.' decimals the same file is read as its comma-separated twin.
    const auto comma = diagnosis::read_recordings_text("speed_in_rpm,torque_in_Nm,P_loss_W\n600,150,210.5\n", "c.csv");
    const auto semi_ok = diagnosis::read_recordings_text("speed_in_rpm;torque_in_Nm;P_loss_W\n600;150;210.5\n", "s.csv");
    const auto tab = diagnosis::read_recordings_text("speed_in_rpm\ttorque_in_Nm\tP_loss_W\n600\t150\t210.5\n", "tab.csv");
    for (const auto* r : {&semi_ok, &tab}) {
        REQUIRE(r->points.size() == 1);
        CHECK(r->points[0].loss == comma.points[0].loss);
        CHECK(r->points[0].torque_in == comma.points[0].torque_in);
        CHECK(r->points[0].speed_in == comma.points[0].speed_in);
    }
    // A comma header over semicolon rows: the cell count error carries the hint, at the row's line.
    const auto rows = input_error([] { diagnosis::read_recordings_text(kRecHeader + "600;150;210,5;50\n", "rows.csv"); });
    CHECK_THAT(rows.message, Catch::Contains("cells") && Catch::Contains("looks semicolon-separated"));
    CHECK(rows.line == 2);
    // Cycle files too: read with ';', a decimal comma named at its cell.
    TempDir dir;
    const auto cyc = io::load_cycle_csv(dir.write("cycle.csv", "time_s;speed_kmh\n0;0\n1;5\n"));
    CHECK(cyc.time.size() == 2);
    CHECK(cyc.speed[1] == 5 / 3.6);
    const auto dc = input_error([&] { io::load_cycle_csv(dir.write("dc.csv", "time_s;speed_kmh\n0;0\n1;5,5\n")); });
    CHECK_THAT(dc.message, Catch::Contains("'5,5' has a decimal comma") && Catch::Contains("separated by ';' (detected)"));
    CHECK(dc.line == 3);
}

TEST_CASE("recordings: bad cells are errors with line and column", "[bounded][recordings]") {
    struct Bad {
        std::string row;
        int column;
        std::string key, message;
    };
    for (const Bad& b : {Bad{"600,abc,210,50", 2, "torque_in_Nm", "'abc' is not a number"},
                         Bad{"600,150,,50", 3, "P_loss_W", "empty loss cell"},
                         Bad{",150,210,50", 1, "speed_in_rpm", "empty cell"},
                         Bad{"600,150,nan,50", 3, "P_loss_W", "out of range"},
                         Bad{"600,150,inf,50", 3, "P_loss_W", "out of range"},
                         Bad{"600,-inf,210,50", 2, "torque_in_Nm", "out of range"},
                         Bad{"600,150,1e999,50", 3, "P_loss_W", "out of range"},
                         Bad{"-600,150,210,50", 1, "speed_in_rpm", "negative speed"},
                         Bad{"600,150,210,-300", 4, "oil_temp_C", "below absolute zero"}}) {
        INFO(b.row);
        const auto e = input_error([&] { diagnosis::read_recordings_text(kRecHeader + "600,150,210,50\n" + b.row + "\n", "bad.csv"); });
        CHECK(e.line == 3);
        CHECK(e.column == b.column);
        CHECK(e.key == b.key);
        CHECK_THAT(e.message, Catch::Contains(b.message));
    }
    // A unit scale that overflows in SI units (1e306 kW).
    const auto kw = input_error([] {
        diagnosis::read_recordings_text("speed_in_rpm,torque_in_Nm,P_loss_kW\n600,150,1e306\n", "kw.csv");
    });
    CHECK(kw.line == 2);
    CHECK(kw.column == 3);
    CHECK_THAT(kw.message, Catch::Contains("out of range"));
    // Speeds, torques and losses beyond the ranges the model states (gearloss/model/validate.hpp) are
    // errors at their cell: a loss of 1e155 W made a residual statistic of the diagnosis
    // overflow (an internal error) before.
    const auto pw = input_error([] {
        diagnosis::read_recordings_text("speed_in_rpm,torque_in_Nm,speed_out_rpm,torque_out_Nm\n1e300,1e300,1,1\n", "pw.csv");
    });
    CHECK(pw.line == 2);
    CHECK(pw.column == 1);
    CHECK_THAT(pw.message, Catch::Contains("beyond the stated range"));
    const auto big = input_error([] {
        diagnosis::read_recordings_text("speed_in_rpm,torque_in_Nm,P_loss_W\n600,150,210\n800,150,1e155\n", "big.csv");
    });
    CHECK(big.line == 3);
    CHECK(big.column == 3);
    CHECK_THAT(big.message, Catch::Contains("beyond the stated range"));
    const auto tq = input_error([] {
        diagnosis::read_recordings_text("speed_in_rpm,torque_in_Nm,P_loss_W\n600,-2e8,210\n", "tq.csv");
    });
    CHECK(tq.column == 2);
    // A label that is not UTF-8 (JSON output must stay valid).
    const auto lab = input_error([] {
        diagnosis::read_recordings_text("speed_in_rpm,torque_in_Nm,P_loss_W,label\n600,150,210,caf\xe9\n", "lab.csv");
    });
    CHECK(lab.line == 2);
    CHECK(lab.column == 4);
    CHECK_THAT(lab.message, Catch::Contains("printable UTF-8"));
}

TEST_CASE("recordings: time stamps near 5e18 and non-finite numbers are errors, never loops", "[bounded][recordings]") {
    // At 5e18 s a double steps by 1024 s: the 300 s stabilisation blocks never advanced.
    std::string log = kLogHeader;
    for (int i = 0; i < 40; ++i) log += fmt::format("{:.17g},600,261,150,340,40,25\n", 5e18 + 2048.0 * i);
    const auto e = input_error([&] { diagnosis::read_recordings_text(log, "far.csv"); });
    CHECK(e.line == 2);
    CHECK(e.column == 1);
    CHECK(e.key == "time_s");
    CHECK_THAT(e.message, Catch::Contains("out of range"));
    // Unix time stamps are fine.
    std::string unix_log = kLogHeader;
    for (int i = 0; i < 1000; ++i) unix_log += fmt::format("{},600,261,150,340,40,25\n", 1700000000 + 2 * i);
    const auto r = diagnosis::read_recordings_text(unix_log, "unix.csv");
    REQUIRE(r.points.size() == 1);
    CHECK(std::isfinite(r.points[0].stabilisation_drift));
    // Non-finite time or temperature cells.
    for (const char* row : {"nan,600,261,150,340,40,25", "inf,600,261,150,340,40,25", "0,600,261,150,340,inf,25"}) {
        INFO(row);
        const auto f = input_error([&] { diagnosis::read_recordings_text(kLogHeader + row + "\n2,600,261,150,340,40,25\n", "nf.csv"); });
        CHECK(f.line == 2);
        CHECK(f.column > 0);
        CHECK_THAT(f.message, Catch::Contains("out of range"));
    }
    // time in minutes is converted before the bound.
    const std::string minutes = "time_min,speed_in_rpm,speed_out_rpm,torque_in_Nm,torque_out_Nm,oil_temp_C,room_temp_C\n"
                                "1e11,600,261,150,340,40,25\n";
    CHECK_THAT(input_error([&] { diagnosis::read_recordings_text(minutes, "min.csv"); }).message, Catch::Contains("out of range"));
}

TEST_CASE("recordings: a header with no known column is not quoted", "[bounded][recordings]") {
    const auto e = input_error([] { diagnosis::read_recordings_text(kShadow, "shadow"); });
    CHECK_THAT(e.message, Catch::Contains("not a gearloss recordings CSV file"));
    CHECK(std::string(e.what()).find("root") == std::string::npos);
}
