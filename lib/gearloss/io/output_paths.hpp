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

// Removes the temporary files of the output DIR/NAME left by a dead run: named as above,
// regular, owned by the caller (any owner for root) and not locked, whatever their age. A
// running writer holds an flock on its temporary from its creation to its rename
// (create_locked_temporary), and the kernel drops that lock the moment the process ends,
// however it ends (kill -9, a signal without a handler): an unlocked temporary has no
// writer. The age says nothing: a writer may run for hours, a dead run's file is seconds old.
void remove_stale_temporaries(const std::string& dir, const std::string& name);

// Creates DIR/temp_prefix(NAME)XXXXXX with O_EXCL (mode 0600), locks it (flock, waiting
// for a cleaner that holds it for a moment) and checks it still has its name (a cleaner
// of another run may have removed it in the instant before the lock): then it is made
// again. The target's stale temporaries are removed first. Returns the descriptor and sets
// `path`; -1 with errno set when the directory refuses the file.
int create_locked_temporary(const std::string& dir, const std::string& name, std::string& path);

// The files of one run, as (option or key, path) pairs; empty paths are skipped.
using NamedFiles = std::vector<std::pair<std::string, std::string>>;

// The suffix of the sidecar a CSV output gets (FILE.meta.json, map::sidecar_path): the
// sidecar of an input (a recording's rec.csv.meta.json) is kept from the outputs like the input.
inline constexpr const char* kSidecarSuffix = ".meta.json";

// The one check of a run's files, made before anything is computed or written; each
// failure is an InputError (exit 2) naming both paths and both options or keys:
//  - two outputs leading to the same file (after links, by st_dev/st_ino when the file
//    exists, else by the real directory and name; "-" and /dev/stdout are the same); a
//    character device (terminal, /dev/null) may take several outputs;
//  - an output that is one of the inputs (`map case.yaml -o case.yaml`), compared by
//    st_dev/st_ino after links; inputs that do not exist or are not regular files are
//    skipped;
//  - an output that is the running program (the file /proc/self/exe leads to);
//  - an output that is the sidecar (FILE.meta.json) of an input FILE;
//  - standard output, for every command, when it is a regular file (`1<> case.yaml`): the
//    text a command prints there (check, point, diagnose, the cycle summary, `-o -`) must
//    not land on an input or the program either (it is not compared with the other outputs:
//    "-" is that same stream, written in turn).
// The caller lists every output with its derived names (sidecars, per-gear files) and
// every input with the files they name (app/commands/common.hpp: case_inputs).
// Then every output that is a pipe, FIFO or socket reached through a descriptor ("-",
// /dev/stdout, /dev/fd/N), and standard output when `text_on_stdout` (the command prints
// its result there), is watched from this moment (io::watch_stream_outputs): a reader that
// goes away ends the run within a second, while the output is still being computed.
void require_safe_outputs(const NamedFiles& outputs, const NamedFiles& inputs, bool text_on_stdout = false);

// The process umask, read without changing it.
mode_t current_umask();

}  // namespace gearloss::io
