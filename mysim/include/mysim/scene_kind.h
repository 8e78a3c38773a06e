#pragma once
// What every kind of system a scene can hold provides. A kind is one struct, declared in its own
// header and defined in its own source (circle_scene.h, chain_scene.h, cloth_scene.h,
// particles_scene.h), and one name in Scene's variant (scene.h): the scene reader finds it by
// its kType, the model builder calls its build, and nothing else names it.
#include <concepts>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mysim/integrator.h"
#include "mysim/json_input.h"
#include "mysim/model.h"

namespace mysim {

// Particles and springs a scene will build (springs: an upper bound for a cloth), for the run
// limits, which are checked before anything is built.
struct SystemSize {
  double particles = 0.0;
  double springs = 0.0;
};

// What a kind may leave to these defaults (a kind declares its own to replace one).
struct SceneKindBase {
  // Throws FieldError when the whole scene cannot run (every particle pinned, an integrator the
  // kind cannot take).
  void checkWhole(const IntegratorSettings&) const {}
  // The drag (N s/m) its material's damping rate means, when it has one: the scene's
  // forces.drag must then be silent (it would say it twice).
  std::optional<double> materialDrag() const { return std::nullopt; }
  // Whether it bends by hinges, which the CG's SSOR preconditioner does not see.
  bool bendsByHinges() const { return false; }
  // What reading it skipped and the run goes on without (a mesh file's unsupported lines).
  std::vector<std::string> warnings() const { return {}; }
};

// A body built to hang from its pins (a chain, a cloth): which particles are pinned, and the
// velocity every other particle starts with.
struct HangingStart {
  std::vector<int> pins;
  Vec3 velocity = Vec3::Zero();

  // Pins the model's particles, gives the free ones the velocity, marks it hanging.
  void apply(Model& model) const;
  // Throws FieldError ("system.pins") when every one of `particles` is pinned.
  void checkSomethingMoves(double particles) const;
};

template <class Kind>
concept SceneKind = std::derived_from<Kind, SceneKindBase> &&
                    requires(Kind kind, const Kind& read, FieldReader& system,
                             const std::string& source, Model& model) {
                      { Kind::kType } -> std::convertible_to<std::string_view>;
                      kind.read(system, source);  // "system"'s fields; source: the scene file
                      read.build(model);          // its particles, springs, pins, naming
                      { read.size() } -> std::same_as<SystemSize>;
                    };

}  // namespace mysim
