#pragma once
// Bullet 3.24 twins of mysim models, built from the same model (node order, rest lengths, masses,
// pins, force terms). See docs/reference.md.
#include <expected>
#include <memory>
#include <string>
#include <vector>

#include "mysim/integrator.h"
#include "mysim/model.h"
#include "mysim/scene.h"
#include "mysim/stepper.h"

class btSoftBody;

namespace reference {

enum class BulletEngine {
  Deformable,  // btDeformableMultiBodyDynamicsWorld, explicit (symplectic Euler, implicit damping)
  Implicit,    // the same world, linearised backward Euler + CG with projection
  Classic,     // btSoftRigidDynamicsWorld, position-based links
};
constexpr BulletEngine kBulletEngines[] = {BulletEngine::Deformable, BulletEngine::Implicit,
                                           BulletEngine::Classic};

// "bullet-deformable", "bullet-implicit", "bullet-classic".
const char* bulletEngineName(BulletEngine engine);
// What the engine is, in a line (for `springcheck list`).
const char* bulletEngineDescription(BulletEngine engine);
// The scheme that steps it, for tables: "bullet-explicit", "bullet-backward-euler",
// "bullet-pbd-N".
std::string bulletIntegratorName(BulletEngine engine, int classic_iterations);
// The mysim integrator whose theory (order, stability limit) an engine's scheme follows
// (docs/reference.md): the explicit deformable world is symplectic Euler, the implicit one
// linearised backward Euler; empty for classic, which moves positions, not forces.
const char* bulletScheme(BulletEngine engine);

// The scene section only Bullet engines read: "bullet": {"classic_iterations": N}.
const mysim::EngineSection& bulletSceneSection();

// How to run: the scene step (classic maps stiffness through it), the implicit solver's CG
// settings (mysim's backward-euler settings, so both implicit solvers stop alike), and the
// classic solver's passes per step.
struct BulletSettings {
  std::string source;  // the scene file, for messages
  double dt = 0.01;
  double cg_tolerance = 1e-8;
  int cg_max_iterations = 1000;
  int classic_iterations = 10;
  // Deformable engines: use the per-link spring force even where Bullet's own mass-spring force
  // holds every parameter (the test that checks one against the other sets it).
  bool force_per_link_springs = false;
};
BulletSettings bulletSettings(const std::string& source, double dt,
                              const mysim::IntegratorSettings& integrator,
                              const mysim::EngineSettings& engine_settings);

// A Bullet world holding one soft body, stepping a run: step() advances Bullet by exactly one
// stepSimulation(h, 0) and copies the node state into the mysim state layout, so mysim's run
// loop, health checks and energy apply unchanged.
class BulletStepper : public mysim::Stepper {
 public:
  virtual const btSoftBody& body() const = 0;
  // What this engine does differently from mysim for this model (e.g. how drag is applied,
  // whose force law the springs follow).
  virtual const std::vector<std::string>& notes() const = 0;
};

// Refuses, naming the engine and the scene field, what an engine cannot represent (so no force
// term is ever dropped silently); nothing else.
[[nodiscard]] std::expected<void, std::string> checkSupported(const mysim::Model& model,
                                                              BulletEngine engine,
                                                              const BulletSettings& settings);

// Builds the engine for a model, or says which field it cannot represent and why. The circle
// runs as its mechanical twin (mysim::circleTwin) and is reported in the circle's state layout.
[[nodiscard]] std::expected<std::unique_ptr<BulletStepper>, std::string> makeBulletStepper(
    const mysim::Model& model, BulletEngine engine, const BulletSettings& settings);

// Classic link stiffness kLST in [0, 1] for a spring of stiffness k between particles of inverse
// masses wa + wb = w at step h, with n solver iterations. A compliant constraint (XPBD, Macklin
// et al. 2016) solved exactly closes  alpha = k h^2 w / (1 + k h^2 w)  of a link's error in a
// step; n passes of kLST on a lone link close 1 - (1 - kLST)^n of it, so
//   kLST = 1 - (1 - alpha)^(1/n).
// Exact for a lone link; on a mesh the Gauss-Seidel passes couple links, so it is approximate
// (measured in docs/reference.md).
double classicLinkStiffness(double k, double h, double inverse_mass_sum, int iterations);

}  // namespace reference
