#pragma once
// A scene of particles and springs listed one by one (scene_kind.h).
#include <vector>

#include "mysim/scene_kind.h"

namespace mysim {

struct ExplicitParticle {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  double mass = 1.0;
  bool pinned = false;
};

struct ParticlesScene : SceneKindBase {
  static constexpr const char* kType = "particles";
  std::vector<ExplicitParticle> particles;
  std::vector<Spring> springs;

  void read(FieldReader& system, const std::string& source);
  void build(Model& model) const;
  SystemSize size() const { return {double(particles.size()), double(springs.size())}; }
  // Refuses a scene whose every particle is pinned.
  void checkWhole(const IntegratorSettings&) const;
};

}  // namespace mysim
