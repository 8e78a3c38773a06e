#pragma once
// Running a sweep: every (remaining) case of a spec, measured against its reference, timed, and
// kept as a typed row of the results table. The spec: sweep_spec.h; the table: sweep_table.h.
#include <expected>
#include <functional>
#include <string>

#include "compare/engines/engine_registry.h"
#include "compare/studies/sweep_spec.h"
#include "compare/studies/sweep_table.h"

namespace springcheck {

struct SweepOptions {
  int jobs = 0;  // runs at once (jobCount: 0 for every free core)
  // Timing (docs/timing.md). With repeats 1 the cases run `jobs` at a time. With repeats > 1
  // they are timed one at a time (cases run side by side slow each other down through the
  // caches and memory they share: up to 1.8x on a 2-core VM), in `repeats` rounds over all cases
  // rather than back to back, on `threads` OpenMP threads (0: every core), following the load
  // unless fixed_threads; the first round, which gives the results, is then one of the timed
  // ones (a round side by side for the results and `repeats` timed ones after it cost half a
  // round more). The references run `jobs` at a time either way. Wall time: the fastest round.
  int repeats = 1;
  int threads = 0;
  bool fixed_threads = false;
  int shard_index = 0;  // run cases with id % shard_count == shard_index
  int shard_count = 1;
  bool resume = true;  // keep rows already in the output file and skip their cases
  std::function<void(int done, int total)> progress = nullptr;
  std::function<void(int done, int total)> timing_progress = nullptr;  // the timing rounds
};

// Runs the (remaining) cases of the spec in parallel, appending each finished row to a journal
// beside `out_csv` as soon as it is done (so an interrupted sweep loses only runs in flight),
// then writes the table whole, sorted by case id. Returns the number of cases run now.
[[nodiscard]] std::expected<int, std::string> runSweep(const EngineRegistry& registry,
                                                       const SweepSpec& spec,
                                                       const std::string& out_csv,
                                                       const SweepOptions& options);

}  // namespace springcheck
