#include "mysim/thread_budget.h"

#include <omp.h>
#include <sched.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

namespace mysim {
namespace {

// CPU seconds the whole machine has been busy since boot (every core, every process), from the
// first line of /proc/stat; nothing where there is no /proc (the budget then keeps its maximum).
std::optional<double> machineBusySeconds() {
  std::ifstream in("/proc/stat");
  std::string cpu;
  double user, nice, system, idle, iowait, irq, softirq, steal;
  if (!(in >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal) ||
      cpu != "cpu") {
    return std::nullopt;
  }
  static const double ticks_per_second = static_cast<double>(sysconf(_SC_CLK_TCK));
  return (user + nice + system + irq + softirq + steal) / ticks_per_second;
}

double processBusySeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Runnable tasks of the machine right now, other than the one asking (the 4th field of
// /proc/loadavg, "running/total"): the first guess, before a window of CPU times exists.
std::optional<int> otherRunnableTasks() {
  std::ifstream in("/proc/loadavg");
  double a, b, c;
  int running = 0;
  char slash;
  if (!(in >> a >> b >> c >> running >> slash)) return std::nullopt;
  return std::max(0, running - 1);
}

// Threads for `cores` when others keep `busy_cores` of them busy. A core counts as free when
// less than a quarter of it is taken: a thread sharing a core with a busy process stalls every
// barrier for a scheduler time slice, which costs far more than the quarter core gains.
int threadsFor(int cores, double busy_cores, int max_threads) {
  const int free = static_cast<int>(std::floor(cores - busy_cores + 0.25));
  return std::clamp(free, 1, max_threads);
}

}  // namespace

int availableCores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1, omp_get_num_procs());
}

// 0 threads asked: the user's OMP_NUM_THREADS if set, else every core we may use.
static int defaultThreads() {
  return std::getenv("OMP_NUM_THREADS") ? omp_get_max_threads() : availableCores();
}

ThreadBudget::ThreadBudget(int max_threads, bool follow_load)
    : max_threads_(max_threads > 0 ? max_threads : defaultThreads()),
      previous_threads_(omp_get_max_threads()),
      follow_load_(follow_load) {
  int start = max_threads_;
  if (follow_load_ && max_threads_ > 1) {
    if (auto others = otherRunnableTasks()) start = threadsFor(availableCores(), *others, start);
  }
  apply(start);
  window_start_ = std::chrono::steady_clock::now();
  machine_busy_start_ = machineBusySeconds().value_or(0.0);
  own_busy_start_ = processBusySeconds();
}

ThreadBudget::~ThreadBudget() { omp_set_num_threads(previous_threads_); }

void ThreadBudget::apply(int threads) {
  threads_ = threads;
  most_ = std::max(most_, threads);
  omp_set_num_threads(threads);
}

void ThreadBudget::update() {
  if (!follow_load_ || max_threads_ == 1) return;
  const auto now = std::chrono::steady_clock::now();
  const double wall = std::chrono::duration<double>(now - window_start_).count();
  if (wall < std::chrono::duration<double>(kWindow).count()) return;
  const auto machine = machineBusySeconds();
  if (!machine) return;
  const double own = processBusySeconds();
  // What the rest of the machine kept busy over the window, in cores.
  const double others =
      std::max(0.0, (*machine - machine_busy_start_) - (own - own_busy_start_)) / wall;
  apply(threadsFor(availableCores(), others, max_threads_));
  window_start_ = now;
  machine_busy_start_ = *machine;
  own_busy_start_ = own;
}

}  // namespace mysim
