#pragma once
// The simulation work a process has done: every run an engine made (each repeat of a timed run
// counts) and the steps it took. The main job holds its budget by these counts, not by seconds
// (scripts/run-suite.sh writes them per stage into out/timings.json;
// scripts/check-main-job-work.py compares them with scripts/main-job-work.json): the same input
// gives the same counts on any machine, at any load.
#include <string>

namespace springcheck {

struct WorkCount {
  long runs = 0;
  long steps = 0;
};

// Adds one run of `steps` steps (any thread).
void countRun(long steps);
WorkCount workDone();

// The environment variable naming the file a process appends its WorkCount to when it ends.
inline constexpr const char* kWorkFileVariable = "SPRINGCHECK_WORK_FILE";
// Appends {"runs": N, "steps": M} as one line to the file $SPRINGCHECK_WORK_FILE names, if it is
// set (several commands of one stage append to one file). An error names the file.
[[nodiscard]] bool reportWorkDone(std::string& error);

}  // namespace springcheck
