#pragma once
// Input errors carry where they come from so the CLI can print
// "file:line:col: key.path: message" and exit non-zero; an IoError is a failure to write an
// output (or an interrupt), exit 3 (README "Exit codes").
#include <exception>
#include <stdexcept>
#include <string>

namespace gearloss {

struct InputError : std::runtime_error {
    InputError(std::string file_, int line_, int column_, std::string key_, std::string message_)
        : std::runtime_error(format(file_, line_, column_, key_, message_)),
          file(std::move(file_)), line(line_), column(column_), key(std::move(key_)), message(std::move(message_)) {}
    std::string file;
    int line;     // 1-based, 0 when unknown
    int column;   // 1-based, 0 when unknown
    std::string key;
    std::string message;

    static std::string format(const std::string& f, int l, int c, const std::string& k, const std::string& m) {
        std::string s = f.empty() ? std::string("<input>") : f;
        if (l > 0) s.append(":").append(std::to_string(l));
        if (c > 0) s.append(":").append(std::to_string(c));
        s.append(": ");
        if (!k.empty()) s.append(k).append(": ");
        return s.append(m);
    }
};

// An output that could not be written, or an interrupt (core/interrupt.hpp): nothing is
// renamed and temporary files are removed (io/atomic_file.hpp).
struct IoError : std::exception {
    explicit IoError(std::string m) : msg(std::move(m)) {}
    const char* what() const noexcept override { return msg.c_str(); }
    std::string msg;
};

}  // namespace gearloss
