#pragma once
// The errors the library throws on purpose, under one root, gearloss::Error: a message and,
// when known, where it comes from (file, line, column, key path), so that the CLI prints
// "file:line:col: key.path: message" and exits non-zero.
//
//   Error                         root; located or not
//   ├── InputError                the description, an option or a recording is wrong (exit 2)
//   │   ├── units::UnitError       a unit that cannot be read (the caller adds the location)
//   │   ├── geometry::GeometryError  an impossible gear pair
//   │   └── gearbox::TopologyError   a gear train that cannot work (names its item)
//   └── IoError                   an output that could not be written, or an interrupt (exit 3)
//
// Anything else escaping the library (std::bad_alloc, a logic_error) is an internal error.
#include <stdexcept>
#include <string>

namespace gearloss {

// Where a value was written: a file and its 1-based line and column (0 when unknown).
struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;
    bool known() const { return line > 0; }
};

struct Error : std::runtime_error {
    Error(std::string file_, int line_, int column_, std::string key_, std::string message_)
        : std::runtime_error(format(file_, line_, column_, key_, message_)),
          file(std::move(file_)), line(line_), column(column_), key(std::move(key_)), message(std::move(message_)) {}
    std::string file;
    int line;     // 1-based, 0 when unknown
    int column;   // 1-based, 0 when unknown
    std::string key;      // key path ("bearings.B1.C0") or command-line option ("--speed"); may be empty
    std::string message;  // without the location
    SourceLocation where() const { return {file, line, column}; }

    // "file:line:col: key: message"; the parts that are known ("--speed: message" for a
    // command-line option, which has no file); the bare message when nothing is.
    static std::string format(const std::string& f, int l, int c, const std::string& k, const std::string& m) {
        if (f.empty() && l <= 0) return k.empty() ? m : k + ": " + m;
        std::string s = f.empty() ? std::string("<input>") : f;
        if (l > 0) s.append(":").append(std::to_string(l));
        if (c > 0) s.append(":").append(std::to_string(c));
        s.append(": ");
        if (!k.empty()) s.append(k).append(": ");
        return s.append(m);
    }
};

struct InputError : Error {
    using Error::Error;
    explicit InputError(std::string message_) : Error({}, 0, 0, {}, std::move(message_)) {}
    InputError(const SourceLocation& at, std::string key_, std::string message_)
        : Error(at.file, at.line, at.column, std::move(key_), std::move(message_)) {}
};

// An output that could not be written, or an interrupt (gearloss/core/interrupt.hpp): nothing is
// renamed and temporary files are removed (gearloss/io/atomic_file.hpp; also io::IoError).
struct IoError : Error {
    explicit IoError(std::string m) : Error({}, 0, 0, {}, std::move(m)) {}
};

}  // namespace gearloss
