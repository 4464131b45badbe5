#pragma once
// Reading input (recordings, drive cycles, map shards, and the bounded file reader every
// input file goes through): a shard's line into its cells as written (the records of the
// other files: csv_records.hpp), a cell into a finite number or an error naming the place,
// and the bounds on what is read at all (README "Reliability": only regular files, sizes,
// line lengths, text).
#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_records.hpp"

namespace gearloss::io {

// Bounds on input files (README "Reliability").
inline constexpr std::size_t kMaxYamlFileBytes = std::size_t{16} << 20;  // case, oil and sweep files: 16 MiB
inline constexpr std::size_t kMaxCsvFileBytes = std::size_t{64} << 20;   // recordings and cycles: 64 MiB
inline constexpr std::size_t kMaxLineBytes = 65536;                       // any line of any input file
inline constexpr std::size_t kExcerptChars = 60;                          // quoted input in messages

// Reads a file the user named. Only a regular file is read (a FIFO, a device, a socket
// or a directory is refused by name before any byte is read); more than `max_bytes`
// is refused without reading it all; the text must pass check_input_text. Failures are
// InputErrors naming `file` and never quoting its content.
std::string read_input_file(const std::string& file, std::size_t max_bytes);
// The same without the text check, for content that is only hashed.
std::string read_regular_file(const std::string& file, std::size_t max_bytes);
// The file opened for reading with the same refusals (only a regular file, never blocking on
// a FIFO); the caller owns the descriptor. For files read piece by piece (LineReader).
int open_regular_file(const std::string& file);

// The bounds on text already in memory (the *_text entry points): at most `max_bytes`,
// every line at most kMaxLineBytes, and text only: a NUL or another control byte (other
// than tab, CR, LF) means the file is not YAML or CSV, and it is refused without quoting it.
// `first_line` numbers the first line of `text` in messages (text read piece by piece).
void check_input_text(std::string_view text, const std::string& file, std::size_t max_bytes, int first_line = 1);

// At most `max` characters of `s` for a message: control bytes and invalid UTF-8 are
// shown as '?', and "..." marks a cut.
std::string excerpt(std::string_view s, std::size_t max = kExcerptChars);

// Valid UTF-8 (no overlong forms, no surrogates) without control characters (C0, DEL, C1) nor the
// bidirectional controls (U+061C, U+200E-U+200F, U+202A-U+202E, U+2066-U+2069), which reorder text.
bool is_printable_utf8(std::string_view s);

// Why `s` cannot name a component (empty when it can): printable UTF-8 without invisible
// characters (no-break and other Unicode spaces, zero-width and direction marks, variation
// selectors, byte-order mark), no blank at either end, no ',' or '"' (names become CSV
// column names), no '/' and not "." or ".." (a ratio's name becomes part of a file name),
// at most max_bytes. Two names that look alike are then the same bytes.
std::string name_problem(std::string_view s, std::size_t max_bytes);

// A hint when a CSV line holds none of the file's separator (detected from its header) but
// another one: it "looks semicolon-separated" (or tab- or comma-); "" otherwise.
std::string separator_hint(const std::string& line, char separator = ',');

// The cells of a CSV line as written: split at commas outside double quotes, nothing removed
// (a merge checks cells byte for byte).
inline std::vector<std::string_view> split_csv_cells(std::string_view line) {
    std::vector<std::string_view> cells;
    size_t c0 = 0;
    bool quoted = false;
    for (size_t i = 0; i <= line.size(); ++i) {
        if (i < line.size() && line[i] == '"') quoted = !quoted;
        if (i == line.size() || (line[i] == ',' && !quoted)) {
            cells.push_back(line.substr(c0, i - c0));
            c0 = i + 1;
        }
    }
    return cells;
}

// A cell read as a whole number (std::from_chars: no blank, '+' or hexadecimal): what it is.
enum class CellNumber { number, not_finite, not_number };
inline CellNumber read_cell_number(std::string_view s, double& v) {
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec == std::errc::result_out_of_range || (ec == std::errc() && p == s.data() + s.size() && !std::isfinite(v)))
        return CellNumber::not_finite;
    return ec == std::errc() && p == s.data() + s.size() ? CellNumber::number : CellNumber::not_number;
}

// The cell as a finite number; InputError at file:line:column, key `column`, otherwise (a
// number with a decimal comma says so, and names the file's separator when it is not ',').
inline double csv_cell_number(const std::string& s, const std::string& file, int line, int column,
                              const std::string& column_name, char separator = ',') {
    if (s.empty()) throw InputError(file, line, column, column_name, "empty cell; a number is expected");
    double v = 0;
    const CellNumber kind = read_cell_number(s, v);
    if (kind == CellNumber::not_finite)
        throw InputError(file, line, column, column_name, "'" + excerpt(s) + "' is out of range (not a finite number)");
    if (kind == CellNumber::not_number) {
        const std::string decimal_comma = decimal_comma_problem(s, separator);
        throw InputError(file, line, column, column_name, decimal_comma.empty() ? "'" + excerpt(s) + "' is not a number" : decimal_comma);
    }
    return v;
}

}  // namespace gearloss::io
