#pragma once
// Output files are written to a temporary file beside the target and renamed
// over it only when complete, so a reader never sees a partial file and an
// interrupted run leaves the previous file (or none).
#include <atomic>
#include <cstdio>
#include <string>

namespace gearloss::io {

class AtomicFile {
public:
    explicit AtomicFile(std::string path);   // "-" writes to stdout directly
    ~AtomicFile();                            // discards if not committed
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    std::FILE* stream() { return f_; }
    void write(const std::string& s);
    void commit();                            // flush, fsync, rename; throws on failure

private:
    std::string path_, tmp_;
    std::FILE* f_ = nullptr;
    bool committed_ = false;
    bool to_stdout_ = false;
};

struct IoError : std::exception {
    explicit IoError(std::string m) : msg(std::move(m)) {}
    const char* what() const noexcept override { return msg.c_str(); }
    std::string msg;
};

// Set by the signal handler: long loops stop and outputs are discarded.
extern std::atomic<bool> g_interrupted;

}  // namespace gearloss::io
