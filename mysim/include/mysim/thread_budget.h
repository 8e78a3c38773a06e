#pragma once
// How many OpenMP threads a run may use, kept in step with the machine while it runs.
//
// mysim's parallel loops end in a barrier: with more threads than free cores, every barrier waits
// for a thread that the scheduler has parked behind another process, and a spinning wait burns
// the core that thread needs (measured on 2 cores with one busy process: 2.3x to 25x slower than
// one thread). The budget therefore watches how much CPU the rest of the machine takes and runs
// on the cores that are left, at least one; a run's results do not depend on its thread count
// (every parallel loop is statically split and reduction-free), so this changes speed only.

#include <chrono>

namespace mysim {

class ThreadBudget {
 public:
  // `max_threads` 0: every core the process may run on.
  explicit ThreadBudget(int max_threads, bool follow_load = true);
  ~ThreadBudget();  // gives the calling thread back the thread count it had
  ThreadBudget(const ThreadBudget&) = delete;
  ThreadBudget& operator=(const ThreadBudget&) = delete;

  // Call between steps: at most every kWindow it re-measures the load and sets the thread count.
  void update();
  int threads() const { return threads_; }
  int mostThreads() const { return most_; }  // the largest count used so far

  // How long the load is averaged over: /proc/stat counts in 10 ms ticks, so shorter windows
  // would be mostly rounding.
  static constexpr std::chrono::milliseconds kWindow{100};

 private:
  void apply(int threads);

  int max_threads_ = 1;
  int previous_threads_ = 1;
  bool follow_load_ = true;
  int threads_ = 1;
  int most_ = 1;
  std::chrono::steady_clock::time_point window_start_{};
  double machine_busy_start_ = 0.0;  // s of CPU the whole machine had spent at window start
  double own_busy_start_ = 0.0;      // s of CPU this process had spent
};

// Cores this process may run on (its affinity mask).
int availableCores();

}  // namespace mysim
