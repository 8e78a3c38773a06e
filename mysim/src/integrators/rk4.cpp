#include "mysim/integrator.h"
#include "solvers/vector_ops.h"

namespace mysim {
namespace {

// Classical fourth-order Runge-Kutta (Butcher tableau 0 | 1/2 1/2 | 1/2 0 1/2 | 1 0 0 1,
// weights 1/6 1/3 1/3 1/6). Each stage is evaluated at its own trial state and time: the seed's
// "not stable enough" RK4 came from evaluating stages at the stored state instead.
// The slopes are summed as they come (k1 + 2 k2 + 2 k3 + k4, left to right, the same bits as
// summing them at the end), so a step holds three state-sized buffers instead of five: on a
// 256 x 256 cloth that is 6 MB less.
class Rk4 final : public Integrator {
 public:
  StepCounts step(OdeSystem& system, State& s, double h) override {
    system.derivative(s.t, s.y, k_);
    slopes_.resize(k_.size());
    copyParallel(k_, slopes_);
    addScaled(s.y, 0.5 * h, k_, trial_);
    system.derivative(s.t + 0.5 * h, trial_, k_);
    addScaled(slopes_, 2.0, k_, slopes_);
    addScaled(s.y, 0.5 * h, k_, trial_);
    system.derivative(s.t + 0.5 * h, trial_, k_);
    addScaled(slopes_, 2.0, k_, slopes_);
    addScaled(s.y, h, k_, trial_);
    system.derivative(s.t + h, trial_, k_);
    addScaled(slopes_, 1.0, k_, slopes_);
    addScaled(s.y, h / 6.0, slopes_, s.y);
    s.t += h;
    system.afterStep(s);
    return {.accepted = 1, .derivative_evaluations = 4};
  }

 private:
  Vector k_, trial_, slopes_;
};

}  // namespace

std::unique_ptr<Integrator> makeRk4() { return std::make_unique<Rk4>(); }

}  // namespace mysim
