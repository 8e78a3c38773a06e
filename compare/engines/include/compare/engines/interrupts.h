#pragma once
// SIGINT and SIGTERM while external engines run: springcheck stops every engine it started (the
// process, its group and everything carrying its run's marker), removes their scratch folders and
// exits 128 + the signal's number. Results already written stay as they were: result files are
// written whole or not at all, and nothing more is written after the signal.
#include <sys/types.h>

#include <functional>
#include <string>

namespace springcheck {

// Call first in main, before any thread starts: blocks SIGINT and SIGTERM in every thread and
// waits for them on a thread of its own. Without it (tests, the library used directly) the
// signals keep their default action.
void handleInterrupts();

// An engine process in flight, known to the interrupt handler until destroyed. `spawn` starts it
// and returns its pid (or -1); it runs under the registry's lock, so no engine starts unseen
// while the handler stops the others.
class TrackedRun {
 public:
  TrackedRun(const std::function<pid_t()>& spawn, const std::string& marker);
  ~TrackedRun();
  pid_t pid() const { return pid_; }
  TrackedRun(const TrackedRun&) = delete;
  TrackedRun& operator=(const TrackedRun&) = delete;

 private:
  pid_t pid_ = -1;
  int slot_ = -1;
};

// A scratch folder the handler removes if the run is interrupted.
class TrackedScratch {
 public:
  explicit TrackedScratch(const std::string& path);
  ~TrackedScratch();
  TrackedScratch(const TrackedScratch&) = delete;
  TrackedScratch& operator=(const TrackedScratch&) = delete;

 private:
  int slot_ = -1;
};

// Kills the process group `pid` started and every process whose environment holds `marker`
// ("NAME=value"), until none is left, reaping those that are springcheck's children.
void stopRun(pid_t pid, const std::string& marker);

}  // namespace springcheck
