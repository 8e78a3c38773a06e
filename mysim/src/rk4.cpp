#include "mysim/integrator.h"
#include "mysim/vector_ops.h"

namespace mysim {
namespace {

// Classical fourth-order Runge-Kutta (Butcher tableau 0 | 1/2 1/2 | 1/2 0 1/2 | 1 0 0 1,
// weights 1/6 1/3 1/3 1/6). Each stage is evaluated at its own trial state and time: the seed's
// "not stable enough" RK4 came from evaluating stages at the stored state instead.
class Rk4 final : public Integrator {
 public:
  StepCounts step(OdeSystem& system, State& s, double h) override {
    system.derivative(s.t, s.y, k1_);
    addScaled(s.y, 0.5 * h, k1_, trial_);
    system.derivative(s.t + 0.5 * h, trial_, k2_);
    addScaled(s.y, 0.5 * h, k2_, trial_);
    system.derivative(s.t + 0.5 * h, trial_, k3_);
    addScaled(s.y, h, k3_, trial_);
    system.derivative(s.t + h, trial_, k4_);
    addRk4Slopes(h, k1_, k2_, k3_, k4_, s.y);
    s.t += h;
    system.afterStep(s);
    return {.accepted = 1, .derivative_evaluations = 4};
  }

 private:
  Vector k1_, k2_, k3_, k4_, trial_;
};

}  // namespace

std::unique_ptr<Integrator> makeRk4() { return std::make_unique<Rk4>(); }

}  // namespace mysim
