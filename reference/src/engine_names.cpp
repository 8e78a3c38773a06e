#include <cmath>

#include "reference/bullet_engine.h"

namespace reference {

const char* bulletEngineName(BulletEngine engine) {
  switch (engine) {
    case BulletEngine::Deformable:
      return "bullet-deformable";
    case BulletEngine::Implicit:
      return "bullet-implicit";
    case BulletEngine::Classic:
      return "bullet-classic";
  }
  return "?";
}

const char* bulletEngineDescription(BulletEngine engine) {
  switch (engine) {
    case BulletEngine::Deformable:
      return "Bullet deformable world, explicit: symplectic Euler, damping implicit";
    case BulletEngine::Implicit:
      return "Bullet deformable world, implicit: linearised backward Euler + CG";
    case BulletEngine::Classic:
      return "Bullet classic soft body: position-based links (bullet.classic_iterations)";
  }
  return "?";
}

std::string bulletIntegratorName(BulletEngine engine, int classic_iterations) {
  switch (engine) {
    case BulletEngine::Deformable:
      return "bullet-explicit";
    case BulletEngine::Implicit:
      return "bullet-backward-euler";
    case BulletEngine::Classic:
      return "bullet-pbd-" + std::to_string(classic_iterations);
  }
  return "?";
}

const char* bulletScheme(BulletEngine engine) {
  switch (engine) {
    case BulletEngine::Deformable:
      return "symplectic-euler";
    case BulletEngine::Implicit:
      return "backward-euler";
    case BulletEngine::Classic:
      return "";
  }
  return "";
}

const mysim::EngineSection& bulletSceneSection() {
  static const mysim::EngineSection section = {
      "bullet",
      {{"classic_iterations", 1, 10'000, 10, true,
        "position solver passes per step of the bullet-classic engine"}}};
  return section;
}

BulletSettings bulletSettings(const std::string& source, double dt,
                              const mysim::IntegratorSettings& integrator,
                              const mysim::EngineSettings& engine_settings) {
  BulletSettings s;
  s.source = source;
  s.dt = dt;
  s.cg_tolerance = integrator.cg_tolerance;
  s.cg_max_iterations = integrator.cg_max_iterations;
  if (auto section = engine_settings.find("bullet"); section != engine_settings.end()) {
    if (auto it = section->second.find("classic_iterations"); it != section->second.end()) {
      s.classic_iterations = static_cast<int>(it->second);
    }
  }
  return s;
}

double classicLinkStiffness(double k, double h, double inverse_mass_sum, int iterations) {
  const double a = k * h * h * inverse_mass_sum;
  const double alpha = a / (1.0 + a);
  return 1.0 - std::pow(1.0 - alpha, 1.0 / iterations);
}

}  // namespace reference
