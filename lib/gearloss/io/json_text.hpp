#pragma once
// The JSON documents gearloss writes (summaries, check --json, diagnosis) are built as
// nlohmann::ordered_json objects, so members come out in the order the code sets them, and
// turned into text here, in one place, the same way for every command.
#include <nlohmann/json.hpp>
#include <string>

namespace gearloss::io {

// One line of compact JSON and a newline. Non-finite numbers come out as null (JSON has no
// NaN or infinity; nlohmann-json writes null for them); bytes that are not UTF-8 (the inputs
// refuse them, this is a last guard) as U+FFFD instead of an exception.
inline std::string json_line(const nlohmann::ordered_json& j) {
    return j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace gearloss::io
