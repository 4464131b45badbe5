#pragma once
// The folder of the data gearloss ships and reads at run time (the named drive cycles,
// cycles/*.csv), found where the program runs rather than where it was built. In order:
//  1. $GEARLOSS_DATA_DIR, when set and not empty (then the only place searched);
//  2. <exe>/../share/gearloss: an installed binary, <prefix>/bin/gearloss (cmake --install);
//  3. <exe>/../../configs: a binary in a build folder of the source tree, <src>/<build>/app/gearloss.
// <exe> is the folder of the running executable (/proc/self/exe, links resolved). A place
// holds the data when it has a cycles/ folder.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gearloss::io {

struct DataDirSearch {
    std::optional<std::filesystem::path> dir;  // the first place that holds the data
    std::vector<std::string> tried;            // every place looked at, with why it was not taken
    // "searched: A (no cycles/ folder); B (...). Set GEARLOSS_DATA_DIR to ..." for messages.
    std::string explain() const;
};

// The search above for this process (never throws).
DataDirSearch find_data_dir();
// The same from the given value of GEARLOSS_DATA_DIR (nullptr: unset) and path of the
// executable (empty: unknown).
DataDirSearch find_data_dir(const char* env_value, const std::filesystem::path& executable);

// The data folder; when no place holds the data, an InputError (exit 2) under `key` (the
// option that needed the data) saying `need` ("'nedc' is a shipped cycle") and naming every
// place searched.
std::filesystem::path data_dir(const std::string& key, const std::string& need);

}  // namespace gearloss::io
