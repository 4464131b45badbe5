// Replays the fuzz seed corpus and every saved finding through the fuzz
// bodies, as an ordinary test: a reproducer once found stays fixed.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz_harness.hpp"

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    if (argc < 2) return 2;
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
                if (std::string(target) == "config") fuzz::config_one(d, buf.size());
                else if (std::string(target) == "recordings") fuzz::recordings_one(d, buf.size());
                else fuzz::map_one(d, buf.size());
                ++n;
            }
        }
    std::printf("%zu passed, 0 failed\n", n);
    return 0;
}
