#pragma once
// The JSON documents gearloss writes (summaries, check --json, diagnosis) are built as
// nlohmann::ordered_json objects, so members come out in the order the code sets them, and
// turned into text here, in one place, the same way for every command.
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

namespace gearloss::io {

// One line of compact JSON and a newline. Non-finite numbers come out as null (JSON has no
// NaN or infinity; nlohmann-json writes null for them); bytes that are not UTF-8 (the inputs
// refuse them, this is a last guard) as U+FFFD instead of an exception.
inline std::string json_line(const nlohmann::ordered_json& j) {
    return j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

// A number for a JSON document: null when it does not exist, else the value rounded to 15
// significant digits. Every 15-digit decimal survives a trip through a double, so a value
// converted from SI at the boundary comes out as it went in (700 rpm -> rad/s -> rpm prints 700,
// not 700.0000000000001); the rounding is below 1e-15 of the value.
inline nlohmann::ordered_json json_number(double v) {
    if (!std::isfinite(v)) return nullptr;
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 15).ptr;
    double tidy = v;
    std::from_chars(buf, end, tidy);
    return tidy == 0.0 ? 0.0 : tidy;  // no "-0.0"
}

}  // namespace gearloss::io
