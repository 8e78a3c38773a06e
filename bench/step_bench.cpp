// One step of each integrator on the cloth, and the same scene and step in every other engine of
// the registry (the Bullet twins), side by side in one run (docs/performance.md turns them into
// mysim / Bullet ratios).
#include <benchmark/benchmark.h>
#include <omp.h>

#include "bench_scenes.h"
#include "compare/engines/engine_registry.h"
#include "mysim/particle_system.h"

namespace {


// The cloth after 0.1 s of falling, so contacts of springs in tension are exercised.
constexpr double kSettleTime = 0.1;

void stepBenchmark(benchmark::State& state, const std::string& integrator, int n, int threads,
                   double cg_tolerance, double step = 0.0,
                   mysim::CgPreconditioner preconditioner = mysim::CgPreconditioner::Ssor) {
  const double h = step > 0 ? step : bench::stableStep(n);
  mysim::Scene scene = bench::hangingCloth(n, integrator, h);
  scene.integrator.cg_tolerance = cg_tolerance;
  scene.integrator.preconditioner = preconditioner;
  mysim::ParticleSystem system(mysim::buildModel(scene), scene.limits);
  auto method = std::move(mysim::makeIntegrator(scene.integrator).value());
  mysim::State s = system.initialState();
  for (double t = 0; t < kSettleTime; t += h) method->step(system, s, h);
  omp_set_num_threads(threads);
  mysim::StepCounts counts;
  for (auto _ : state) counts += method->step(system, s, h);
  omp_set_num_threads(omp_get_num_procs());
  state.counters["particles"] = system.particleCount();
  state.counters["ns_per_particle"] =
      benchmark::Counter(system.particleCount(), benchmark::Counter::kIsIterationInvariantRate |
                                                     benchmark::Counter::kInvert);
  state.counters["cg_iterations_per_step"] = double(counts.linear_iterations) / state.iterations();
  state.counters["dt"] = h;
}

void engineBenchmark(benchmark::State& state, const springcheck::EngineRegistry& registry,
                     const std::string& engine, int n, double cg_tolerance) {
  const double h = bench::stableStep(n);
  mysim::Scene scene = bench::hangingCloth(n, "symplectic-euler", h);
  scene.integrator.cg_tolerance = cg_tolerance;
  const mysim::Model model = mysim::buildModel(scene);
  auto instance = registry.build(engine, model, springcheck::runConfig(scene));
  if (!instance) {
    state.SkipWithError(instance.error().message.c_str());
    return;
  }
  mysim::State s = instance->start;
  for (double t = 0; t < kSettleTime; t += h) instance->stepper->step(s, h);
  for (auto _ : state) instance->stepper->step(s, h);
  state.counters["particles"] = model.particleCount();
  state.counters["ns_per_particle"] =
      benchmark::Counter(model.particleCount(), benchmark::Counter::kIsIterationInvariantRate |
                                                    benchmark::Counter::kInvert);
  state.counters["dt"] = h;
}

// CG tolerance for both implicit solvers when compared (mysim's relative residual; Bullet gets
// its square, see docs/reference.md).
constexpr double kCgTolerance = 1e-4;

// Every engine at 32 x 32: mysim once per integrator of the catalogue, then the others.
void registerEngineStepBenches() {
  for (const std::string& integrator : mysim::integratorNames()) {  // every one of the catalogue
    benchmark::RegisterBenchmark(("BM_MysimStep/" + integrator + "/32").c_str(),
                                 [integrator](benchmark::State& st) {
                                   stepBenchmark(st, integrator, 32, omp_get_num_procs(),
                                                 kCgTolerance);
                                 })
        ->Unit(benchmark::kMicrosecond)
        ->UseRealTime();
  }
  static const springcheck::EngineRegistry registry;
  for (const springcheck::Engine& engine : registry.engines()) {
    if (engine.kind == "mysim") continue;  // above, per integrator
    const std::string name = engine.name;
    benchmark::RegisterBenchmark(
        ("BM_BulletStep/" + name + "/32").c_str(),
        [name](benchmark::State& st) { engineBenchmark(st, registry, name, 32, kCgTolerance); })
        ->Unit(benchmark::kMicrosecond)
        ->UseRealTime();
  }
}

// Scaling with the cloth's size: the explicit steps per particle, backward Euler's CG.
void registerScalingBenches() {
  // Cost per particle of the explicit steps from 32 x 32 to 256 x 256, on one thread: the
  // algorithm's scaling, without the step where the force loop turns parallel (512 particles).
  for (const char* integrator : {"symplectic-euler", "rk4"}) {
    for (int n : {32, 64, 128, 256}) {
      benchmark::RegisterBenchmark(
          ("BM_MysimStepScaling/" + std::string(integrator) + "/" + std::to_string(n)).c_str(),
          [integrator, n](benchmark::State& st) {
            stepBenchmark(st, integrator, n, 1, kCgTolerance);
          })
          ->Unit(benchmark::kMicrosecond)
          ->UseRealTime();
    }
  }
  // Backward Euler: time and CG iterations per step against n.
  for (int n : {16, 32, 64, 128}) {
    benchmark::RegisterBenchmark(("BM_BackwardEulerScaling/" + std::to_string(n)).c_str(),
                                 [n](benchmark::State& st) {
                                   stepBenchmark(st, "backward-euler", n, omp_get_num_procs(),
                                                 kCgTolerance);
                                 })
        ->Unit(benchmark::kMicrosecond)
        ->UseRealTime();
  }
}

// Backward Euler at the large steps it is for, then RK4 on one thread and two.
void registerLargeStepBenches() {
  // Large implicit steps, the reason backward Euler exists: fixed physical steps of 1/60 s and
  // 1/240 s (far above the explicit limit 1 / (40 n)) from 32 x 32 to 256 x 256, on one core,
  // with each CG preconditioner side by side (plain Jacobi and the whole factor only to
  // 128 x 128: at 256 x 256 Jacobi's step takes seconds and says nothing the smaller sizes do not,
  // and backward Euler's Auto keeps CG above 12500 particles, where the factor is not measured).
  using mysim::CgPreconditioner;
  for (int per_second : {60, 240}) {
    for (int n : {32, 64, 128, 256}) {
      for (CgPreconditioner preconditioner :
           {CgPreconditioner::Ssor, CgPreconditioner::BlockJacobi, CgPreconditioner::Jacobi,
            CgPreconditioner::Cholesky}) {
        if ((preconditioner == CgPreconditioner::Jacobi ||
             preconditioner == CgPreconditioner::Cholesky) && n > 128) {
          continue;
        }
        benchmark::RegisterBenchmark(
            ("BM_LargeImplicitStep/" + std::to_string(per_second) + "/" + std::to_string(n) + "/" +
             mysim::preconditionerName(preconditioner))
                .c_str(),
            [per_second, n, preconditioner](benchmark::State& st) {
              stepBenchmark(st, "backward-euler", n, 1, kCgTolerance, 1.0 / per_second,
                            preconditioner);
            })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
      }
    }
  }
  // Threads: RK4 on 256 x 256 with one core and with all.
  for (int threads : {1, 2}) {
    benchmark::RegisterBenchmark(
        ("BM_Rk4Threads/256/" + std::to_string(threads)).c_str(),
        [threads](benchmark::State& st) { stepBenchmark(st, "rk4", 256, threads, kCgTolerance); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
}

void registerStepBenches() {
  registerEngineStepBenches();
  registerScalingBenches();
  registerLargeStepBenches();
}

const bool stepBenchesRegistered = (registerStepBenches(), true);

}  // namespace
