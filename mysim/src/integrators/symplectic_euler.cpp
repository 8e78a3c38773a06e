#include "mysim/integrator.h"
#include "mysim/particle_system.h"

namespace mysim {
namespace {

// Symplectic (semi-implicit) Euler: v1 = v0 + h a(t0, x0, v0), x1 = x0 + h v1.
// First order, but symplectic: an undamped oscillator's energy stays bounded for h w < 2.
class SymplecticEuler final : public Integrator {
 public:
  StepCounts step(OdeSystem& system, State& s, double h) override {
    ParticleSystem& ps = *system.particles();
    const int n3 = 3 * ps.particleCount();
    x_ = s.y.head(n3);
    v_ = s.y.tail(n3);
    a_.resize(n3);
    ps.acceleration(s.t, x_, v_, a_);
    v_ += h * a_;
    // Pinned particles follow their prescribed velocity, integrated the same way.
    x_ += h * v_;
    s.y.head(n3) = x_;
    s.y.tail(n3) = v_;
    s.t += h;
    system.afterStep(s);
    return {.accepted = 1, .derivative_evaluations = 1};
  }

 private:
  Vector x_, v_, a_;
};

}  // namespace

std::unique_ptr<Integrator> makeSymplecticEuler() { return std::make_unique<SymplecticEuler>(); }

}  // namespace mysim
