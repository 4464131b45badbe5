#pragma once
// SIGINT, SIGTERM, SIGHUP, SIGQUIT and SIGPIPE stop any command alike (README "Exit codes"):
//  - on_interrupt_signal (the handler of each, kInterruptSignals) sets g_interrupted
//    (gearloss/core/interrupt.hpp) and remembers the signal;
//  - a reader that closes a pipe the run writes to (EPIPE, or the watch of a streamed output,
//    gearloss/io/atomic_file.hpp) is SIGPIPE: on_reader_closed;
//  - every long loop polls interrupted(): outside a parallel region it throws Interrupted
//    (throw_if_interrupted), inside one it skips the remaining iterations and the code after
//    the region throws;
//  - Interrupted is an IoError: nothing is renamed, temporary files are removed, and the
//    command ends with interrupt_exit_code(), 128 + the signal number (130 SIGINT, 143 SIGTERM,
//    129 SIGHUP, 131 SIGQUIT, 141 SIGPIPE), after report_interrupt() said so on stderr.
#include <atomic>
#include <string>
#include <csignal>
#include <cstdio>

#include "gearloss/core/interrupt.hpp"
#include "gearloss/io/atomic_file.hpp"

namespace gearloss::io {

// The signals that end a run (the CLI's main installs on_interrupt_signal for each).
inline constexpr int kInterruptSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE};

// The first interrupting signal (0: none, or g_interrupted set by other code: SIGINT's code).
// The first one is kept: the exit code tells why the run ended, not what came after.
inline std::atomic<int> g_interrupt_signal{0};

// The handler of kInterruptSignals (async-signal-safe: lock-free atomic operations).
inline void on_interrupt_signal(int sig) noexcept {
    int none = 0;
    g_interrupt_signal.compare_exchange_strong(none, sig, std::memory_order_relaxed);
    g_interrupted.store(true, std::memory_order_relaxed);
}

// A reader closed a pipe, FIFO or socket this run writes to: the run ends as on SIGPIPE
// (with SIGPIPE ignored, or seen before any write failed).
inline void on_reader_closed() noexcept { on_interrupt_signal(SIGPIPE); }

// The flag, its poll and the exception are core's (the computations below io poll them).
using gearloss::interrupted;
using gearloss::Interrupted;
using gearloss::throw_if_interrupted;

// 128 + the signal (130 when none was recorded): the one mapping of an interrupt to an exit code.
inline int interrupt_exit_code() noexcept {
    const int sig = g_interrupt_signal.load(std::memory_order_relaxed);
    return 128 + (sig > 0 ? sig : SIGINT);
}

// "gearloss: interrupted (signal N); no output written" on stderr; returns interrupt_exit_code().
// `stream` names a direct output (a pipe, "to standard output") that got part of its text:
// the message says it stops part-way instead.
// SIGPIPE adds why: "(signal 13: a reader closed its pipe)".
inline int report_interrupt(const std::string& stream = {}) noexcept {
    const int sig = g_interrupt_signal.load(std::memory_order_relaxed);
    const char* why = sig == SIGPIPE ? ": a reader closed its pipe" : "";
    if (stream.empty())
        std::fprintf(stderr, "gearloss: interrupted (signal %d%s); no output written\n", sig ? sig : SIGINT, why);
    else
        std::fprintf(stderr, "gearloss: interrupted (signal %d%s); no output file written; the output %s stops part-way\n",
                     sig ? sig : SIGINT, why, stream.c_str());
    return interrupt_exit_code();
}

}  // namespace gearloss::io
