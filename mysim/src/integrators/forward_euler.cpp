#include "mysim/integrator.h"

namespace mysim {
namespace {

// Forward Euler: y1 = y0 + h f(t0, y0). First order; on x' = -y, y' = x the radius grows by
// sqrt(1 + h^2) every step.
class ForwardEuler final : public Integrator {
 public:
  StepCounts step(OdeSystem& system, State& s, double h) override {
    system.derivative(s.t, s.y, slope_);
    s.y += h * slope_;
    s.t += h;
    system.afterStep(s);
    return {.accepted = 1, .derivative_evaluations = 1};
  }

 private:
  Vector slope_;
};

}  // namespace

std::unique_ptr<Integrator> makeForwardEuler() { return std::make_unique<ForwardEuler>(); }

}  // namespace mysim
