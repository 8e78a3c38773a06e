#include "mysim/integrator.h"
#include "mysim/particle_system.h"

namespace mysim {
namespace {

// Velocity Verlet (kick-drift-kick):
//   v_half = v0 + h/2 a0,  x1 = x0 + h v_half,  v1 = v_half + h/2 a(t1, x1, v_pred),
// with a0 = a(t0, x0, v0). For position-only forces this is the textbook, symplectic method
// (stable for h w < 2). Drag and spring damping make a depend on v1, which is not known yet:
// v_pred = v0 + h a0 is within O(h^2) of it, so the last kick errs by O(h^3) and the method stays
// second order (evaluating at v_half instead would err by O(h^2) a step: first order).
class VelocityVerlet final : public Integrator {
 public:
  StepCounts step(OdeSystem& system, State& s, double h) override {
    ParticleSystem& ps = *system.particles();
    const int n3 = 3 * ps.particleCount();
    x_ = s.y.head(n3);
    v_ = s.y.tail(n3);
    a_.resize(n3);
    ps.acceleration(s.t, x_, v_, a_);
    v_ += 0.5 * h * a_;
    x_ += h * v_;
    v_predicted_ = v_ + 0.5 * h * a_;
    ps.acceleration(s.t + h, x_, v_predicted_, a_);
    v_ += 0.5 * h * a_;
    s.y.head(n3) = x_;
    s.y.tail(n3) = v_;
    s.t += h;
    system.afterStep(s);
    return {.accepted = 1, .derivative_evaluations = 2};
  }

 private:
  Vector x_, v_, v_predicted_, a_;
};

}  // namespace

std::unique_ptr<Integrator> makeVelocityVerlet() { return std::make_unique<VelocityVerlet>(); }

}  // namespace mysim
