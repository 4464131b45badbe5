#include "gearloss/io/atomic_file.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <thread>
#include <poll.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <tuple>
#include <unistd.h>

#include "gearloss/io/interrupt.hpp"

namespace gearloss::io {

namespace {

std::string g_incomplete_stream;  // set by ~AtomicFile, on the thread that owns the file (the main one)

// A completed temporary file waiting for its rename.
struct Pending {
    int fd;
    std::string tmp, dir, name, shown;
};

struct Transaction {
    bool active = false;
    std::vector<Pending> pending;
};
Transaction& transaction() {
    static Transaction t;
    return t;
}

std::string why(int e) { return std::strerror(e); }

void interrupted_check(const std::string& label) {
    if (g_interrupted.load(std::memory_order_relaxed)) throw IoError("interrupted while writing " + label);
}

bool is_regular(int fd) {
    struct stat s {};
    return ::fstat(fd, &s) == 0 && S_ISREG(s.st_mode);
}

// A reader closed the pipe `label` writes to (EPIPE): the run ends as on SIGPIPE.
[[noreturn]] void reader_closed(const std::string& label) {
    on_reader_closed();
    throw IoError("the reader closed the pipe of the output " + label);
}

// Writes all of [p, p+n) to fd. On a pipe, FIFO or terminal it waits with poll() in short
// steps and writes at most PIPE_BUF bytes at a time, so an interrupt is seen even when the
// reader stalls. Throws IoError on any error (a closed pipe: reader_closed) or on an
// interrupt.
void write_all(int fd, const char* p, size_t n, bool waitable, const std::string& label) {
    while (n > 0) {
        interrupted_check(label);
        size_t chunk = std::min(n, size_t(1) << 20);
        if (waitable) {
            pollfd pfd{fd, POLLOUT, 0};
            const int r = ::poll(&pfd, 1, 200);
            if (r < 0 && errno != EINTR) throw IoError("cannot write " + label + ": " + why(errno));
            if (r <= 0) continue;
            chunk = std::min(n, size_t(PIPE_BUF));
        }
        const ssize_t w = ::write(fd, p, chunk);
        if (w < 0) {
            if (errno == EINTR) continue;
            if (errno == EAGAIN || errno == EWOULDBLOCK) {  // a non-blocking descriptor inherited
                waitable = true;
                continue;
            }
            if (errno == EPIPE) reader_closed(label);
            throw IoError("cannot write " + label + ": " + why(errno));
        }
        p += w;
        n -= static_cast<size_t>(w);
    }
}

void fsync_directory(const std::string& dir) {
    const int d = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (d < 0) return;
    ::fsync(d);  // durability of the rename; some file systems refuse it, harmlessly
    ::close(d);
}

// Locks (flock) on the directories a group of renames goes into, taken in one order
// (device, inode) so that two runs never wait for each other in a circle. Runs that publish
// onto the same files then do so one after the other, and the files left are all from the
// last of them: a CSV and its sidecar always come from one run. A directory that cannot be
// opened for reading is renamed into without its lock.
class DirectoryLocks {
public:
    explicit DirectoryLocks(const std::vector<Pending>& list) {
        std::vector<std::tuple<dev_t, ino_t, int>> dirs;
        for (const auto& p : list) {
            const int d = ::open(p.dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
            struct stat s {};
            if (d < 0) continue;
            if (::fstat(d, &s) != 0) {
                ::close(d);
                continue;
            }
            dirs.emplace_back(s.st_dev, s.st_ino, d);
        }
        std::sort(dirs.begin(), dirs.end());
        for (size_t i = 0; i < dirs.size(); ++i) {
            const auto [dev, ino, d] = dirs[i];
            if (i > 0 && std::get<0>(dirs[i - 1]) == dev && std::get<1>(dirs[i - 1]) == ino) {
                ::close(d);
                continue;
            }
            while (::flock(d, LOCK_EX) != 0 && errno == EINTR) {}
            fds_.push_back(d);
        }
    }
    ~DirectoryLocks() {
        for (int d : fds_) ::close(d);  // closing releases the lock
    }
    DirectoryLocks(const DirectoryLocks&) = delete;
    DirectoryLocks& operator=(const DirectoryLocks&) = delete;

private:
    std::vector<int> fds_;
};

void rename_into_place(Pending& p) {
    const std::string target = (p.dir == "/" ? "/" : p.dir + "/") + p.name;
    if (::rename(p.tmp.c_str(), target.c_str()) != 0) {
        const int e = errno;
        ::close(p.fd);
        ::unlink(p.tmp.c_str());
        throw IoError("cannot rename into '" + p.shown + "': " + why(e));
    }
    fsync_directory(p.dir);
    ::close(p.fd);  // releases the lock only now: the file has its final name
}

void discard(std::vector<Pending>& list) {
    for (auto& p : list) {
        ::close(p.fd);
        ::unlink(p.tmp.c_str());
    }
    list.clear();
}

}  // namespace

// While a pipe, FIFO or socket receives a streamed output, a thread waits for its reader to
// go (poll() reports POLLERR on a pipe without readers, POLLHUP on a socket shut by its
// peer): the run then ends as on SIGPIPE at once, not at the next write, which a map may make
// only after minutes of computing (a megabyte of rows is buffered between writes).
class ReaderWatch {
public:
    explicit ReaderWatch(int fd) : fd_(fd), thread_([this] { run(); }) {}
    ~ReaderWatch() {
        stop_.store(true, std::memory_order_relaxed);
        thread_.join();
    }
    ReaderWatch(const ReaderWatch&) = delete;
    ReaderWatch& operator=(const ReaderWatch&) = delete;

    // A descriptor worth watching: a pipe, FIFO or socket (a terminal has SIGHUP).
    static bool watchable(int fd) {
        struct stat s {};
        return ::fstat(fd, &s) == 0 && (S_ISFIFO(s.st_mode) || S_ISSOCK(s.st_mode));
    }

private:
    void run() {
        while (!stop_.load(std::memory_order_relaxed)) {
            pollfd pfd{fd_, 0, 0};  // no event asked: POLLERR and POLLHUP are always reported
            const int r = ::poll(&pfd, 1, 100);
            if (r > 0 && (pfd.revents & (POLLERR | POLLHUP)) && !stop_.load(std::memory_order_relaxed)) {
                on_reader_closed();
                return;
            }
            if (r < 0 && errno != EINTR) return;
        }
    }
    int fd_;
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

namespace {

// The watches of the run's streamed outputs (watch_stream_outputs), by descriptor; used on
// the main thread only.
std::vector<std::pair<int, std::unique_ptr<ReaderWatch>>>& run_watches() {
    static std::vector<std::pair<int, std::unique_ptr<ReaderWatch>>> w;
    return w;
}

// The output written to `fd` takes over (or the run ends): its run watch stops.
void end_run_watch(int fd) {
    auto& w = run_watches();
    w.erase(std::remove_if(w.begin(), w.end(), [fd](const auto& e) { return e.first == fd; }), w.end());
}

}  // namespace

void watch_stream_outputs(const std::vector<int>& fds) {
    auto& w = run_watches();
    for (const int fd : fds)
        if (ReaderWatch::watchable(fd) && std::none_of(w.begin(), w.end(), [fd](const auto& e) { return e.first == fd; }))
            w.emplace_back(fd, std::make_unique<ReaderWatch>(fd));
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), label_("'" + path_ + "'") {
    target_ = resolve_output(path_);
    switch (target_.kind) {
    case OutputTarget::Kind::descriptor: {
        fd_ = target_.fd;
        end_run_watch(fd_);  // this file's own watch takes over
        if (fd_ == 1) {
            label_ = "to standard output";
            std::fflush(stdout);  // keep the order of text printed through stdio (errors: see finish_stdout)
        }
        struct stat s {};
        if (::fstat(fd_, &s) != 0) throw IoError("cannot write " + label_ + ": " + why(errno));
        waitable_ = !S_ISREG(s.st_mode);
        if (ReaderWatch::watchable(fd_)) watch_ = std::make_unique<ReaderWatch>(fd_);
        if (S_ISREG(s.st_mode)) {  // `> out.csv` (or `>>`): where to cut back an abandoned output
            const int flags = ::fcntl(fd_, F_GETFL);
            rewind_to_ = flags >= 0 && (flags & O_APPEND) ? static_cast<long long>(s.st_size)
                                                           : static_cast<long long>(::lseek(fd_, 0, SEEK_CUR));
        }
        break;
    }
    case OutputTarget::Kind::direct:
        open_direct();
        break;
    case OutputTarget::Kind::absent:
    case OutputTarget::Kind::regular:
        create_temporary();
        break;
    }
}

// A character device or FIFO: opened for writing as it is (no O_CREAT, no O_TRUNC). A
// FIFO without a reader is waited for in short steps, so an interrupt ends the wait.
void AtomicFile::open_direct() {
    const std::string p = target_.path();
    const bool fifo = S_ISFIFO(target_.st.st_mode);
    const int flags = O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NOFOLLOW | (fifo ? O_NONBLOCK : 0);
    for (;;) {
        fd_ = ::open(p.c_str(), flags);
        if (fd_ >= 0) break;
        if (errno == EINTR) continue;
        if (fifo && errno == ENXIO) {  // no reader yet
            interrupted_check(label_);
            const timespec step{0, 50'000'000};
            ::nanosleep(&step, nullptr);
            continue;
        }
        throw IoError("cannot write " + label_ + ": " + why(errno));
    }
    own_fd_ = true;
    struct stat s {};
    if (::fstat(fd_, &s) != 0 || s.st_dev != target_.st.st_dev || s.st_ino != target_.st.st_ino || S_ISREG(s.st_mode)) {
        ::close(fd_);
        fd_ = -1;
        throw IoError("cannot write " + label_ + ": the file changed while it was opened");
    }
    if (fifo) ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
    waitable_ = true;
    if (ReaderWatch::watchable(fd_)) watch_ = std::make_unique<ReaderWatch>(fd_);
}

void AtomicFile::create_temporary() {
    std::string tmpl;
    fd_ = create_locked_temporary(target_.dir, target_.name, tmpl);  // locked: "in use" until renamed or removed
    if (fd_ < 0)
        throw IoError("cannot write " + label_ + ": cannot create a temporary file in '" + target_.dir + "': " + why(errno));
    own_fd_ = true;
    tmp_ = tmpl;
    mode_t mode = 0666 & ~current_umask();
    if (target_.kind == OutputTarget::Kind::regular) {
        const struct stat& st = target_.st;
        // The owner can only be given away by root; the group also by a member of it.
        // Failures leave the file to the caller, as a new file would be.
        if (::geteuid() == 0) {
            if (::fchown(fd_, st.st_uid, st.st_gid) != 0) {}
        } else if (st.st_gid != ::getegid()) {
            if (::fchown(fd_, static_cast<uid_t>(-1), st.st_gid) != 0) {}
        }
        mode = st.st_mode & 07777;  // after fchown, which may clear set-id bits
    }
    if (::fchmod(fd_, mode) != 0) {
        const int e = errno;
        ::close(fd_);
        ::unlink(tmp_.c_str());
        fd_ = -1;
        throw IoError("cannot write " + label_ + ": " + why(e));
    }
}

AtomicFile::~AtomicFile() {
    watch_.reset();
    if (!committed_ && wrote_ && tmp_.empty() && fd_ >= 0) {
        // A direct output abandoned part-way: a regular file is cut back (a shell's `> out.csv`
        // then holds what it held before); a stream cannot be, and the messages say so.
        if (rewind_to_ >= 0 && ::ftruncate(fd_, static_cast<off_t>(rewind_to_)) == 0)
            (void)::lseek(fd_, static_cast<off_t>(rewind_to_), SEEK_SET);
        else
            g_incomplete_stream = label_;
    }
    if (own_fd_ && fd_ >= 0) ::close(fd_);
    if (!committed_ && !tmp_.empty()) ::unlink(tmp_.c_str());
}

void AtomicFile::write(std::string_view s) {
    interrupted_check(label_);
    buf_.append(s);
    // A stream (pipe, FIFO, terminal) also gets what is ready every 0.2 s: its reader sees the
    // rows as they come (`map ... -o - | head -2` gets its lines at once, not after a megabyte).
    const auto now = std::chrono::steady_clock::now();
    if (buf_.size() >= (size_t(1) << 20) || (waitable_ && now - last_flush_ >= std::chrono::milliseconds(200))) {
        flush_buffer();
        last_flush_ = now;
    }
}

void AtomicFile::flush_buffer() {
    if (buf_.empty()) return;
    wrote_ = true;
    write_all(fd_, buf_.data(), buf_.size(), waitable_, label_);
    buf_.clear();
}

void AtomicFile::commit() {
    if (committed_) return;
    // The watch stops before the last write: a reader already gone is seen by that write
    // (EPIPE), and one that leaves once every byte went out loses nothing and ends nothing.
    watch_.reset();
    flush_buffer();
    if (tmp_.empty()) {  // written directly
        if (own_fd_) {
            const int fd = fd_;
            fd_ = -1;
            if (::close(fd) != 0 && errno != EINTR) throw IoError("cannot write " + label_ + ": " + why(errno));
        }
        committed_ = true;
        return;
    }
    if (::fsync(fd_) != 0) throw IoError("cannot write " + label_ + ": " + why(errno));
    interrupted_check(label_);
    Pending p{fd_, tmp_, target_.dir, target_.name, path_};
    fd_ = -1;
    committed_ = true;  // the temporary file now belongs to the transaction or is renamed
    auto& tx = transaction();
    if (tx.active) {
        tx.pending.push_back(std::move(p));
    } else {
        const DirectoryLocks locks({p});
        rename_into_place(p);
    }
}

OutputTransaction::OutputTransaction() { transaction().active = true; }

OutputTransaction::~OutputTransaction() {
    run_watches().clear();
    auto& tx = transaction();
    discard(tx.pending);
    tx.active = false;
}

void OutputTransaction::publish() {
    auto& tx = transaction();
    finish_stdout();
    if (g_interrupted) throw IoError("interrupted; no output file written");
    std::vector<Pending> list = std::move(tx.pending);
    tx.pending.clear();
    tx.active = false;
    const DirectoryLocks locks(list);
    for (size_t i = 0; i < list.size(); ++i) {
        try {
            rename_into_place(list[i]);
        } catch (...) {
            std::vector<Pending> rest(list.begin() + static_cast<long>(i) + 1, list.end());
            discard(rest);
            throw;
        }
    }
}

std::string incomplete_stream() { return g_incomplete_stream; }

void finish_stdout() {
    const bool flushed = std::fflush(stdout) == 0;
    const int e = errno;
    if (flushed && !std::ferror(stdout)) return;
    std::clearerr(stdout);
    // An earlier stdio write may have failed: a pipe without a reader ends the run as SIGPIPE.
    pollfd pfd{STDOUT_FILENO, POLLOUT, 0};
    if ((!flushed && e == EPIPE) || (::poll(&pfd, 1, 0) == 1 && (pfd.revents & POLLERR))) reader_closed("to standard output");
    throw IoError("cannot write to standard output: " + (flushed ? std::string("write error") : why(e)));
}

void write_stdout(std::string_view text) {
    finish_stdout();
    // The text is written now, in one go: a reader already gone is seen by the write itself
    // (EPIPE), and one that leaves once every byte went out loses nothing and ends nothing
    // (the watch, stopped after the write, could see it leave an instant later).
    end_run_watch(STDOUT_FILENO);
    write_all(STDOUT_FILENO, text.data(), text.size(), !is_regular(STDOUT_FILENO), "to standard output");
}

}  // namespace gearloss::io
