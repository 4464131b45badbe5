#pragma once
// Reading CSV input (recordings, drive cycles): one line into trimmed cells (double
// quotes protect commas), and a cell into a finite number or an error naming the place.
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace gearloss::io {

inline std::vector<std::string> split_csv_line(const std::string& line) {
    std::vector<std::string> out;
    std::string cur;
    bool quoted = false;
    for (char c : line) {
        if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) {
            out.push_back(cur);
            cur.clear();
        } else if (c != '\r') cur += c;
    }
    out.push_back(cur);
    for (auto& s : out) {
        s.erase(0, s.find_first_not_of(" \t"));
        s.erase(s.find_last_not_of(" \t") + 1);
    }
    return out;
}

// The cell as a finite number; InputError at file:line:column, key `column`, otherwise.
inline double csv_cell_number(const std::string& s, const std::string& file, int line, int column,
                              const std::string& column_name) {
    double v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v))
        throw InputError(file, line, column, column_name, "'" + s + "' is not a number");
    return v;
}

}  // namespace gearloss::io
