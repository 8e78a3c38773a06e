// Memory bandwidth probe: a STREAM triad a = b + s c over buffers far larger than the last-level
// cache. The measured bandwidth sets the roofline bound the force benchmark is held against.
#include <benchmark/benchmark.h>

#include <chrono>
#include <vector>

#include "bench_state.h"

namespace {

void BM_StreamTriad(benchmark::State& state) {
  const std::size_t n = std::size_t(1) << 24;  // 3 x 128 MiB
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  const double s = 3.0;
  double best = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    double* __restrict pa = a.data();
    const double* __restrict pb = b.data();
    const double* __restrict pc = c.data();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) pa[i] = pb[i] + s * pc[i];
    benchmark::DoNotOptimize(a.data());
    benchmark::ClobberMemory();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // STREAM's count: 24 bytes an element (read b and c, write a; write-allocate not counted).
    best = std::max(best, 24.0 * n / seconds);
  }
  bench::measuredBandwidth() = best;
  state.counters["bytes_per_second"] = best;
}
BENCHMARK(BM_StreamTriad)->Iterations(20)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
