#include "engine_support.h"

#include "mysim/cloth_surface.h"

namespace reference {

double uniformFreeMass(const mysim::Model& model) {
  double mass = 0.0;
  for (int p = 0; p < model.particleCount(); ++p) {
    if (model.pinned[p]) continue;
    if (mass == 0.0) mass = model.mass[p];
    if (model.mass[p] != mass) return 0.0;
  }
  return mass;
}

std::optional<UniformSprings> uniformSprings(const mysim::Model& model) {
  const mysim::Spring* first_of_kind[2] = {nullptr, nullptr};  // non-bending, bending
  UniformSprings u;
  for (const mysim::Spring& s : model.springs) {
    const bool bending = s.family == mysim::SpringFamily::Flex;
    const mysim::Spring*& same_kind = first_of_kind[bending];
    if (!same_kind) same_kind = &s;
    if (s.stiffness != same_kind->stiffness) return std::nullopt;
    if (s.damping != model.springs.front().damping) return std::nullopt;
    (bending ? u.bending_stiffness : u.stiffness) = s.stiffness;
    u.damping = s.damping;
  }
  if (!first_of_kind[0]) u.stiffness = u.bending_stiffness;  // only flex: the other is unused
  return u;
}

namespace {

// Bullet's soft-body contact has one friction coefficient, kDF x the body's friction, for both
// sticking and sliding (btSoftBodyInternals.h: CollideSDF_RS, CollideSDF_RD); the classic
// solver's kinetic branch keeps 1 - fc of the tangential velocity, so fc above 1 reverses it.
std::optional<std::string> unsupportedFriction(const mysim::Model& model, BulletEngine engine,
                                               std::string& field) {
  for (std::size_t k = 0; k < model.colliders.size(); ++k) {
    const mysim::Friction& f = mysim::colliderFriction(model.colliders[k]);
    field = "colliders[" + std::to_string(k) + "].friction";
    if (f.static_coefficient != f.kinetic) {
      return "Bullet's soft-body contact has one friction coefficient (kDF x the body's friction) "
             "for sticking and sliding; give static = kinetic, or run mysim, which takes both";
    }
    if (engine == BulletEngine::Classic && f.kinetic > 1.0) {
      return "the classic solver keeps 1 - mu of the tangential velocity on sliding contact, "
             "which reverses it for mu > 1; use bullet-deformable or bullet-implicit";
    }
  }
  return std::nullopt;
}

}  // namespace

std::expected<void, std::string> checkSupported(const mysim::Model& model, BulletEngine engine,
                                                const BulletSettings& settings) {
  const std::string prefix = settings.source + ": " + bulletEngineName(engine) + ": ";
  auto refuse = [&](const std::string& field, const std::string& why) {
    return std::unexpected(prefix + field + ": " + why);
  };
  std::string friction_field;
  if (auto why = unsupportedFriction(model, engine, friction_field)) return refuse(friction_field, *why);
  if (model.self_collision_thickness) {
    if (engine == BulletEngine::Classic) {
      return refuse("system.self_collision",
                    "the classic solver's self-collision needs clusters (CL_SELF), a different "
                    "body than the one matched to mysim's springs; use bullet-deformable or "
                    "bullet-implicit");
    }
    if (mysim::clothTriangles(model).empty()) {
      return refuse("system.self_collision",
                    "Bullet's soft-body self-collision is between faces; a chain has none");
    }
  }
  // The deformable engines take every other model: what Bullet's own force classes cannot hold
  // goes through our per-link spring force and custom drag and wind forces (deformable_forces.h).
  if (engine != BulletEngine::Classic) return {};
  if (!model.hinges.empty()) {
    return refuse("system.material.bending",
                  "the classic solver has no hinge energy (its bending constraints are links "
                  "between nodes two apart: the flex model); use \"model\": \"flex\", or "
                  "bullet-deformable or bullet-implicit, which take hinges as a force");
  }
  // The classic solver scales velocities by (1 - kDP) once a step, the same for every node: that
  // equals viscous drag c only when c h / m is one number.
  const std::string drag_field =
      model.material ? "system.material.damping_rate" : "forces.drag";
  if (model.drag > 0.0) {
    const double m = uniformFreeMass(model);
    if (m == 0.0) {
      return refuse(drag_field,
                    "the classic solver damps every node by one factor, which is viscous drag "
                    "only with equal masses on all free particles" +
                        std::string(model.material
                                        ? " (a material cloth's edges carry less mass)"
                                        : "; give them one mass") +
                        ", set the damping to 0, or use bullet-deformable");
    }
    if (model.drag * settings.dt / m >= 1.0) {
      return refuse(drag_field,
                    "drag * dt / mass must be < 1 (kDP scales v by 1 - it); take a smaller "
                    "integrator.dt or a smaller drag");
    }
  }
  for (int k = 0; k < static_cast<int>(model.springs.size()); ++k) {
    if (model.springs[k].damping > 0.0) {
      return refuse(mysim::springField(model, k, "damping"),
                    "position-based links carry no spring damping; set it to 0 and damp with "
                    "forces.drag, or use bullet-deformable or bullet-implicit");
    }
  }
  return {};
}

}  // namespace reference
