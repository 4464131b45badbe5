#include "gearloss/report/pdf_print.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "gearloss/core/errors.hpp"
#include "gearloss/core/interrupt.hpp"

namespace gearloss::report {
namespace {

namespace fs = std::filesystem;

bool is_executable(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

// `name` as the shell finds it: a path as given, else the first executable of that name on PATH.
std::string on_path(const std::string& name) {
    if (name.find('/') != std::string::npos) return is_executable(name) ? name : std::string();
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/" + name;
        if (is_executable(candidate)) return candidate;
    }
    return {};
}

std::string read_all(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The last `n` non-empty lines of a text, for an error message.
std::string last_lines(const std::string& text, size_t n) {
    std::vector<std::string> lines;
    std::stringstream in(text);
    for (std::string l; std::getline(in, l);)
        if (l.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(l);
    std::string s;
    for (size_t i = lines.size() > n ? lines.size() - n : 0; i < lines.size(); ++i) s += "\n  " + lines[i];
    return s;
}

// A private directory removed with everything in it when the print is over.
struct TemporaryDirectory {
    fs::path path;
    TemporaryDirectory() {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/gearloss-pdf-XXXXXX";
        if (!::mkdtemp(pattern.data())) throw IoError(fmt::format("--pdf: cannot create a temporary directory: {}", std::strerror(errno)));
        path = pattern;
    }
    ~TemporaryDirectory() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    TemporaryDirectory(const TemporaryDirectory&) = delete;
    TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
};

}  // namespace

std::string find_chromium() {
    if (const char* c = std::getenv("CHROMIUM"); c && *c) return on_path(c);
    for (const char* name : {"chromium", "chromium-browser", "google-chrome", "google-chrome-stable"})
        if (std::string p = on_path(name); !p.empty()) return p;
    return {};
}

std::string print_pdf(const std::string& html, const std::string& option, double timeout_s) {
    const std::string browser = find_chromium();
    if (browser.empty()) {
        const char* c = std::getenv("CHROMIUM");
        throw InputError("", 0, 0, option,
                         c && *c ? fmt::format("prints with headless Chromium: CHROMIUM={} is not an executable", c)
                                 : "prints with headless Chromium, and none was found (chromium, chromium-browser, "
                                   "google-chrome on PATH; scripts/install-deps.sh report installs Debian's 'chromium', or set CHROMIUM=/path/to/chromium)");
    }
    TemporaryDirectory dir;
    const fs::path page = dir.path / "report.html", pdf = dir.path / "report.pdf", log = dir.path / "chromium.log";
    {
        std::ofstream out(page, std::ios::binary);
        out << html;
        if (!out.flush()) throw IoError(fmt::format("{}: cannot write the page to print into {}", option, dir.path.string()));
    }
    std::vector<std::string> args = {browser, "--headless", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run",
                                     "--no-default-browser-check", "--disable-extensions", "--disable-background-networking",
                                     "--disable-component-update", "--disable-sync", "--mute-audio",
                                     "--user-data-dir=" + (dir.path / "profile").string(), "--no-pdf-header-footer",
                                     "--virtual-time-budget=5000", "--print-to-pdf=" + pdf.string(), "file://" + page.string()};
    // Chromium's sandbox refuses to start as root; the page is gearloss's own and loads nothing.
    if (::geteuid() == 0) args.insert(args.begin() + 1, "--no-sandbox");
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string cache = (dir.path / "cache").string(), config = (dir.path / "config").string();

    const pid_t pid = ::fork();
    if (pid < 0) throw IoError(fmt::format("{}: cannot start {}: {}", option, browser, std::strerror(errno)));
    if (pid == 0) {  // the child: its own process group (so that a deadline ends its helpers too), output to the log
        ::setpgid(0, 0);
        const int in = ::open("/dev/null", O_RDONLY), out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (in >= 0) ::dup2(in, 0);
        if (out >= 0) ::dup2(out, 1), ::dup2(out, 2);
        ::setenv("XDG_CACHE_HOME", cache.c_str(), 1);
        ::setenv("XDG_CONFIG_HOME", config.c_str(), 1);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    ::setpgid(pid, pid);  // also from here, whichever runs first
    const auto t0 = std::chrono::steady_clock::now();
    int status = 0;
    bool timed_out = false;
    for (;;) {
        const pid_t r = ::waitpid(pid, &status, WNOHANG);
        if (r == pid || (r < 0 && errno != EINTR)) break;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (interrupted() || elapsed > timeout_s) {
            timed_out = !interrupted();
            ::kill(-pid, SIGKILL);
            while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ::kill(-pid, SIGKILL);  // helpers of the browser that outlived it (none when it exits cleanly)
    throw_if_interrupted();
    const std::string output = read_all(log);
    if (timed_out)
        throw IoError(fmt::format("{}: {} did not finish printing within {} s{}", option, browser, timeout_s, last_lines(output, 5)));
    std::string bytes = fs::exists(pdf) ? read_all(pdf) : std::string();
    if (bytes.rfind("%PDF-", 0) != 0) {
        const std::string how = WIFEXITED(status) ? fmt::format("exit status {}", WEXITSTATUS(status))
                                                  : fmt::format("signal {}", WIFSIGNALED(status) ? WTERMSIG(status) : 0);
        throw IoError(fmt::format("{}: {} wrote no PDF ({}){}", option, browser, how, last_lines(output, 5)));
    }
    return bytes;
}

}  // namespace gearloss::report
