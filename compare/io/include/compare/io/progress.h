#pragma once
#include <chrono>
#include <cstdio>
#include <string>

namespace springcheck {

// Progress of a batch of runs on stderr: a redrawn bar (done/total, elapsed, ETA) on a
// terminal, plain lines otherwise (every 10 % and at the end), so logs stay readable.
class Progress {
 public:
  Progress(std::string label, bool terminal);
  void update(int done, int total);

 private:
  std::string label_;
  bool terminal_;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace springcheck
