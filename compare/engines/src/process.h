#pragma once
#include <string>
#include <vector>

namespace springcheck {

// How a child process ended.
struct ProcessResult {
  bool started = false;    // false: it could not be started (no such program, say)
  bool timed_out = false;  // killed at the time limit
  int exit_code = -1;      // when it exited
  int signal = 0;          // when a signal ended it
  double wall_seconds = 0.0;
  std::string error;  // why it could not be started
};

// Runs argv[0] (searched on PATH) with argv in its own process group, standard input from
// /dev/null and standard output and error into `log_path`; kills the whole group at
// `time_limit` seconds.
ProcessResult runProcess(const std::vector<std::string>& argv, const std::string& log_path,
                         double time_limit);

// The last `lines` lines of a text file (what a failed program said last).
std::string lastLines(const std::string& path, int lines);

}  // namespace springcheck
