#include "gearloss/io/csv_records.hpp"

#include <charconv>
#include <cmath>
#include <utility>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"

namespace gearloss::io {

char detect_separator(std::string_view header) {
    size_t comma = 0, semicolon = 0, tab = 0;
    bool quoted = false;
    for (char c : header) {
        if (c == '"') quoted = !quoted;
        if (quoted) continue;
        comma += c == ',';
        semicolon += c == ';';
        tab += c == '\t';
    }
    if (semicolon > comma && semicolon >= tab) return ';';
    if (tab > comma && tab > semicolon) return '\t';
    return ',';
}

std::string separator_note(char separator) {
    if (separator == ',') return "";
    return std::string("the columns are separated by ") + (separator == '\t' ? "tabs" : "';'") + " (detected)";
}

CsvReader::CsvReader(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;  // UTF-8 byte-order mark (spreadsheets write one)
}

namespace {
bool blank(char c) { return c == ' ' || c == '\t'; }

// A cell not in quotes: blanks (other than the separator) at either end trimmed.
std::string trimmed(std::string s, char separator) {
    size_t a = 0, b = s.size();
    while (a < b && blank(s[a]) && s[a] != separator) ++a;
    while (b > a && blank(s[b - 1]) && s[b - 1] != separator) --b;
    return s.substr(a, b - a);
}
}  // namespace

bool CsvReader::next(CsvRecord& r) {
    const size_t n = text_.size();
    // Blank and comment lines between records.
    for (;;) {
        if (pos_ >= n) return false;
        const size_t eol = text_.find('\n', pos_);
        std::string_view line = text_.substr(pos_, (eol == std::string_view::npos ? n : eol) - pos_);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (!line.empty() && line[0] != '#') break;
        if (eol == std::string_view::npos) {
            pos_ = n;
            return false;
        }
        pos_ = eol + 1;
        ++line_;
    }
    if (separator_ == 0) {
        const size_t eol = text_.find('\n', pos_);
        separator_ = detect_separator(text_.substr(pos_, (eol == std::string_view::npos ? n : eol) - pos_));
    }
    r.cells.clear();
    r.line = line_;
    const size_t start = pos_;
    size_t end = n;  // of the record's text
    std::string cell;
    enum class State { start, plain, quoted, closed } state = State::start;
    int open_line = 0;
    size_t column = 1;
    const auto finish = [&] {
        r.cells.push_back(state == State::plain || state == State::start ? trimmed(std::move(cell), separator_) : std::move(cell));
        cell.clear();
        state = State::start;
    };
    size_t i = pos_;
    for (; i < n; ++i) {
        const char c = text_[i];
        if (state == State::quoted) {
            if (c == '"') {
                if (i + 1 < n && text_[i + 1] == '"') {  // a doubled quote is one quote
                    cell += '"';
                    ++i;
                } else {
                    state = State::closed;
                }
            } else if (c == '\r' && i + 1 < n && text_[i + 1] == '\n') {
                // CRLF inside a cell: the line break, as LF
            } else {
                if (c == '\n') ++line_;
                cell += c;
            }
            continue;
        }
        if (c == '\n') {
            end = i;
            break;
        }
        if (c == '\r') continue;  // of a CRLF line end (or stray): not part of a cell
        if (c == separator_) {
            finish();
            ++column;
            continue;
        }
        if (c == '"' && state == State::start) {  // blanks before the opening quote are dropped
            cell.clear();
            state = State::quoted;
            open_line = line_;
            continue;
        }
        if (state == State::closed) {
            if (blank(c)) continue;  // blanks after the closing quote
            throw InputError(file_, line_, static_cast<int>(column), "",
                             "text after the closing '\"' of a quoted cell (a quote inside a cell is written twice: \"\")");
        }
        cell += c;
        if (!blank(c)) state = State::plain;
    }
    if (state == State::quoted)
        throw InputError(file_, open_line, static_cast<int>(column), "",
                         "a quoted cell is not closed: no closing '\"' before the end of the file");
    finish();
    if (end > start && text_[end - 1] == '\r') --end;
    r.text = text_.substr(start, end - start);
    pos_ = i < n ? i + 1 : n;
    if (i < n) ++line_;
    return true;
}

std::string decimal_comma_problem(std::string_view cell, char separator) {
    const size_t comma = cell.find(',');
    if (comma == std::string_view::npos || cell.find(',', comma + 1) != std::string_view::npos) return "";
    std::string dotted(cell);
    dotted[comma] = '.';
    double v = 0;
    if (read_cell_number(dotted, v) != CellNumber::number) return "";
    std::string msg = "'" + excerpt(cell) + "' has a decimal comma";
    if (separator != ',')
        msg += "; " + separator_note(separator) + ", as a spreadsheet saved in a locale with decimal commas writes them";
    return msg + "; gearloss reads '.' as the decimal point: save the file with '.' decimals";
}

}  // namespace gearloss::io
