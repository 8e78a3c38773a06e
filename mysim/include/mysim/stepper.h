#pragma once
#include <memory>

#include "mysim/integrator.h"
#include "mysim/ode_system.h"

namespace mysim {

// Advances a run by one scene step. The run loop (simulate) steps this, whatever engine is behind
// it: one of mysim's integrators over an OdeSystem, or another simulator (a Bullet world) that
// keeps its own state and reports it in the mysim state layout, y = [x (3N); v (3N)].
class Stepper {
 public:
  virtual ~Stepper() = default;
  // Moves `state` from t to t + h; what the step cost comes back.
  virtual StepCounts step(State& state, double h) = 0;
};

// One of mysim's integrators stepping `system` (which must outlive the stepper).
class IntegratorStepper final : public Stepper {
 public:
  IntegratorStepper(OdeSystem& system, std::unique_ptr<Integrator> integrator)
      : system_(system), integrator_(std::move(integrator)) {}
  StepCounts step(State& state, double h) override { return integrator_->step(system_, state, h); }

 private:
  OdeSystem& system_;
  std::unique_ptr<Integrator> integrator_;
};

}  // namespace mysim
