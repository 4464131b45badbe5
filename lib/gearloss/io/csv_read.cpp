#include "gearloss/io/csv_read.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gearloss::io {

namespace {

// Length of the valid UTF-8 sequence at s[i] (1-4), 0 if it is not one.
std::size_t utf8_length(std::string_view s, std::size_t i) {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = b(i);
    if (c < 0x80) return 1;
    // Length, and the range of the second byte (no overlong forms, no UTF-16 surrogates, nothing above U+10FFFF).
    std::size_t n = 0;
    unsigned lo = 0x80, hi = 0xBF;
    if (c >= 0xC2 && c <= 0xDF) {
        n = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
        n = 3;
        if (c == 0xE0) lo = 0xA0;
        if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
        n = 4;
        if (c == 0xF0) lo = 0x90;
        if (c == 0xF4) hi = 0x8F;
    } else {
        return 0;
    }
    if (i + n > s.size()) return 0;
    if (b(i + 1) < lo || b(i + 1) > hi) return 0;
    for (std::size_t k = 2; k < n; ++k)
        if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
    return n;
}

bool is_control(std::string_view s, std::size_t i, std::size_t len) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (len == 1) return c < 0x20 || c == 0x7F;
    const auto at = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
    if (len == 2) return (c == 0xC2 && at(1) < 0xA0) || (c == 0xD8 && at(1) == 0x9C);  // C1 controls; U+061C
    // The bidirectional controls reorder the text after them, so that a name or a message shows
    // other than it reads (U+202E right-to-left override): marks U+200E-U+200F, embeddings and
    // overrides U+202A-U+202E, isolates U+2066-U+2069.
    if (len == 3 && c == 0xE2)
        return (at(1) == 0x80 && (at(2) == 0x8E || at(2) == 0x8F || (at(2) >= 0xAA && at(2) <= 0xAE))) ||
               (at(1) == 0x81 && at(2) >= 0xA6 && at(2) <= 0xA9);
    return false;
}

std::string kind_of(mode_t m) {
    if (S_ISDIR(m)) return "a directory";
    if (S_ISFIFO(m)) return "a FIFO";
    if (S_ISCHR(m)) return "a character device";
    if (S_ISBLK(m)) return "a block device";
    if (S_ISSOCK(m)) return "a socket";
    return "not a plain file";
}

std::string size_text(std::size_t bytes) {
    return bytes % (std::size_t{1} << 20) == 0 ? fmt::format("{} MiB", bytes >> 20) : fmt::format("{} bytes", bytes);
}

[[noreturn]] void not_regular(const std::string& file, mode_t m) {
    throw InputError(file, 0, 0, "", "is not a regular file (" + kind_of(m) + "); gearloss reads only regular files");
}

[[noreturn]] void too_large(const std::string& file, std::size_t max_bytes) {
    throw InputError(file, 0, 0, "", "file is larger than " + size_text(max_bytes) + ", the limit for this kind of input");
}

struct Fd {
    int fd;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

std::string read_input_file(const std::string& file, std::size_t max_bytes) {
    std::string data = read_regular_file(file, max_bytes);
    check_input_text(data, file, max_bytes);
    return data;
}

namespace {
int open_checked(const std::string& file, struct stat& st) {
    // stat first: a FIFO or a device is refused without ever being opened (opening a FIFO blocks).
    if (::stat(file.c_str(), &st) != 0) {
        const int err = errno;
        throw InputError(file, 0, 0, "", std::string("cannot open file: ") + std::strerror(err));
    }
    if (!S_ISREG(st.st_mode)) not_regular(file, st.st_mode);
    // O_NONBLOCK: should the path be swapped for a FIFO after the stat, the open does not block
    // and the fstat below refuses it.
    Fd f{::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK)};
    if (f.fd < 0) {
        const int err = errno;
        throw InputError(file, 0, 0, "", std::string("cannot open file: ") + std::strerror(err));
    }
    if (::fstat(f.fd, &st) != 0 || !S_ISREG(st.st_mode)) not_regular(file, st.st_mode);
    const int fd = f.fd;
    f.fd = -1;
    return fd;
}
}  // namespace

int open_regular_file(const std::string& file) {
    struct stat st {};
    return open_checked(file, st);
}

std::string read_regular_file(const std::string& file, std::size_t max_bytes) {
    struct stat st {};
    Fd f{open_checked(file, st)};
    if (st.st_size < 0 || static_cast<unsigned long long>(st.st_size) > max_bytes) too_large(file, max_bytes);
    std::string data;
    data.reserve(static_cast<std::size_t>(st.st_size));
    char buf[65536];
    for (;;) {
        const ssize_t n = ::read(f.fd, buf, sizeof buf);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int err = errno;
            throw InputError(file, 0, 0, "", std::string("cannot read file: ") + std::strerror(err));
        }
        if (n == 0) break;
        if (data.size() + static_cast<std::size_t>(n) > max_bytes) too_large(file, max_bytes);  // grew while read
        data.append(buf, static_cast<std::size_t>(n));
    }
    return data;
}

void check_input_text(std::string_view text, const std::string& file, std::size_t max_bytes, int first_line) {
    if (text.size() > max_bytes) too_large(file, max_bytes);
    int line = first_line;
    std::size_t line_start = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++line;
            line_start = i + 1;
            continue;
        }
        if (i - line_start >= kMaxLineBytes)
            throw InputError(file, line, 0, "",
                             fmt::format("line longer than {} bytes; gearloss reads text files with lines of at most "
                                         "{} bytes", kMaxLineBytes, kMaxLineBytes));
        if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7F)
            throw InputError(file, line, static_cast<int>(i - line_start + 1), "",
                             fmt::format("control byte 0x{:02X}: not a text (YAML or CSV) file", c));
    }
}

std::string excerpt(std::string_view s, std::size_t max) {
    std::string out;
    std::size_t chars = 0, i = 0;
    while (i < s.size()) {
        if (chars == max) {
            out += "...";
            break;
        }
        const std::size_t n = utf8_length(s, i);
        if (n == 0 || is_control(s, i, n)) {
            out += '?';
            i += n == 0 ? 1 : n;
        } else {
            out.append(s.substr(i, n));
            i += n;
        }
        ++chars;
    }
    return out;
}

bool is_printable_utf8(std::string_view s) {
    for (std::size_t i = 0; i < s.size();) {
        const std::size_t n = utf8_length(s, i);
        if (n == 0 || is_control(s, i, n)) return false;
        i += n;
    }
    return true;
}

namespace {
// The code point of the valid UTF-8 sequence of n bytes at i.
char32_t code_point(std::string_view s, std::size_t i, std::size_t n) {
    const auto b = [&](std::size_t k) { return static_cast<char32_t>(static_cast<unsigned char>(s[i + k])); };
    if (n == 1) return b(0);
    char32_t c = b(0) & (n == 2 ? 0x1F : n == 3 ? 0x0F : 0x07);
    for (std::size_t k = 1; k < n; ++k) c = (c << 6) | (b(k) & 0x3F);
    return c;
}

// Characters that print as nothing or as a blank: they would make two names look alike.
bool invisible(char32_t c) {
    return c == 0x00A0 || c == 0x00AD || c == 0x034F || c == 0x061C || c == 0x180E || (c >= 0x2000 && c <= 0x200F) ||
           (c >= 0x2028 && c <= 0x202F) || (c >= 0x205F && c <= 0x206F) || c == 0x3000 || (c >= 0xFE00 && c <= 0xFE0F) ||
           c == 0xFEFF || (c >= 0xE0000 && c <= 0xE007F);
}
}  // namespace

std::string name_problem(std::string_view s, std::size_t max_bytes) {
    if (s.empty()) return "a name cannot be empty";
    if (!is_printable_utf8(s)) return "a name must be printable UTF-8 text without control characters (nor direction controls such as U+202E) or line breaks";
    for (std::size_t i = 0; i < s.size();) {
        const std::size_t n = utf8_length(s, i);
        if (invisible(code_point(s, i, n)))
            return fmt::format("a name cannot contain the invisible character U+{:04X} (a no-break or other Unicode space, "
                               "a zero-width or direction mark)", static_cast<unsigned>(code_point(s, i, n)));
        i += n;
    }
    if (s.front() == ' ' || s.back() == ' ' || s.front() == '\t' || s.back() == '\t')
        return "a name cannot begin or end with a blank";
    if (s.find_first_of(",\"") != std::string_view::npos) return "a name cannot contain ',' or '\"' (names become CSV column names)";
    if (s.find('/') != std::string_view::npos || s == "." || s == "..")
        return "a name cannot contain '/' or be '.' or '..' (names become parts of file names)";
    if (s.size() > max_bytes) return "a name is at most " + std::to_string(max_bytes) + " bytes long";
    return {};
}

std::string separator_hint(const std::string& line, char separator) {
    // Called once a line is known to be wrong (one header cell, a cell count that differs):
    // a line split more often by another separator than by the file's is split by that one
    // (a row pasted from a spreadsheet saved in another locale).
    const auto count = [&](char c) { return std::count(line.begin(), line.end(), c); };
    const char other = detect_separator(line);
    if (other == separator || count(other) <= count(separator)) return "";
    const char* looks = other == ';' ? "semicolon" : other == '\t' ? "tab" : "comma";
    const std::string sep = separator == '\t' ? "tabs" : fmt::format("'{}'", separator);
    return fmt::format("the line looks {}-separated, the header's columns are separated by {}; one separator throughout",
                       looks, sep);
}

}  // namespace gearloss::io
