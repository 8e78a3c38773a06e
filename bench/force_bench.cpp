// Force evaluation of an n x n cloth with all three spring families: time per particle, bytes
// moved per evaluation, and the ratio to the memory-bandwidth bound measured in the same run.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>

#include "bench_scenes.h"
#include "bench_state.h"
#include "forces/spring_forces.h"
#include "mysim/particle_system.h"

namespace {

// Compulsory traffic of one evaluation, by the data layout: per particle x, v and the force
// (3 doubles each), its mass, its adjacency offset; per incidence (2 per spring) an 8-byte
// (neighbour, parameter) pair. Neighbours' x and v are re-read from cache, not memory.
double bytesPerEvaluation(const mysim::ParticleSystem& system) {
  const double n = system.particleCount();
  const double incidences = system.adjacency().other.size();
  return n * (3 * 8 * 3 + 8 + 4) + incidences * 8;
}

// kernel: "fast" (every spring once, vectorised; the dispatch's pick), "baseline" (the same
// without AVX2) or "reference" (the per-end loop it replaced), so each ratio comes from one run.
void forceBenchmark(benchmark::State& state, int threads, const std::string& kernel = "fast") {
  const int n = static_cast<int>(state.range(0));
  const mysim::Scene scene = bench::hangingCloth(n);
  mysim::ParticleSystem system(mysim::buildModel(scene), scene.limits);
  const mysim::State s = system.initialState();
  const int n3 = 3 * system.particleCount();
  mysim::Vector f(n3);
  omp_set_num_threads(threads);
  mysim::setSpringForcesSimd(kernel != "baseline");
  state.SetLabel(kernel == "reference" ? "per-end reference" : mysim::springForcesKernel());
  std::chrono::duration<double> spent{};
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    if (kernel == "reference") {
      system.referenceForce(0.0, s.y.head(n3), s.y.tail(n3), f);
    } else {
      system.force(0.0, s.y.head(n3), s.y.tail(n3), f);
    }
    benchmark::DoNotOptimize(f.data());
    spent += std::chrono::steady_clock::now() - start;
  }
  omp_set_num_threads(omp_get_num_procs());
  mysim::setSpringForcesSimd(true);
  const double per_eval = spent.count() / state.iterations();
  const double bytes = bytesPerEvaluation(system);
  state.counters["particles"] = system.particleCount();
  state.counters["ns_per_particle"] = 1e9 * per_eval / system.particleCount();
  state.counters["bytes_per_eval"] = bytes;
  if (bench::measuredBandwidth() > 0) {
    const double bound = bytes / bench::measuredBandwidth();
    state.counters["bound_ns"] = 1e9 * bound;
    state.counters["ratio_to_bound"] = per_eval / bound;
  }
}

void BM_ClothForce(benchmark::State& state) { forceBenchmark(state, omp_get_num_procs()); }
void BM_ClothForceOneThread(benchmark::State& state) { forceBenchmark(state, 1); }

BENCHMARK(BM_ClothForce)
    ->RangeMultiplier(2)
    ->Range(16, 256)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();
BENCHMARK(BM_ClothForceOneThread)->Arg(128)->Arg(256)->Unit(benchmark::kMicrosecond)->UseRealTime();
// The same sizes with the baseline (no AVX2) kernel and with the per-end loop, in the same run.
void BM_ClothForceBaseline(benchmark::State& state) {
  forceBenchmark(state, omp_get_num_procs(), "baseline");
}
void BM_ClothForceReference(benchmark::State& state) {
  forceBenchmark(state, omp_get_num_procs(), "reference");
}
BENCHMARK(BM_ClothForceBaseline)->Arg(128)->Arg(256)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(BM_ClothForceReference)->Arg(128)->Arg(256)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace
