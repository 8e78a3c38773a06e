#pragma once
// Limits every run is held to, whatever set its step and duration (a scene file, a command-line
// override, a sweep): checked before anything is allocated or stepped.
#include <optional>
#include <string>

#include "mysim/limit_error.h"
#include "mysim/simulation.h"

namespace mysim {

// At most a billion steps a run. The longest run any study of ours makes is 10^6 steps (the
// energy drift extremes); at the fastest step we have (~20 ns, a lone oscillator) 10^9 steps are
// already 20 s, and a cloth's take days. More is a mistyped dt or duration (1e-320, 1e300), which
// would otherwise overflow the step count.
constexpr double kMaxSteps = 1e9;

// The run of `particles` particles and `springs` springs with these settings: finite positive
// dt <= duration, at most kMaxSteps steps, a finite sample interval, and an estimated memory
// (state, integrator buffers, springs, sampled trajectory) within half the machine's.
std::optional<LimitError> checkRunLimits(double particles, double springs, const RunSettings& run);

// The machine's physical memory, bytes.
double physicalMemoryBytes();

}  // namespace mysim
