#include "mysim/integrator.h"

namespace mysim {
namespace {

// Trapezoidal rule in Heun's explicit form: an Euler trial step, then the average of the slopes
// at both ends:  k1 = f(t, y),  k2 = f(t + h, y + h k1),  y1 = y + h/2 (k1 + k2).
// Second order; its amplification on x' = -y, y' = x is |1 + ih - h^2/2| = sqrt(1 + h^4/4).
class Trapezoidal final : public Integrator {
 public:
  StepCounts step(OdeSystem& system, State& s, double h) override {
    system.derivative(s.t, s.y, k1_);
    trial_ = s.y + h * k1_;
    system.derivative(s.t + h, trial_, k2_);
    s.y += 0.5 * h * (k1_ + k2_);
    s.t += h;
    system.afterStep(s);
    return {.accepted = 1, .derivative_evaluations = 2};
  }

 private:
  Vector k1_, k2_, trial_;
};

}  // namespace

std::unique_ptr<Integrator> makeTrapezoidal() { return std::make_unique<Trapezoidal>(); }

}  // namespace mysim
