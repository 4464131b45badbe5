#pragma once
// SIGINT and SIGTERM stop any command (README "Exit codes"):
//  - on_interrupt_signal (the handler) sets g_interrupted (gearloss/core/interrupt.hpp) and remembers
//    the signal;
//  - every long loop polls interrupted(): outside a parallel region it throws Interrupted
//    (throw_if_interrupted), inside one it skips the remaining iterations and the code after
//    the region throws;
//  - Interrupted is an IoError: nothing is renamed, temporary files are removed, and the
//    command ends with interrupt_exit_code(), 130 for SIGINT and 143 for SIGTERM (128 + the
//    signal number), after report_interrupt() said so on stderr.
#include <atomic>
#include <string>
#include <csignal>
#include <cstdio>

#include "gearloss/core/interrupt.hpp"
#include "gearloss/io/atomic_file.hpp"

namespace gearloss::io {

// The last interrupting signal (0: none, or g_interrupted set by other code: SIGINT's code).
inline std::atomic<int> g_interrupt_signal{0};

// The handler of SIGINT and SIGTERM (async-signal-safe: two lock-free atomic stores).
inline void on_interrupt_signal(int sig) noexcept {
    g_interrupt_signal.store(sig, std::memory_order_relaxed);
    g_interrupted.store(true, std::memory_order_relaxed);
}

// The flag, its poll and the exception are core's (the computations below io poll them).
using gearloss::interrupted;
using gearloss::Interrupted;
using gearloss::throw_if_interrupted;

// 130 (SIGINT) or 143 (SIGTERM): the one mapping of an interrupt to an exit code.
inline int interrupt_exit_code() noexcept { return g_interrupt_signal.load(std::memory_order_relaxed) == SIGTERM ? 143 : 130; }

// "gearloss: interrupted (signal N); no output written" on stderr; returns interrupt_exit_code().
// `stream` names a direct output (a pipe, "to standard output") that got part of its text:
// the message says it stops part-way instead.
inline int report_interrupt(const std::string& stream = {}) noexcept {
    const int sig = g_interrupt_signal.load(std::memory_order_relaxed);
    if (stream.empty())
        std::fprintf(stderr, "gearloss: interrupted (signal %d); no output written\n", sig ? sig : SIGINT);
    else
        std::fprintf(stderr, "gearloss: interrupted (signal %d); no output file written; the output %s stops part-way\n",
                     sig ? sig : SIGINT, stream.c_str());
    return interrupt_exit_code();
}

}  // namespace gearloss::io
