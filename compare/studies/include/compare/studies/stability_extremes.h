#pragma once
// What happens at the extremes: 10^6 steps of the undamped oscillator per long-run method
// (energy drift, wall time) and a 256 x 256 cloth (time per step, stability, CG iterations), with
// the process's peak memory: out/extremes.csv.
#include <expected>
#include <string>

#include "compare/engines/engine_registry.h"

namespace springcheck {

[[nodiscard]] std::expected<void, std::string> writeExtremes(const EngineRegistry& registry,
                                                             const std::string& path, int jobs);

}  // namespace springcheck
