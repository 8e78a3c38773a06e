#include "engine_support.h"

#include <cmath>

namespace reference {

std::string springField(const mysim::Scene& scene, const mysim::Spring& spring, int index,
                        const std::string& parameter) {
  switch (scene.kind) {
    case mysim::SystemKind::Chain:
      return "system." + parameter;
    case mysim::SystemKind::Cloth:
      return std::string("system.") + mysim::familyName(spring.family) + "." + parameter;
    default:
      return "system.springs[" + std::to_string(index) + "]." + parameter;
  }
}

double uniformFreeMass(const mysim::Model& model) {
  double mass = 0.0;
  for (int p = 0; p < model.particleCount(); ++p) {
    if (model.pinned[p]) continue;
    if (mass == 0.0) mass = model.mass[p];
    if (model.mass[p] != mass) return 0.0;
  }
  return mass;
}

std::expected<void, std::string> checkSupported(const mysim::Scene& scene,
                                                const mysim::Model& model, BulletEngine engine) {
  const std::string prefix = scene.source + ": " + bulletEngineName(engine) + ": ";
  auto refuse = [&](const std::string& field, const std::string& why) {
    return std::unexpected(prefix + field + ": " + why);
  };
  if (scene.kind == mysim::SystemKind::Circle) {
    return refuse("system.type", "the circle is a first-order ODE, not a soft body");
  }
  // The classic solver scales velocities by (1 - kDP) once a step, the same for every node: that
  // equals viscous drag c only when c h / m is one number.
  if (engine == BulletEngine::Classic && model.drag > 0.0) {
    const double m = uniformFreeMass(model);
    if (m == 0.0) return refuse("forces.drag", "drag needs equal masses on all free particles");
    if (model.drag * scene.dt / m >= 1.0) {
      return refuse("forces.drag", "drag * dt / mass must be < 1 (kDP scales v by 1 - it)");
    }
  }
  // btDeformableMassSpringForce holds one elastic stiffness for every non-bending link, one
  // bending stiffness (our flex family) and one damping for all links; addForce ignores a second
  // force of the same type, so families cannot each have their own.
  const mysim::Spring* first_of_kind[2] = {nullptr, nullptr};  // non-bending, bending
  const mysim::Spring* first = nullptr;
  for (int k = 0; k < static_cast<int>(model.springs.size()); ++k) {
    const mysim::Spring& s = model.springs[k];
    if (engine == BulletEngine::Classic) {
      if (s.damping > 0.0) {
        return refuse(springField(scene, s, k, "damping"),
                      "the position-based solver has no spring damping; set it to 0 and damp "
                      "with forces.drag, or use bullet-deformable");
      }
      continue;
    }
    const bool bending = s.family == mysim::SpringFamily::Flex;
    const mysim::Spring*& same_kind = first_of_kind[bending];
    if (!same_kind) same_kind = &s;
    if (!first) first = &s;
    if (s.stiffness != same_kind->stiffness) {
      return refuse(springField(scene, s, k, "stiffness"),
                    "Bullet's mass-spring force has one stiffness for all " +
                        std::string(bending ? "bending (flex)" : "non-bending") + " links; " +
                        std::to_string(s.stiffness) + " N/m here, " +
                        std::to_string(same_kind->stiffness) + " N/m on another");
    }
    if (s.damping != first->damping) {
      return refuse(springField(scene, s, k, "damping"),
                    "Bullet's mass-spring force has one damping for all links");
    }
  }
  return {};
}

}  // namespace reference
