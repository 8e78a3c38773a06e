#pragma once
#include <expected>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mysim/blowup.h"
#include "mysim/chain.h"
#include "mysim/cloth.h"
#include "mysim/integrator.h"
#include "mysim/model.h"

namespace mysim {

enum class SystemKind { Circle, Chain, Cloth, Particles };
const char* systemKindName(SystemKind kind);

struct ExplicitParticle {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  double mass = 1.0;
  bool pinned = false;
};

// Settings for the Bullet classic (position-based) engine; mysim ignores them.
struct ClassicSettings {
  int iterations = 10;  // positional solver passes per step (piterations)
};

// A scene as the user described it, validated: the plain description every engine is built from.
// No engine reads JSON. The schema is in docs/scenes.md.
struct Scene {
  std::string name;
  std::string description;
  std::string source;  // file it came from, for messages

  SystemKind kind = SystemKind::Cloth;
  Eigen::Vector2d circle_start{1.0, 0.0};
  ChainShape chain;
  ClothShape cloth;
  std::vector<ExplicitParticle> particles;  // kind == Particles
  std::vector<Spring> springs;              // kind == Particles
  std::vector<int> pins;                    // chain and cloth: pinned particle indices
  Vec3 start_velocity = Vec3::Zero();       // chain and cloth: every particle's initial velocity

  Vec3 gravity = Vec3::Zero();
  double drag = 0.0;
  std::optional<Wind> wind;
  std::optional<PinMotion> pin_motion;
  std::optional<Sphere> sphere;

  IntegratorSettings integrator;
  double dt = 0.04;              // s
  double duration = 10.0;        // s
  double sample_interval = 0.0;  // s between trajectory frames; 0 = about 200 frames a run
  BlowUpLimits limits;
  ClassicSettings classic;
};

// The model of a chain, cloth or particles scene (the circle has none).
Model buildModel(const Scene& scene);

// The system to integrate, and its start state.
std::unique_ptr<OdeSystem> makeSystem(const Scene& scene);
State initialState(const Scene& scene, OdeSystem& system);

}  // namespace mysim
