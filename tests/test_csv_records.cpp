// The CSV reader of input files (io::CsvReader): RFC 4180 records (Shafranovich 2005) and the
// separator detected from the header. Expected cells are written out by hand from the text.
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "gearloss/core/errors.hpp"
#include "gearloss/diagnosis/recordings.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/io/csv_records.hpp"

using namespace gearloss;
using Cells = std::vector<std::string>;

namespace {
struct Read {
    std::vector<Cells> records;
    std::vector<int> lines;
    char separator = 0;
};
Read read_all(const std::string& text) {
    io::CsvReader csv(text, "t.csv");
    io::CsvRecord r;
    Read out;
    while (csv.next(r)) {
        out.records.push_back(r.cells);
        out.lines.push_back(r.line);
    }
    out.separator = csv.separator();
    return out;
}
InputError error_of(const std::string& text) {
    try {
        read_all(text);
    } catch (const InputError& e) {
        return e;
    }
    FAIL("no InputError");
    return InputError("");
}
}  // namespace

TEST_CASE("csv: quoted cells hold the separator, doubled quotes and line breaks", "[csv]") {
    const std::string text = "name,comment,x\n"
                             "\"a, b\",\"say \"\"hi\"\"\",1\n"
                             "\"two\nlines\",plain ,  2  \n"
                             "last,\"\",3\n";
    const Read r = read_all(text);
    REQUIRE(r.records.size() == 4);
    CHECK(r.separator == ',');
    CHECK(r.records[1] == Cells{"a, b", "say \"hi\"", "1"});
    // A line break inside quotes belongs to the cell; the record after it starts on line 5.
    CHECK(r.records[2] == Cells{"two\nlines", "plain", "2"});
    CHECK(r.records[3] == Cells{"last", "", "3"});
    CHECK(r.lines == std::vector<int>{1, 2, 3, 5});
}

TEST_CASE("csv: CRLF line ends, a byte-order mark, comments and blank lines", "[csv]") {
    const Read r = read_all("\xEF\xBB\xBFtime_s,speed_kmh\r\n# a comment\r\n\r\n0,0\r\n1,\"5\r\n\"\r\n");
    REQUIRE(r.records.size() == 3);
    CHECK(r.records[0] == Cells{"time_s", "speed_kmh"});  // the mark is not part of the first name
    CHECK(r.records[1] == Cells{"0", "0"});
    CHECK(r.records[2] == Cells{"1", "5\n"});  // CRLF inside quotes: one line break
    CHECK(r.lines == std::vector<int>{1, 4, 5});
}

TEST_CASE("csv: the separator is detected from the header", "[csv]") {
    CHECK(io::detect_separator("a,b,c") == ',');
    CHECK(io::detect_separator("a;b;c") == ';');
    CHECK(io::detect_separator("a\tb\tc") == '\t');
    CHECK(io::detect_separator("\"a;b\",c") == ',');  // a separator in quotes does not count
    CHECK(io::detect_separator("single") == ',');
    const Read semi = read_all("speed_in_rpm;torque_in_Nm;P_loss_W\n600;150;\"a;b\"\n");
    CHECK(semi.separator == ';');
    CHECK(semi.records[1] == Cells{"600", "150", "a;b"});
    const Read tab = read_all("speed_in_rpm\ttorque_in_Nm\n600\t150\n");
    CHECK(tab.separator == '\t');
    CHECK(tab.records[1] == Cells{"600", "150"});
    CHECK(io::separator_note(';') == "the columns are separated by ';' (detected)");
    CHECK(io::separator_note('\t') == "the columns are separated by tabs (detected)");
    CHECK(io::separator_note(',').empty());
}

TEST_CASE("csv: a decimal comma is named, with the separator", "[csv]") {
    CHECK_THAT(io::decimal_comma_problem("210,5", ';'),
               Catch::StartsWith("'210,5' has a decimal comma") && Catch::Contains("separated by ';' (detected)"));
    CHECK_THAT(io::decimal_comma_problem("-1,5e3", '\t'), Catch::Contains("decimal comma") && Catch::Contains("tabs"));
    CHECK(io::decimal_comma_problem("1,234,5", ';').empty());  // not a number either way
    CHECK(io::decimal_comma_problem("abc", ';').empty());
    CHECK(io::decimal_comma_problem("12.5", ';').empty());
    // Through the cell reader: the message at file:line:column.
    try {
        io::csv_cell_number("3,25", "f.csv", 4, 2, "P_loss_W", ';');
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.line == 4);
        CHECK(e.column == 2);
        CHECK_THAT(e.message, Catch::StartsWith("'3,25' has a decimal comma"));
    }
    // A quoted "1,5" in a comma-separated file: a decimal comma too, no separator note.
    CHECK_THAT(io::decimal_comma_problem("1,5", ','), !Catch::Contains("detected"));
}

TEST_CASE("csv: broken quoting is an error at its line", "[csv]") {
    const auto open = error_of("a,b\n1,\"never closed\n2,3\n");
    CHECK(open.line == 2);
    CHECK(open.column == 2);
    CHECK_THAT(open.message, Catch::Contains("quoted cell is not closed"));
    const auto after = error_of("a,b\n1,\"x\"y\n");
    CHECK(after.line == 2);
    CHECK_THAT(after.message, Catch::Contains("after the closing '\"'"));
}

TEST_CASE("csv: recordings with quoted cells, CRLF and a byte-order mark", "[csv][recordings]") {
    // The same point written by a spreadsheet (BOM, CRLF, quoted numbers and label) and plainly.
    const auto plain = diagnosis::read_recordings_text("speed_in_rpm,torque_in_Nm,P_loss_W\n600,150,210.5\n", "p.csv");
    const auto sheet = diagnosis::read_recordings_text(
        "\xEF\xBB\xBF\"speed_in_rpm\",\"torque_in_Nm\",\"P_loss_W\"\r\n\"600\",\"150\",\"210.5\"\r\n", "s.csv");
    REQUIRE(sheet.points.size() == 1);
    CHECK(sheet.points[0].loss == plain.points[0].loss);
    CHECK(sheet.points[0].speed_in == plain.points[0].speed_in);
    // The semicolon file's header error says which separator was detected.
    try {
        diagnosis::read_recordings_text("foo;bar\n1;2\n", "x.csv");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.line == 1);
        CHECK_THAT(e.message, Catch::StartsWith("the columns are separated by ';' (detected); the header names none"));
    }
}
