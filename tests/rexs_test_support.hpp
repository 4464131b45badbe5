// Helpers the REXS tests share: the shipped test models, a file's text, a text edit that must
// apply, and the message of an expected InputError.
#pragma once

#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <string>

#include "gearloss/core/errors.hpp"

namespace rexs_test {

inline std::string data(const std::string& name) { return std::string(GEARLOSS_SOURCE_DIR) + "/tests/data/rexs/" + name; }

inline std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// `s` with the first `from` replaced by `to`; the test fails when `from` is not there.
inline std::string replaced(std::string s, const std::string& from, const std::string& to) {
    const auto p = s.find(from);
    REQUIRE(p != std::string::npos);
    return s.replace(p, from.size(), to);
}

// The message of the InputError `f` throws ("" when it throws none).
template <class F>
std::string error_of(F f) {
    try {
        f();
    } catch (const gearloss::InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace rexs_test
