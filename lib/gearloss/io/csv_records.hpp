#pragma once
// The CSV reader of the input files (recordings, drive cycles): RFC 4180 records (Shafranovich
// 2005: cells in double quotes may hold the separator, a doubled quote and line breaks; CRLF
// or LF line ends) with the separator detected from the header line, since spreadsheets
// saved in many European locales write ';' between cells and ',' as the decimal point, and
// some tools write tabs. Blank lines and lines starting with '#' (comments) are skipped; a
// UTF-8 byte-order mark at the start is dropped. Every failure is an InputError naming the
// file and line.
//
// Hand-written rather than a packaged library: Debian's C++ CSV parsers either fix the column
// count at compile time (fast-cpp-csv-parser, libfccp-dev) or report cells through C callbacks
// without their line (libcsv-dev), while every message here names file:line:column. Map shards
// (`merge`) are gearloss's own output, checked byte for byte: they keep split_csv_cells.
#include <string>
#include <string_view>
#include <vector>

namespace gearloss::io {

// The separator of a header line: ',', ';' or '\t', whichever occurs most often outside
// double quotes (',' on a tie and when none occurs: a file of one column).
char detect_separator(std::string_view header);

// How a message names a separator that is not the comma: "the columns are separated by ';'
// (detected)"; "" for ','.
std::string separator_note(char separator);

struct CsvRecord {
    std::vector<std::string> cells;  // unquoted; blanks around a cell not in quotes trimmed
    int line = 0;                    // the line the record starts on (1-based)
    std::string_view text;           // the record as written, without its line end (for hints)
};

class CsvReader {
public:
    // `text` (already bounded and checked: read_input_file) must outlive the reader.
    CsvReader(std::string_view text, std::string file);
    // The next record; the first one (the header) fixes the separator. False at the end.
    bool next(CsvRecord& record);
    char separator() const { return separator_; }
    int line() const { return line_; }  // the line the reader is on (the last line at the end)

private:
    std::string_view text_;
    std::string file_;
    size_t pos_ = 0;
    int line_ = 1;
    char separator_ = 0;
};

// Why a cell that is not a number is not one, when it is a number written with a decimal
// comma ("210,5"): the message to give ("" otherwise).
std::string decimal_comma_problem(std::string_view cell, char separator);

}  // namespace gearloss::io
