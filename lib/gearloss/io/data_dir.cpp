#include "gearloss/io/data_dir.hpp"

#include <cstdlib>
#include <system_error>

#include "gearloss/core/errors.hpp"

namespace gearloss::io {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMarker = "cycles";  // a data folder holds cycles/

// Whether `dir` holds the data; otherwise why not, appended to `tried`.
bool holds_data(const fs::path& dir, const std::string& label, std::vector<std::string>& tried) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        tried.push_back(label + dir.string() + " (not a folder)");
        return false;
    }
    if (!fs::is_directory(dir / kMarker, ec)) {
        tried.push_back(label + dir.string() + " (no " + kMarker + "/ folder there)");
        return false;
    }
    return true;
}

}  // namespace

std::string DataDirSearch::explain() const {
    std::string s = "searched: ";
    for (size_t i = 0; i < tried.size(); ++i) s += (i ? "; " : "") + tried[i];
    return s + ". Set GEARLOSS_DATA_DIR to the folder that holds " + kMarker +
           "/ (<prefix>/share/gearloss of an installation, configs/ of the source tree)";
}

DataDirSearch find_data_dir(const char* env_value, const fs::path& executable) {
    DataDirSearch r;
    if (env_value && *env_value) {
        const fs::path d(env_value);
        if (holds_data(d, "GEARLOSS_DATA_DIR=", r.tried)) r.dir = d;
        return r;  // an explicit setting is the only place searched
    }
    if (executable.empty()) {
        r.tried.push_back("the folder of the executable (its path is unknown: /proc/self/exe cannot be read)");
        return r;
    }
    const fs::path bin = executable.parent_path();
    for (const fs::path& d : {bin / ".." / "share" / "gearloss", bin / ".." / ".." / "configs"}) {
        const fs::path n = d.lexically_normal();
        if (holds_data(n, "", r.tried)) {
            r.dir = n;
            return r;
        }
    }
    return r;
}

DataDirSearch find_data_dir() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return find_data_dir(std::getenv("GEARLOSS_DATA_DIR"), ec ? fs::path() : exe);
}

fs::path data_dir(const std::string& key, const std::string& need) {
    const DataDirSearch s = find_data_dir();
    if (s.dir) return *s.dir;
    throw InputError("", 0, 0, key, need + ", but the folder of gearloss's shipped data was not found; " + s.explain());
}

}  // namespace gearloss::io
