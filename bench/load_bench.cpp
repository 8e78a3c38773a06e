// mysim under load: the 64 x 64 hanging cloth under RK4 (0.2 s at 0.4 ms), on the idle machine and
// with one competing process that keeps a core busy the whole time. The goal (issue "the trade"):
// loaded, a run may take at most 1.3x the time of the same run on one thread of the idle machine
// (the share the load leaves it). bench/summarize.py prints the ratio.
#include <benchmark/benchmark.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench_scenes.h"
#include "mysim/particle_system.h"
#include "mysim/simulation.h"

namespace {

// A process that spins on one core until it is killed: the competing load.
class BusyProcess {
 public:
  BusyProcess() : pid_(fork()) {
    if (pid_ == 0) {
      volatile unsigned long spin = 0;
      for (;;) spin = spin + 1;  // volatile: the loop is not optimised away
    }
    usleep(200'000);  // let the scheduler see it before the run starts
  }
  ~BusyProcess() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  BusyProcess(const BusyProcess&) = delete;
  BusyProcess& operator=(const BusyProcess&) = delete;

 private:
  pid_t pid_;
};

void clothRun(benchmark::State& state, int threads, bool follow_load, bool loaded) {
  const double h = 4e-4;
  mysim::Scene scene = bench::hangingCloth(64, "rk4", h);
  const mysim::Model model = mysim::buildModel(scene);
  mysim::RunSettings settings{.dt = h, .duration = 0.2, .sample_interval = 0.2};
  settings.threads = threads;
  settings.follow_load = follow_load;
  std::optional<BusyProcess> load;
  if (loaded) load.emplace();
  int used = 0;
  for (auto _ : state) {
    mysim::ParticleSystem system(model, scene.limits);
    auto stepper =
        mysim::IntegratorStepper(system, mysim::makeIntegrator(scene.integrator).value());
    const mysim::RunRecord r = mysim::simulate(system, stepper, system.initialState(), settings);
    state.SetIterationTime(r.wall_seconds);
    used = r.threads;
  }
  state.counters["threads_used"] = used;
}

void registerLoadBenches() {
  struct Case {
    const char* name;
    int threads;
    bool follow_load, loaded;
  };
  for (const Case& c :
       {Case{"idle_one_thread", 1, false, false}, Case{"idle_all_threads", 0, true, false},
        Case{"loaded_follow_load", 0, true, true},
        Case{"loaded_fixed_all_threads", 0, false, true}}) {
    benchmark::RegisterBenchmark(
        (std::string("BM_ClothRk4UnderLoad/64/") + c.name).c_str(),
        [c](benchmark::State& st) { clothRun(st, c.threads, c.follow_load, c.loaded); })
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime()
        ->Iterations(3);
  }
}

const bool loadBenchesRegistered = (registerLoadBenches(), true);

}  // namespace
