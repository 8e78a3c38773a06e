#include "compare/engines/work_count.h"

#include <atomic>
#include <cstdlib>
#include <fstream>

namespace springcheck {
namespace {
std::atomic<long> runs_done{0};
std::atomic<long> steps_done{0};
}  // namespace

void countRun(long steps) {
  runs_done.fetch_add(1, std::memory_order_relaxed);
  steps_done.fetch_add(steps, std::memory_order_relaxed);
}

WorkCount workDone() { return {runs_done.load(), steps_done.load()}; }

bool reportWorkDone(std::string& error) {
  const char* path = std::getenv(kWorkFileVariable);
  if (!path || !*path) return true;
  const WorkCount work = workDone();
  std::ofstream out(path, std::ios::app);
  out << "{\"runs\": " << work.runs << ", \"steps\": " << work.steps << "}\n";
  out.flush();
  if (!out) {
    error = std::string(kWorkFileVariable) + "=" + path +
            ": cannot append the work count (expected a file springcheck may write, or the "
            "variable unset)";
  }
  return static_cast<bool>(out);
}

}  // namespace springcheck
