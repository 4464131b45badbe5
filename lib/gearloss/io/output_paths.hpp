#pragma once
// Where an output path really leads, before anything is written to it:
//  - "-", /dev/stdout, /dev/stderr, /dev/fd/N and /proc/self/fd/N are open descriptors
//    (written directly, never replaced);
//  - a symbolic link is followed to the file it names (a dangling link to the file it
//    would create), so the link stays a link and its target is what gets replaced;
//  - an existing character device or FIFO is written directly (O_WRONLY, no O_CREAT or
//    O_TRUNC); a directory, block device or socket is refused;
//  - a regular file (or a missing one) is written through a temporary file beside it.
#include <string>
#include <sys/stat.h>
#include <utility>
#include <vector>

namespace gearloss::io {

struct OutputTarget {
    enum class Kind { descriptor, absent, regular, direct };
    Kind kind = Kind::absent;
    int fd = -1;        // descriptor: the descriptor to write to (1 for "-" and /dev/stdout)
    std::string dir;    // absent, regular, direct: directory of the resolved path ("." when relative)
    std::string name;   // absent, regular, direct: last component, never a symbolic link
    struct stat st {};  // regular, direct: the file found there
    std::string path() const { return dir == "/" ? "/" + name : dir + "/" + name; }
};

// Throws IoError (exit 3) for a loop of links, a directory, a block device, a socket or
// a path ending in '/'.
OutputTarget resolve_output(const std::string& path);

// Each temporary file is named TARGET.tmp.gearloss-XXXXXX (6 random characters, created
// with O_EXCL in the target's directory); TARGET is shortened if the name would exceed
// NAME_MAX.
inline constexpr const char* kTempMarker = ".tmp.gearloss-";
std::string temp_prefix(const std::string& name);

// Removes the temporary files of the output DIR/NAME left by a killed run: named as
// above, regular, owned by the caller (any owner for root), last modified more than
// kStaleTempSeconds ago and not locked (a running writer holds an flock on its own).
inline constexpr int kStaleTempSeconds = 300;
void remove_stale_temporaries(const std::string& dir, const std::string& name);

// The outputs of one command, as (option, path) pairs (empty paths are skipped): two of
// them leading to the same file (after links, compared by st_dev/st_ino when the file
// exists; "-" and /dev/stdout are the same) throw InputError (exit 2) naming both
// options. A character device (terminal, /dev/null) may take several outputs.
void require_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& outputs);

// An output that is one of the command's input files (same file after links) throws
// InputError (exit 2) naming both: `map case.yaml -o case.yaml` must not replace the case.
// Pairs are (option, path); empty paths and inputs that do not exist are skipped.
void require_outputs_not_inputs(const std::vector<std::pair<std::string, std::string>>& outputs,
                                const std::vector<std::pair<std::string, std::string>>& inputs);

// The process umask, read without changing it.
mode_t current_umask();

}  // namespace gearloss::io
