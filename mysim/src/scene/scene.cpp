#include "mysim/scene.h"

#include "mysim/circle_system.h"
#include "model/mesh_cloth.h"
#include "mysim/particle_system.h"

namespace mysim {

Model buildModel(const Scene& scene) {
  Model model;
  model.kind = scene.kind;
  switch (scene.kind) {
    case SystemKind::Circle:
      model.circle_start = scene.circle_start;
      break;
    case SystemKind::Chain:
      buildChain(scene.chain, model);
      if (scene.chain_end_mass > 0.0) {  // a material chain: its ends carry half a link
        model.mass[0] = model.mass[model.particleCount() - 1] = scene.chain_end_mass;
      }
      break;
    case SystemKind::Cloth:
      if (scene.cloth_mesh) {  // checked when the scene was read
        (void)buildMeshCloth(*scene.cloth_mesh, *scene.cloth_material, scene.cloth.origin, model);
        break;
      }
      buildCloth(scene.cloth, model);
      if (scene.cloth_material) {
        applyClothMaterial(*scene.cloth_material, scene.material_grid.dx, scene.material_grid.dy,
                           model);
        model.material->clamped = scene.material_clamped;
      }
      break;
    case SystemKind::Particles: {
      const int n = static_cast<int>(scene.particles.size());
      model.mass.resize(n);
      model.pinned.assign(n, 0);
      model.start_position.resize(3 * n);
      model.start_velocity.resize(3 * n);
      for (int p = 0; p < n; ++p) {
        const ExplicitParticle& particle = scene.particles[p];
        model.mass[p] = particle.mass;
        model.pinned[p] = particle.pinned;
        at3(model.start_position, p) = particle.position;
        at3(model.start_velocity, p) = particle.velocity;
      }
      model.springs = scene.springs;
      break;
    }
  }
  if (scene.kind == SystemKind::Chain || scene.kind == SystemKind::Cloth) {
    for (int p : scene.pins) model.pinned[p] = 1;
    for (int p = 0; p < model.particleCount(); ++p) {
      if (!model.pinned[p]) at3(model.start_velocity, p) = scene.start_velocity;
    }
  }
  model.gravity = scene.gravity;
  model.drag = scene.drag;
  model.wind = scene.wind;
  model.pin_motion = scene.pin_motion;
  model.colliders = scene.colliders;
  model.self_collision_thickness = scene.self_collision_thickness;
  return model;
}

std::unique_ptr<OdeSystem> makeSystem(std::shared_ptr<const Model> model,
                                      const BlowUpLimits& limits) {
  if (model->isCircle()) return std::make_unique<CircleSystem>(model->circle_start);
  return std::make_unique<ParticleSystem>(std::move(model), limits);
}

}  // namespace mysim
