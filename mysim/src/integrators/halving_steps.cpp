#include "integrators/halving_steps.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mysim {
namespace {

class HalvingSteps final : public Integrator {
 public:
  HalvingSteps(std::unique_ptr<Integrator> solver, int max_halvings)
      : solver_(std::move(solver)), max_halvings_(max_halvings), saved_(max_halvings) {}

  // The step in pieces of h / 2^level_; a piece the solver cannot solve raises level_, and the
  // pieces after it start at the finer level (their starts stay aligned: every piece is a dyadic
  // part of h, and the level only rises within a step).
  StepCounts step(OdeSystem& system, State& s, double h) override {
    const double t_end = s.t + h;
    const long whole = 1L << max_halvings_;
    const bool in_one_piece = level_ == 0;
    halved_ = false;
    StepCounts counts;
    for (long done = 0; done < whole;) {
      const int level = level_;
      counts += solveOrHalve(system, s, std::ldexp(h, -level), level);
      done += whole >> level;
    }
    // In pieces, the time one step of h reaches, whatever the pieces' sums round to; in one, the
    // solver's own (XPBD's substeps sum to it), so a run that never halves is the plain bits.
    if (!in_one_piece || halved_) s.t = t_end;
    relax();
    return counts;
  }

 private:
  // One piece of the step at `level` (2^level pieces a step): solved, or restored and halved.
  StepCounts solveOrHalve(OdeSystem& system, State& s, double h, int level) {
    if (given_up_) return solver_->step(system, s, h);
    if (level >= max_halvings_) {
      // Unsolved at the deepest level: this scene is beyond what halving buys (rigid constraints,
      // a tolerance below round-off), so the run stops paying for tries and goes on as the plain
      // solver, its failures counted (the rest of this step at its level, then whole steps).
      const StepCounts deepest = solver_->step(system, s, h);
      given_up_ = deepest.solver_failures > 0;
      return deepest;
    }
    saved_[level] = s;
    StepCounts tried = solver_->step(system, s, h);
    if (tried.solver_failures == 0) return tried;
    s = saved_[level];
    halved_ = true;
    level_ = std::max(level_, level + 1);
    // The attempt's work was done (its passes count) but its step was rejected.
    tried.rejected += tried.accepted;
    tried.accepted = 0;
    tried.solver_failures = 0;
    tried += solveOrHalve(system, s, 0.5 * h, level + 1);
    tried += solveOrHalve(system, s, 0.5 * h, level + 1);
    return tried;
  }

  // After kCalmSteps steps solved without a new halving, one level coarser is tried again: the
  // stiff phase (a fall, a landing) may be over.
  void relax() {
    if (given_up_) {
      level_ = 0;
      return;
    }
    calm_ = halved_ ? 0 : calm_ + 1;
    if (calm_ >= kCalmSteps && level_ > 0) --level_, calm_ = 0;
  }

  // 8: a failed try costs one pass cap, so retrying every 8 steps costs at most an eighth of a
  // cap a step; on the 32-cell cantilever at 1/60 s all the tries thrown away (the first descent
  // and the retries: 20 in 180 steps in each family) were 7 % (VBD, XPBD) and 10 %
  // (local/global) of the run's passes at most.
  static constexpr int kCalmSteps = 8;
  std::unique_ptr<Integrator> solver_;
  int max_halvings_;
  int level_ = 0;  // the pieces a step starts in: 2^level_
  int calm_ = 0;   // steps since the last halving
  bool halved_ = false;
  bool given_up_ = false;  // a piece at the deepest level stayed unsolved: no more halving
  std::vector<State> saved_;  // each level's start, to restore on a failed try
};

}  // namespace

std::unique_ptr<Integrator> halvingUnsolvedSteps(std::unique_ptr<Integrator> solver, int max_halvings) {
  if (max_halvings <= 0) return solver;
  return std::make_unique<HalvingSteps>(std::move(solver), max_halvings);
}

}  // namespace mysim
