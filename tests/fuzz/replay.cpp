// Replays the fuzz seed corpus and every saved finding through the fuzz
// bodies, as an ordinary test: a reproducer once found stays fixed. Each input
// runs under a time limit (SIGALRM), so a hang fails the test and names the input.
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>
#include <vector>

#include "fuzz_harness.hpp"

namespace {
constexpr unsigned kSecondsPerInput = 60;  // libFuzzer runs use -timeout=20; sanitizers and shared cores here
char g_current[4096] = "";

void on_alarm(int) {
    const char head[] = "FUZZ FINDING: hang (no result within the per-input time limit): ";
    (void)!::write(2, head, sizeof head - 1);
    (void)!::write(2, g_current, std::strlen(g_current));
    (void)!::write(2, "\n", 1);
    ::_exit(1);
}
}  // namespace

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    if (argc < 2) return 2;
    std::signal(SIGALRM, on_alarm);
    const fs::path root = argv[1];
    size_t n = 0;
    for (const char* target : {"config", "recordings", "map"})
        for (const char* kind : {"corpus", "regressions"}) {
            const fs::path dir = root / kind / target;
            if (!fs::exists(dir)) continue;
            for (const auto& e : fs::directory_iterator(dir)) {
                if (!e.is_regular_file() || e.path().filename() == ".keep") continue;
                std::ifstream in(e.path(), std::ios::binary);
                const std::vector<char> buf((std::istreambuf_iterator<char>(in)), {});
                const auto* d = reinterpret_cast<const uint8_t*>(buf.data());
                std::snprintf(g_current, sizeof g_current, "%s", e.path().c_str());
                ::alarm(kSecondsPerInput);
                if (std::string(target) == "config") fuzz::config_one(d, buf.size());
                else if (std::string(target) == "recordings") fuzz::recordings_one(d, buf.size());
                else fuzz::map_one(d, buf.size());
                ::alarm(0);
                ++n;
            }
        }
    std::printf("%zu passed, 0 failed\n", n);
    return 0;
}
