#include "compare/studies/parallel_jobs.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "mysim/thread_budget.h"

namespace springcheck {

int jobCount(int requested, std::size_t runs) {
  const int wanted = requested > 0 ? requested : mysim::availableCores();
  return static_cast<int>(std::clamp<std::size_t>(static_cast<std::size_t>(std::max(wanted, 1)), 1,
                                                  std::max<std::size_t>(runs, 1)));
}

void forEachInParallel(std::size_t n, int jobs, const std::function<void(std::size_t)>& f) {
  std::atomic<std::size_t> next{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < std::max(1, jobs); ++t) {
    threads.emplace_back([&] {
      for (std::size_t k; (k = next++) < n;) f(k);
    });
  }
  for (std::thread& t : threads) t.join();
}

}  // namespace springcheck
