#include "gearloss/io/line_reader.hpp"

#include <cerrno>
#include <cstring>
#include <unistd.h>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"

namespace gearloss::io {

LineReader::LineReader(const std::string& file) : file_(file), fd_(open_regular_file(file)) {}

LineReader::~LineReader() {
    if (fd_ >= 0) ::close(fd_);
}

bool LineReader::fill() {
    if (eof_) return false;
    buf_.erase(0, pos_);
    pos_ = 0;
    constexpr size_t kPiece = size_t{1} << 20;
    const size_t have = buf_.size();
    buf_.resize(have + kPiece);
    for (;;) {
        const ssize_t n = ::read(fd_, buf_.data() + have, kPiece);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const int err = errno;
            buf_.resize(have);
            throw InputError(file_, line_ + 1, 0, "", std::string("cannot read file: ") + std::strerror(err));
        }
        buf_.resize(have + static_cast<size_t>(n));
        if (n == 0) eof_ = true;
        return n > 0;
    }
}

bool LineReader::next(std::string_view& line) {
    size_t nl = buf_.find('\n', pos_);
    while (nl == std::string::npos) {
        // A line longer than the bound is refused by the check below once it is this long.
        if (buf_.size() - pos_ > kMaxLineBytes || !fill()) break;
        nl = buf_.find('\n', pos_);
    }
    if (nl == std::string::npos && pos_ == buf_.size()) return false;
    const size_t end = nl == std::string::npos ? buf_.size() : nl;
    line = std::string_view(buf_).substr(pos_, end - pos_);
    ++line_;
    ended_ = nl != std::string::npos;
    check_input_text(line, file_, static_cast<size_t>(-1), line_);  // the line bound, not a file size
    pos_ = ended_ ? nl + 1 : end;
    return true;
}

}  // namespace gearloss::io
