#pragma once
// The lines of a text file too large to hold (map shards of any size), read a piece at a
// time with the bounds every input file has: only a regular file, each line at most
// kMaxLineBytes and text only (check_input_text), failures naming the file and line.
#include <string>
#include <string_view>

namespace gearloss::io {

class LineReader {
public:
    explicit LineReader(const std::string& file);  // InputError when it is not a readable regular file
    ~LineReader();
    LineReader(const LineReader&) = delete;
    LineReader& operator=(const LineReader&) = delete;
    // The next line without its '\n' (valid until the next call); false at the end of the file.
    bool next(std::string_view& line);
    int line_number() const { return line_; }           // of the line last returned (1-based)
    bool last_line_ended() const { return ended_; }     // the line last returned had its '\n'
    const std::string& file() const { return file_; }

private:
    bool fill();  // more bytes after the unread ones; false at the end
    std::string file_, buf_;
    size_t pos_ = 0;
    int fd_ = -1, line_ = 0;
    bool eof_ = false, ended_ = true;
};

}  // namespace gearloss::io
