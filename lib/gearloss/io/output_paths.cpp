#include "gearloss/io/output_paths.hpp"

#include "gearloss/io/csv_read.hpp"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <fstream>
#include <optional>
#include <sys/file.h>
#include <unistd.h>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/atomic_file.hpp"

namespace gearloss::io {
namespace {

bool all_digits(const std::string& s) {
    if (s.empty() || s.size() > 9) return false;
    for (char c : s)
        if (c < '0' || c > '9') return false;
    return true;
}

// /dev/stdout, /dev/fd/N, /proc/self/fd/N, /proc/<own pid>/fd/N: the descriptor N.
std::optional<int> descriptor_of(const std::string& p) {
    if (p == "-" || p == "/dev/stdout") return 1;
    if (p == "/dev/stderr") return 2;
    const std::string own = "/proc/" + std::to_string(::getpid()) + "/fd/";
    for (const std::string& prefix : {std::string("/dev/fd/"), std::string("/proc/self/fd/"),
                                     std::string("/proc/thread-self/fd/"), own})
        if (p.size() > prefix.size() && p.compare(0, prefix.size(), prefix) == 0 && all_digits(p.substr(prefix.size())))
            return std::atoi(p.c_str() + prefix.size());
    return std::nullopt;
}

void split(const std::string& p, std::string& dir, std::string& name) {
    const auto slash = p.find_last_of('/');
    if (slash == std::string::npos) {
        dir = ".";
        name = p;
    } else {
        dir = slash == 0 ? "/" : p.substr(0, slash);
        name = p.substr(slash + 1);
    }
}

std::string cannot(const std::string& path, const std::string& why) { return "cannot write '" + path + "': " + why; }

}  // namespace

OutputTarget resolve_output(const std::string& path) {
    OutputTarget t;
    if (path.empty()) throw IoError("cannot write '': empty file name");
    std::string p = path;
    for (int hops = 0;; ++hops) {
        if (hops > 40) throw IoError(cannot(path, std::strerror(ELOOP)));
        if (const auto fd = descriptor_of(p)) {
            t.kind = OutputTarget::Kind::descriptor;
            t.fd = *fd;
            return t;
        }
        split(p, t.dir, t.name);
        struct stat ls {};
        if (::lstat(p.c_str(), &ls) != 0) {
            // Missing (or not reachable): the temporary file's creation reports why.
            if (t.name.empty() || t.name == "." || t.name == "..") throw IoError(cannot(path, "not a file name"));
            t.kind = OutputTarget::Kind::absent;
            break;
        }
        if (S_ISLNK(ls.st_mode)) {
            std::string target(static_cast<size_t>(ls.st_size > 0 ? ls.st_size : PATH_MAX) + 1, '\0');
            const ssize_t n = ::readlink(p.c_str(), target.data(), target.size());
            if (n < 0) throw IoError(cannot(path, std::strerror(errno)));
            target.resize(static_cast<size_t>(n));
            if (target.empty()) throw IoError(cannot(path, "empty symbolic link"));
            p = target[0] == '/' ? target : (t.dir == "/" ? "/" : t.dir + "/") + target;
            continue;
        }
        if (S_ISDIR(ls.st_mode) || t.name.empty()) throw IoError(cannot(path, "is a directory"));
        t.st = ls;
        if (S_ISREG(ls.st_mode)) t.kind = OutputTarget::Kind::regular;
        else if (S_ISCHR(ls.st_mode) || S_ISFIFO(ls.st_mode)) t.kind = OutputTarget::Kind::direct;
        else throw IoError(cannot(path, S_ISBLK(ls.st_mode) ? "a block device is not written" : "not a regular file"));
        break;
    }
    // A directory that is (a link to) /proc/self/fd: the descriptor named by the last component.
    if (char* real = ::realpath(t.dir.c_str(), nullptr)) {
        const std::string r = real;
        std::free(real);
        if (const auto fd = descriptor_of(r + "/" + t.name)) {
            t.kind = OutputTarget::Kind::descriptor;
            t.fd = *fd;
        }
    }
    return t;
}

std::string temp_prefix(const std::string& name) {
    const size_t room = NAME_MAX - std::strlen(kTempMarker) - 6;
    return (name.size() > room ? name.substr(0, room) : name) + kTempMarker;
}

void remove_stale_temporaries(const std::string& dir, const std::string& name) {
    const std::string prefix = temp_prefix(name);
    DIR* d = ::opendir(dir.c_str());
    if (!d) return;
    while (const dirent* e = ::readdir(d)) {
        const std::string n = e->d_name;
        if (n.size() != prefix.size() + 6 || n.compare(0, prefix.size(), prefix) != 0) continue;
        bool random_part = true;
        for (size_t i = prefix.size(); i < n.size(); ++i)
            random_part = random_part && std::isalnum(static_cast<unsigned char>(n[i]));
        if (!random_part) continue;
        const std::string full = (dir == "/" ? "/" : dir + "/") + n;
        const int fd = ::open(full.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
        if (fd < 0) continue;
        struct stat s {}, l {};
        // Unlocked: its writer is gone (the lock, not the age, decides). Still the same file
        // under that name once locked: then it is removed while this run holds its lock.
        if (::fstat(fd, &s) == 0 && S_ISREG(s.st_mode) && (::geteuid() == 0 || s.st_uid == ::geteuid()) &&
            ::flock(fd, LOCK_EX | LOCK_NB) == 0 && ::lstat(full.c_str(), &l) == 0 && l.st_dev == s.st_dev &&
            l.st_ino == s.st_ino)
            ::unlink(full.c_str());
        ::close(fd);
    }
    ::closedir(d);
}

int create_locked_temporary(const std::string& dir, const std::string& name, std::string& path) {
    remove_stale_temporaries(dir, name);
    const std::string base = (dir == "/" ? "/" : dir + "/") + temp_prefix(name) + "XXXXXX";
    for (int attempt = 0;; ++attempt) {
        path = base;
        const int fd = ::mkostemp(path.data(), O_CLOEXEC);  // O_CREAT | O_EXCL, mode 0600: never follows a planted link
        if (fd < 0) return -1;
        // Blocking: a cleaner holds the lock only while it checks and unlinks.
        while (::flock(fd, LOCK_EX) != 0 && errno == EINTR) {}
        struct stat s {}, l {};
        if (attempt >= 100 ||
            (::fstat(fd, &s) == 0 && s.st_nlink > 0 && ::lstat(path.c_str(), &l) == 0 && l.st_dev == s.st_dev &&
             l.st_ino == s.st_ino))
            return fd;
        ::close(fd);  // removed by another run's cleaner before it was locked: make another
    }
}

namespace {

// What a path leads to, for comparing files: st_dev/st_ino when it exists (or the open
// descriptor it names), else a key made of its real directory and name.
struct FileIdentity {
    bool inode = false, shareable = false;
    dev_t dev = 0;
    ino_t ino = 0;
    std::string key;
    bool same(const FileIdentity& o) const { return inode ? o.inode && o.dev == dev && o.ino == ino : !o.inode && o.key == key; }
};

FileIdentity output_identity(const std::string& path) {
    FileIdentity id;
    try {
        const OutputTarget t = resolve_output(path);
        struct stat s {};
        if (t.kind == OutputTarget::Kind::descriptor ? ::fstat(t.fd, &s) == 0
                                                     : t.kind != OutputTarget::Kind::absent && ((s = t.st), true)) {
            id.inode = true;
            id.dev = s.st_dev;
            id.ino = s.st_ino;
            id.shareable = S_ISCHR(s.st_mode);
        } else if (t.kind == OutputTarget::Kind::descriptor) {
            id.key = "fd:" + std::to_string(t.fd);
        } else {
            char* real = ::realpath(t.dir.c_str(), nullptr);
            id.key = (real ? std::string(real) : t.dir) + "/" + t.name;
            std::free(real);
        }
    } catch (const IoError&) {
        id.key = path;  // not writable: reported when written
    }
    return id;
}

std::string quoted(const std::string& path) { return "'" + excerpt(path, 200) + "'"; }

}  // namespace

void require_safe_outputs(const NamedFiles& outputs, const NamedFiles& inputs, bool text_on_stdout) {
    std::vector<std::pair<size_t, FileIdentity>> seen;  // (index in outputs, identity)
    std::vector<int> streams;                            // descriptors to watch for their reader
    if (text_on_stdout) streams.push_back(STDOUT_FILENO);
    for (size_t i = 0; i < outputs.size(); ++i) {
        const auto& [option, path] = outputs[i];
        if (path.empty()) continue;
        const FileIdentity id = output_identity(path);
        for (const auto& [j, o] : seen) {
            if (!o.same(id) || id.shareable) continue;
            const auto& [o_option, o_path] = outputs[j];
            // The message begins with the options' names: no key before it (it would say them twice).
            throw InputError("", 0, 0, "",
                             o_option + " and " + option + " name the same file" +
                                 (o_path == path ? " " + quoted(path) : " (" + quoted(o_path) + " and " + quoted(path) + ")") +
                                 "; give two different files");
        }
        seen.emplace_back(i, id);
        try {
            if (const OutputTarget t = resolve_output(path); t.kind == OutputTarget::Kind::descriptor) streams.push_back(t.fd);
        } catch (const IoError&) {
            // not writable: reported when written
        }
    }
    // What is written: the outputs, and standard output when it is a regular file (whatever
    // a command prints lands there; `1<> case.yaml` would write into the case).
    struct Written {
        std::string option, path;
        FileIdentity id;
    };
    std::vector<Written> written;
    for (const auto& [j, o] : seen) written.push_back({outputs[j].first, outputs[j].second, o});
    if (struct stat out {}; ::fstat(STDOUT_FILENO, &out) == 0 && S_ISREG(out.st_mode)) {
        char name[PATH_MAX + 1] = {};
        const ssize_t n = ::readlink("/proc/self/fd/1", name, PATH_MAX);
        FileIdentity id;
        id.inode = true;
        id.dev = out.st_dev;
        id.ino = out.st_ino;
        written.push_back({"standard output", n > 0 ? std::string(name, static_cast<size_t>(n)) : std::string("-"), id});
    }
    // The inputs, the sidecars beside them, then the program itself: a regular file an output
    // leads to is refused.
    std::vector<std::pair<std::string, std::string>> read;  // (what it is, path)
    for (const auto& [in_option, in_path] : inputs) {
        if (in_path.empty() || in_path == "-") continue;
        read.emplace_back("the input " + in_option + " " + quoted(in_path), in_path);
        const std::string sidecar = in_path + kSidecarSuffix;
        read.emplace_back("the metadata " + quoted(sidecar) + " of the input " + in_option + " " + quoted(in_path), sidecar);
    }
    {
        char exe[PATH_MAX + 1] = {};
        const ssize_t n = ::readlink("/proc/self/exe", exe, PATH_MAX);
        read.emplace_back("the running program" + (n > 0 ? " " + quoted(std::string(exe, static_cast<size_t>(n))) : std::string()),
                          "/proc/self/exe");
    }
    for (const auto& [what, in_path] : read) {
        struct stat in {};
        if (::stat(in_path.c_str(), &in) != 0 || !S_ISREG(in.st_mode)) continue;
        for (const auto& w : written) {
            if (!w.id.inode || w.id.dev != in.st_dev || w.id.ino != in.st_ino) continue;
            throw InputError("", 0, 0, "",
                             w.option + " " + quoted(w.path) + " is " + what + "; write the output to another file");
        }
    }
    watch_stream_outputs(streams);
}

mode_t current_umask() {
    static const mode_t mask = [] {
        std::ifstream in("/proc/self/status");
        std::string line;
        while (std::getline(in, line))
            if (line.rfind("Umask:", 0) == 0) return static_cast<mode_t>(std::strtoul(line.c_str() + 6, nullptr, 8));
        const mode_t m = ::umask(022);  // no /proc: read it by setting it back
        ::umask(m);
        return m;
    }();
    return mask;
}

}  // namespace gearloss::io
