// CHOLMOD (SuiteSparse, Debian's libsuitesparse-dev) against Eigen's SimplicialLDLT on the
// local/global matrix: factorisation and one three-column solve, side by side in one run, so the
// choice of factoriser in local_global.cpp rests on a measurement (docs/performance.md). Built
// only where CHOLMOD is installed; mysim itself does not depend on it.
#include <benchmark/benchmark.h>

#include <Eigen/CholmodSupport>

#include "bench_scenes.h"
#include "local_global_matrix.h"

namespace {

void BM_CholmodFactor(benchmark::State& state) {
  const Eigen::SparseMatrix<double> matrix =
      bench::localGlobalMatrix(static_cast<int>(state.range(0)));
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  llt.analyzePattern(matrix);
  for (auto _ : state) llt.factorize(matrix);
  state.counters["factor_nonzeros"] =
      static_cast<double>(llt.cholmod().lnz);  // cholmod's own count (supernodal, with diagonal)
}
BENCHMARK(BM_CholmodFactor)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_CholmodSolve(benchmark::State& state) {
  const Eigen::SparseMatrix<double> matrix =
      bench::localGlobalMatrix(static_cast<int>(state.range(0)));
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt(matrix);
  Eigen::MatrixXd b = Eigen::MatrixXd::Ones(matrix.rows(), 3), x;
  for (auto _ : state) {
    x = llt.solve(b);
    benchmark::DoNotOptimize(x.data());
  }
}
BENCHMARK(BM_CholmodSolve)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace
