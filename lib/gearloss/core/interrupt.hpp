#pragma once
// The interrupt flag that every long computation polls (README "Exit codes"): the signal
// handler (gearloss/io/interrupt.hpp) sets g_interrupted; outside a parallel region a loop throws
// Interrupted (throw_if_interrupted), inside one it skips the remaining iterations and the
// code after the region throws. Interrupted is an IoError: no output is written.
#include <atomic>

#include "gearloss/core/errors.hpp"

namespace gearloss {

// Set by the signal handler: long loops stop and outputs are discarded.
inline std::atomic<bool> g_interrupted{false};

inline bool interrupted() noexcept { return g_interrupted.load(std::memory_order_relaxed); }

struct Interrupted : IoError {
    Interrupted() : IoError("interrupted; no output file written") {}
};

inline void throw_if_interrupted() {
    if (interrupted()) throw Interrupted();
}

}  // namespace gearloss
