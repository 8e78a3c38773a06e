#pragma once
// Small models shared by the tests.
#include <cmath>
#include <memory>
#include <string>

#include "mysim/integrator.h"
#include "mysim/particle_system.h"
#include "mysim/scene.h"
#include "mysim/simulation.h"

namespace mysim::testing {

// A 1-D damped oscillator along x: a free particle on a spring to a pinned anchor.
//
//   anchor (pinned) o----/\/\/\----o particle, starts at rest_length + amplitude, v = 0
//
// Motion stays on the x axis, where the spring is exactly linear:
//   m u'' + c u' + k u = 0,  u = x - rest_length.
struct Oscillator {
  double mass = 1.0;
  double stiffness = 4.0;  // w0 = 2 rad/s
  double drag = 0.0;
  double rest_length = 1.0;
  double amplitude = 0.1;

  double omega0() const { return std::sqrt(stiffness / mass); }

  Model model() const {
    Model m;
    m.mass = Vector::Constant(2, mass);
    m.pinned = {1, 0};
    m.start_position = Vector::Zero(6);
    m.start_position[3] = rest_length + amplitude;
    m.start_velocity = Vector::Zero(6);
    m.springs.push_back({0, 1, rest_length, stiffness, 0.0, SpringFamily::Custom});
    m.drag = drag;
    return m;
  }

  // Exact u(t) and u'(t) of the underdamped solution from u(0) = amplitude, u'(0) = 0.
  double displacement(double t) const {
    const double g = drag / (2 * mass), wd = std::sqrt(omega0() * omega0() - g * g);
    return amplitude * std::exp(-g * t) * (std::cos(wd * t) + g / wd * std::sin(wd * t));
  }
  double velocity(double t) const {
    const double g = drag / (2 * mass), wd = std::sqrt(omega0() * omega0() - g * g);
    return -amplitude * std::exp(-g * t) * (omega0() * omega0() / wd) * std::sin(wd * t);
  }
};

// Runs `steps` steps of an integrator and returns the final state.
inline State integrate(OdeSystem& system, Integrator& integrator, State state, double h,
                       long steps) {
  for (long n = 0; n < steps; ++n) integrator.step(system, state, h);
  return state;
}

inline std::unique_ptr<Integrator> integratorNamed(const std::string& name,
                                                   double cg_tolerance = 1e-12) {
  IntegratorSettings s;
  s.name = name;
  s.cg_tolerance = cg_tolerance;
  return std::move(makeIntegrator(s).value());
}

// Integrators that take a particle system: every one of the catalogue.
inline std::vector<std::string> particleIntegrators() { return integratorNames(); }

// Runs a scene in mysim with its own integrator, step and duration.
inline RunRecord simulateScene(const Scene& scene) {
  auto system = makeSystem(scene);
  IntegratorStepper stepper(*system, std::move(makeIntegrator(scene.integrator).value()));
  return simulate(*system, stepper, system->initialState(),
                  {scene.dt, scene.duration, scene.sample_interval});
}

// GoogleTest parameter names must be identifiers: "backward-euler" -> "backwardeuler".
inline std::string identifier(std::string name) {
  std::erase(name, '-');
  return name;
}

// Names a suite whose parameter is an integrator name.
struct IntegratorParamName {
  template <typename Info>
  std::string operator()(const Info& info) const {
    return identifier(info.param);
  }
};

}  // namespace mysim::testing
