// The solver families at large steps (issue: milliseconds at h = 1/60 s): one step of each on the
// 128 x 128 hanging cloth, one core unless named, side by side in one run; and the local/global
// solver's two parts apart: the factorisation (once per scene and step) and one three-column
// solve, whose bytes read from the factor give its bandwidth against BM_StreamTriad's.
#include <benchmark/benchmark.h>
#include <omp.h>

#include "bench_scenes.h"
#include "mysim/particle_system.h"
#include "local_global_matrix.h"
#include "solvers/sparse_ldlt3.h"

namespace {

using bench::kLargeStep;

void familyStep(benchmark::State& state, const std::string& integrator,
                std::map<std::string, double> values, int n, int threads) {
  mysim::Scene scene = bench::hangingCloth(n, integrator, kLargeStep);
  scene.integrator.values = std::move(values);
  scene.integrator.cg_tolerance = 1e-4;
  mysim::ParticleSystem system(mysim::buildModel(scene), scene.limits);
  auto method = std::move(mysim::makeIntegrator(scene.integrator).value());
  mysim::State s = system.initialState();
  omp_set_num_threads(threads);
  const mysim::StepCounts first = method->step(system, s, kLargeStep);  // set-up, apart
  for (int k = 0; k < 5; ++k) method->step(system, s, kLargeStep);    // the cloth falling
  mysim::StepCounts counts;
  for (auto _ : state) counts += method->step(system, s, kLargeStep);
  omp_set_num_threads(omp_get_num_procs());
  state.counters["setup_ms"] = 1e3 * first.setup_seconds;
  state.counters["iterations_per_step"] = double(counts.linear_iterations) / state.iterations();
  state.counters["particles"] = system.particleCount();
}

void BM_LocalGlobalFactor(benchmark::State& state) {
  const Eigen::SparseMatrix<double> matrix = bench::localGlobalMatrix(static_cast<int>(state.range(0)));
  mysim::SparseLdlt3 factor;
  std::string error;
  for (auto _ : state) benchmark::DoNotOptimize(factor.factor(matrix, error));
  state.counters["factor_nonzeros"] = static_cast<double>(factor.factorNonZeros());
}
BENCHMARK(BM_LocalGlobalFactor)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime();

// One solve reads the factor twice (12 bytes a non-zero: value and row index), and the 3-column
// right-hand side a few times (24 bytes a node, ~4 passes): bytes / time is its bandwidth.
void BM_LocalGlobalSolve(benchmark::State& state) {
  const Eigen::SparseMatrix<double> matrix = bench::localGlobalMatrix(static_cast<int>(state.range(0)));
  mysim::SparseLdlt3 factor;
  std::string error;
  factor.factor(matrix, error);
  mysim::Vector b = mysim::Vector::Ones(3 * factor.size());
  for (auto _ : state) {
    factor.solve(b);
    benchmark::DoNotOptimize(b.data());
  }
  const double bytes = 2.0 * 12.0 * factor.factorNonZeros() + 4.0 * 24.0 * factor.size();
  state.counters["factor_nonzeros"] = static_cast<double>(factor.factorNonZeros());
  state.counters["bytes_per_solve"] = bytes;
  state.counters["bandwidth_GBps"] =
      benchmark::Counter(bytes * 1e-9, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_LocalGlobalSolve)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMicrosecond)->UseRealTime();

void registerFamilies() {
  struct Case {
    std::string label, integrator;
    std::map<std::string, double> values;
    int threads;
  };
  const std::vector<Case> cases = {
      {"local-global/10it/1thread", "local-global", {{"iterations", 10}}, 1},
      {"vbd/10it/1thread", "vbd", {{"iterations", 10}}, 1},
      {"vbd/10it/2threads", "vbd", {{"iterations", 10}}, 2},
      {"xpbd/10substeps/1thread", "xpbd", {{"substeps", 10}, {"iterations", 1}}, 1},
      {"xpbd/10substeps/2threads", "xpbd", {{"substeps", 10}, {"iterations", 1}}, 2},
      {"backward-euler/1thread", "backward-euler", {}, 1},
  };
  for (const Case& c : cases) {
    benchmark::RegisterBenchmark(("BM_SolverFamilyStep/128/" + c.label).c_str(),
                                 [c](benchmark::State& st) {
                                   familyStep(st, c.integrator, c.values, 128, c.threads);
                                 })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
}

const bool familyBenchesRegistered = (registerFamilies(), true);

}  // namespace
