#pragma once
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "mysim/blowup.h"
#include "mysim/energy.h"
#include "mysim/integrator.h"
#include "mysim/stepper.h"

namespace mysim {

using ParticleRows = Eigen::Matrix<double, Eigen::Dynamic, 6>;  // (N x 6): x y z vx vy vz

// Particle p's position in a frame of rows.
inline Vec3 rowPosition(const ParticleRows& rows, int p) { return rows.row(p).head<3>().transpose(); }

// What a run produced, the same for every engine (mysim or a Bullet reference).
struct RunRecord {
  std::string engine;
  std::string integrator;
  double dt = 0.0;
  double duration = 0.0;  // requested
  long steps = 0;         // scene steps taken
  StepCounts counts;
  double wall_seconds = 0.0;         // stepping alone: no set-up, sampling or output
  double wall_median_seconds = 0.0;  // over `repeats` identical runs (wall_seconds: the fastest)
  int repeats = 1;
  int threads = 1;                    // the most OpenMP threads the run stepped with
  std::vector<double> times;          // (F) s
  std::vector<ParticleRows> frames;   // (F) sampled states, finite only
  std::vector<EnergyTerms> energies;  // (F) where the system has energy
  std::optional<BlowUp> blowup;
  // When the run ended early at rest (RunSettings::rest_displacement): the time it stopped, s.
  std::optional<double> rested_at;
  std::vector<std::string> notes;  // how the engine differs from the scene as written, if at all
  // For an engine that computes in single precision: half an ulp of float at the run's largest
  // coordinate, m. No such engine can be closer than this to anything; 0 for double engines.
  double precision_floor = 0.0;

  // "ok"; "blowup" (a health check failed); "step-limit" (an adaptive integrator stopped the run,
  // unable to meet its tolerance); "solver-not-converged" (the run is complete, but some linear
  // solves stopped short of their tolerance: less accurate than asked).
  std::string status() const;
  // Simulated seconds per wall second of stepping (0 when nothing was timed).
  double realtimeFactor() const;
};

struct RunSettings {
  double dt = 0.01;
  double duration = 1.0;
  double sample_interval = 0.0;  // 0: about 200 frames
  // OpenMP threads: 0 for every core the process may use. With follow_load the run uses only
  // the cores other processes leave free (mysim/thread_budget.h); results are the same either way.
  int threads = 0;
  bool follow_load = true;
  // The stability study's: a step whose solver stopped short of its tolerance (an iterative
  // family at its pass cap, CG at its iteration limit) ends the run as "solver-not-converged",
  // so a map's limit for an iterative family is the largest step it still solves, not one it
  // survives unsolved (issue 36). Off in every other run: there it is reported, not fatal.
  bool stop_at_solver_failure = false;
  // The stability study's: > 0 ends the run once it has come to rest, no coordinate having moved
  // more than this (m) over each of two sampling intervals in a row. A state at rest is a fixed
  // point of the step, and the steps left would only repeat it (the study's reason: its probes
  // run 4000 steps, and a damped scene at a large step is at rest after a few hundred). 0: off.
  double rest_displacement = 0.0;
};

// Frames are taken every this many steps.
long sampleStride(const RunSettings& settings);

// Number of scene steps of a run: duration / dt, rounded.
long stepCount(const RunSettings& settings);

// Steps from `state` for the duration with `stepper`, checking health on `system` after every
// step (every engine is judged by the same system: its health checks, energy and output rows);
// stops at the first unhealthy state and records it (the frames hold the states before it,
// never NaNs).
RunRecord simulate(OdeSystem& system, Stepper& stepper, State state, const RunSettings& settings);

}  // namespace mysim
