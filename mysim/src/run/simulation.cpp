#include "mysim/simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "mysim/thread_budget.h"

namespace mysim {
std::string RunRecord::status() const {
  if (blowup) return blowup->check == "step-limit" ? "step-limit" : "blowup";
  if (counts.solver_failures > 0) return "solver-not-converged";
  return "ok";
}

double RunRecord::realtimeFactor() const {
  const double simulated = times.empty() ? 0.0 : times.back() - times.front();
  return wall_seconds > 0.0 ? simulated / wall_seconds : 0.0;
}

long stepCount(const RunSettings& settings) {
  return std::max(1L, std::lround(settings.duration / settings.dt));
}

namespace {

void recordFrame(OdeSystem& system, const State& state, const std::optional<EnergyTerms>& energy,
                 RunRecord& record) {
  record.times.push_back(state.t);
  record.frames.push_back(system.particleRows(state));
  if (energy) record.energies.push_back(*energy);
}

std::optional<EnergyTerms> energyOf(OdeSystem& system, const State& state, double external_work) {
  auto e = system.energy(state);
  if (e) e->external_work = external_work;
  return e;
}

}  // namespace

long sampleStride(const RunSettings& settings) {
  if (settings.sample_interval > 0.0) {
    return std::max(1L, std::lround(settings.sample_interval / settings.dt));
  }
  return std::max(1L, stepCount(settings) / 200);
}

namespace {

// A passive scene's total energy risen above its lowest earlier value by more than the limit:
// the bounded instability, reported as a blow-up at that frame.
std::optional<BlowUp> energyRise(double total, double lowest, double limit, double t, long step) {
  const double rise = total - lowest;
  if (rise <= limit) return std::nullopt;
  return BlowUp{t, step, "energy-rise",
                "total energy " + std::to_string(rise) +
                    " J above its lowest earlier value, more than " + std::to_string(limit) +
                    " J (blowup.max_energy_rise, or max_energy_rise_damped with drag, of the "
                    "energy scale): a passive scene cannot gain energy"};
}

// A solver that could not do its step: an adaptive method gave up (always fatal), or, where the
// run asks (the stability search), an iterative solver stopped at its cap.
std::optional<BlowUp> solverStop(const StepCounts& counts, const RunSettings& settings, double t,
                                 long step) {
  if (counts.gave_up) {
    return BlowUp{t, step, "step-limit",
                  "the adaptive integrator could not meet its tolerance above its minimum step "
                  "or within its maximum steps; the run stops here"};
  }
  if (settings.stop_at_solver_failure && counts.solver_failures > 0) {
    return BlowUp{t, step, "solver-not-converged",
                  "the step's solver stopped short of its tolerance (its iteration cap); the "
                  "stability search counts the step as failed"};
  }
  return std::nullopt;
}

// Whether the run has come to rest (RunSettings::rest_displacement): no coordinate moved more
// than `limit` between the last two sampled frames, for the second interval in a row.
bool cameToRest(const RunRecord& record, double limit, int& intervals_at_rest) {
  const std::size_t f = record.frames.size();
  if (limit <= 0.0 || f < 2 || record.frames[f - 1].rows() == 0) return false;
  const auto moved = record.frames[f - 1].leftCols<3>() - record.frames[f - 2].leftCols<3>();
  intervals_at_rest = moved.cwiseAbs().maxCoeff() <= limit ? intervals_at_rest + 1 : 0;
  return intervals_at_rest == 2;
}

}  // namespace

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
  // Bounded instability: checked at the sampled frames, where the energy is computed anyway.
  const std::optional<double> rise_limit = system.energyRiseLimit();
  double lowest = std::numeric_limits<double>::infinity();
  recordFrame(system, state, energyOf(system, state, 0.0), record);
  if (!record.energies.empty()) lowest = record.energies.back().total();

  ThreadBudget budget(settings.threads, settings.follow_load);
  Clock::duration stepping{};
  int intervals_at_rest = 0;
  for (long step = 1; step <= steps; ++step) {
    budget.update();
    if (driven) before = state;
    const auto start = Clock::now();
    record.counts += stepper.step(state, settings.dt);
    stepping += Clock::now() - start;
    record.steps = step;
    if (driven) external_work += system.externalWork(before, state);
    if (auto stop = solverStop(record.counts, settings, state.t, step)) {
      record.blowup = stop;
      break;
    }
    // One health check a step: the first bad state is reported, never written.
    if (auto bad = system.checkHealth(state)) {
      record.blowup = BlowUp{state.t, step, bad->check, bad->detail};
      break;
    }
    if (step % stride == 0 || step == steps) {
      const std::optional<EnergyTerms> e = energyOf(system, state, external_work);
      if (rise_limit && e) {
        if (auto rise = energyRise(e->total(), lowest, *rise_limit, state.t, step)) {
          record.blowup = rise;
          break;
        }
        lowest = std::min(lowest, e->total());
      }
      recordFrame(system, state, e, record);
      if (cameToRest(record, settings.rest_displacement, intervals_at_rest)) {
        record.rested_at = state.t;
        break;
      }
    }
  }
  record.wall_seconds = std::chrono::duration<double>(stepping).count();
  record.wall_median_seconds = record.wall_seconds;
  record.threads = budget.mostThreads();
  return record;
}

}  // namespace mysim
