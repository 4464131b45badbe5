#include "io/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <unistd.h>

namespace gearloss::io {

std::atomic<bool> g_interrupted{false};

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
    if (path_ == "-") {
        to_stdout_ = true;
        f_ = stdout;
        return;
    }
    tmp_ = path_ + ".tmp." + std::to_string(::getpid());
    f_ = std::fopen(tmp_.c_str(), "wb");
    if (!f_) throw IoError("cannot write '" + path_ + "': " + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
    if (to_stdout_) return;
    if (!committed_) {
        if (f_) std::fclose(f_);
        ::unlink(tmp_.c_str());
    }
}

void AtomicFile::write(const std::string& s) {
    if (std::fwrite(s.data(), 1, s.size(), f_) != s.size())
        throw IoError("cannot write '" + path_ + "': " + std::strerror(errno));
}

void AtomicFile::commit() {
    if (to_stdout_) {
        std::fflush(stdout);
        committed_ = true;
        return;
    }
    if (g_interrupted) throw IoError("interrupted; '" + path_ + "' left unchanged");
    if (std::fflush(f_) != 0 || ::fsync(fileno(f_)) != 0) {
        const std::string e = std::strerror(errno);
        throw IoError("cannot write '" + path_ + "': " + e);
    }
    if (std::fclose(f_) != 0) {
        f_ = nullptr;
        throw IoError("cannot write '" + path_ + "': " + std::strerror(errno));
    }
    f_ = nullptr;
    if (std::rename(tmp_.c_str(), path_.c_str()) != 0)
        throw IoError("cannot rename into '" + path_ + "': " + std::strerror(errno));
    committed_ = true;
}

}  // namespace gearloss::io
