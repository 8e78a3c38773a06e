#include "mysim/simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace mysim {
std::string RunRecord::status() const {
  if (blowup) return blowup->check == "step-limit" ? "step-limit" : "blowup";
  if (counts.solver_failures > 0) return "solver-not-converged";
  return "ok";
}

long stepCount(const RunSettings& settings) {
  return std::max(1L, std::lround(settings.duration / settings.dt));
}

namespace {

void recordFrame(OdeSystem& system, const State& state, double external_work, RunRecord& record) {
  record.times.push_back(state.t);
  record.frames.push_back(system.particleRows(state));
  if (auto e = system.energy(state)) {
    e->external_work = external_work;
    record.energies.push_back(*e);
  }
}

}  // namespace

long sampleStride(const RunSettings& settings) {
  if (settings.sample_interval > 0.0) {
    return std::max(1L, std::lround(settings.sample_interval / settings.dt));
  }
  return std::max(1L, stepCount(settings) / 200);
}

RunRecord simulate(OdeSystem& system, Stepper& stepper, State state, const RunSettings& settings) {
  using Clock = std::chrono::steady_clock;
  RunRecord record;
  record.dt = settings.dt;
  record.duration = settings.duration;
  const long steps = stepCount(settings);
  const long stride = sampleStride(settings);
  // External work, step by step; only when the system has an external driver (a scene pays only
  // for what it names).
  const bool driven = system.hasExternalDriver();
  State before;
  double external_work = 0.0;
  recordFrame(system, state, external_work, record);

  Clock::duration stepping{};
  for (long step = 1; step <= steps; ++step) {
    if (driven) before = state;
    const auto start = Clock::now();
    record.counts += stepper.step(state, settings.dt);
    stepping += Clock::now() - start;
    record.steps = step;
    if (driven) external_work += system.externalWork(before, state);
    if (record.counts.gave_up) {
      record.blowup = BlowUp{state.t, step, "step-limit",
                             "the adaptive integrator could not meet its tolerance above its "
                             "minimum step or within its maximum steps; the run stops here"};
      break;
    }
    // One health check a step: the first bad state is reported, never written.
    if (auto bad = system.checkHealth(state)) {
      record.blowup = BlowUp{state.t, step, bad->check, bad->detail};
      break;
    }
    if (step % stride == 0 || step == steps) recordFrame(system, state, external_work, record);
  }
  record.wall_seconds = std::chrono::duration<double>(stepping).count();
  return record;
}

}  // namespace mysim
