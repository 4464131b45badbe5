#pragma once
// Output files are written to a temporary file beside the target and renamed over it
// only when complete, so a reader never sees a partial file and an interrupted run
// leaves the previous file (or none). Details (lib/gearloss/io/output_paths.hpp):
//  - the temporary file TARGET.tmp.gearloss-XXXXXX is created with O_EXCL (mkostemp) in
//    the directory of the file finally written, with the target's mode (and owner, as
//    root) when it exists, else 0666 & ~umask; it is flock'ed from its creation to its
//    rename, and the next run on the target removes a dead run's unlocked temporary;
//  - a symbolic link is written through: the link stays, the file it names is replaced;
//  - "-", /dev/stdout, /dev/fd/N, a character device or a FIFO is written directly,
//    never replaced, as the text comes (a map streams its rows; a stream gets what is
//    ready at least every 0.2 s); when such a write is not
//    committed (error, interrupt), a regular file behind the descriptor (`> out.csv`) is
//    cut back to where it stood, and a pipe, FIFO or terminal, which cannot be taken back,
//    is reported as incomplete (incomplete_stream);
//  - every write, flush, fsync, close and rename is checked (IoError, exit 3); a reader
//    that closed its pipe (EPIPE, or seen by a watch while a pipe, FIFO or socket is
//    written) ends the run as SIGPIPE does (gearloss/io/interrupt.hpp: on_reader_closed);
//  - an interrupt (g_interrupted) stops the writing (IoError) and nothing is renamed;
//  - the renames of one run hold an flock on each target directory, so two runs writing
//    the same files leave all the files of one of them (a CSV and its sidecar agree).
#include <chrono>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "gearloss/core/errors.hpp"
#include "gearloss/core/interrupt.hpp"
#include "gearloss/io/output_paths.hpp"

namespace gearloss::io {

class ReaderWatch;

class AtomicFile {
public:
    explicit AtomicFile(std::string path);   // "-" writes to stdout directly
    ~AtomicFile();                            // discards the temporary file if not committed
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    void write(std::string_view s);
    // Flush, fsync and rename (inside an OutputTransaction: the rename waits for
    // publish()); throws IoError on failure or interrupt.
    void commit();

private:
    void flush_buffer();
    void open_direct();
    void create_temporary();

    std::string path_, label_;  // as given; "'path'" or "to standard output" for messages
    OutputTarget target_;
    int fd_ = -1;
    bool own_fd_ = false, waitable_ = false, committed_ = false;
    std::unique_ptr<ReaderWatch> watch_;  // a pipe, FIFO or socket: its reader's leaving ends the run
    std::chrono::steady_clock::time_point last_flush_ = std::chrono::steady_clock::now();
    std::string tmp_;           // temporary file, empty when written directly
    std::string buf_;
    long long rewind_to_ = -1;  // a regular file written through a descriptor: its offset before
    bool wrote_ = false;        // bytes reached the target before commit
};

// The label ("to standard output", "'fifo'") of a direct target that received part of an
// output that was then abandoned (error, interrupt), or empty: the messages say so.
std::string incomplete_stream();

// The files of one command appear together: while an OutputTransaction exists,
// AtomicFile::commit() leaves the completed temporary file in place and publish()
// renames them all, after flushing stdout (checked) and checking for an interrupt. The
// destructor removes the temporary files not published (error, interrupt).
class OutputTransaction {
public:
    OutputTransaction();
    ~OutputTransaction();
    OutputTransaction(const OutputTransaction&) = delete;
    OutputTransaction& operator=(const OutputTransaction&) = delete;
    void publish();
};

// The descriptors (standard output, /dev/fd/N) of a run's streamed outputs, watched from
// the check of its files (require_safe_outputs) until they are written: while the output is
// still being computed (a report, a synthesised campaign, a diagnosis, a cycle), a pipe,
// FIFO or socket whose reader goes away ends the run within a second as SIGPIPE does
// (on_reader_closed), not at the first write at the end. The output written to that
// descriptor (AtomicFile, write_stdout) takes over: its watch ends with its last byte, so a
// reader that leaves once everything arrived loses nothing and ends nothing. Descriptors
// that are not a pipe, FIFO or socket are not watched; the end of the run's
// OutputTransaction stops every watch.
void watch_stream_outputs(const std::vector<int>& fds);

// Text on standard output, checked: IoError on a write error (e.g. ENOSPC on /dev/full);
// a closed pipe (EPIPE) ends the run as SIGPIPE (on_reader_closed, then IoError).
void write_stdout(std::string_view text);
// Flushes stdio's stdout, checked as write_stdout.
void finish_stdout();

// IoError (exit 3) and the interrupt flag (set by the signal handler: long loops stop and
// outputs are discarded) are core's; the io names stay.
using gearloss::g_interrupted;
using gearloss::IoError;

}  // namespace gearloss::io
