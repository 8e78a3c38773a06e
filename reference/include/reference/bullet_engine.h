#pragma once
// Bullet 3.24 twins of mysim scenes, built from the same scene description and the same model
// topology (node order, rest lengths, masses, pins). See docs/reference.md.
#include <expected>
#include <memory>
#include <string>
#include <vector>

#include "mysim/integrator.h"
#include "mysim/particle_system.h"
#include "mysim/scene.h"
#include "mysim/simulation.h"

class btSoftBody;

namespace reference {

enum class BulletEngine {
  Deformable,  // btDeformableMultiBodyDynamicsWorld, explicit (symplectic Euler, implicit damping)
  Implicit,    // the same world, linearised backward Euler + CG with projection
  Classic,     // btSoftRigidDynamicsWorld, position-based links
};

// "bullet-deformable", "bullet-implicit", "bullet-classic".
const std::vector<std::string>& bulletEngineNames();
std::expected<BulletEngine, std::string> bulletEngineNamed(const std::string& name);
const char* bulletEngineName(BulletEngine engine);

// A Bullet world holding one soft body, stepped as an Integrator over a mysim ParticleSystem of
// the same model: step() advances Bullet by exactly one stepSimulation(h, 0) and copies the node
// state into the mysim state, so mysim's run loop, health checks and energy apply unchanged.
class BulletStepper : public mysim::Integrator {
 public:
  bool needsParticles() const override { return true; }
  virtual const btSoftBody& body() const = 0;
  // What this engine does differently from mysim for this scene (e.g. how drag is applied).
  virtual const std::vector<std::string>& notes() const = 0;
};

// Builds the engine for a scene, or says which field it cannot represent and why.
[[nodiscard]] std::expected<std::unique_ptr<BulletStepper>, std::string> makeBulletStepper(
    const mysim::Scene& scene, const mysim::Model& model, BulletEngine engine);

// Runs a scene in a Bullet engine, recorded like a mysim run.
[[nodiscard]] std::expected<mysim::RunRecord, std::string> runBullet(const mysim::Scene& scene,
                                                                     BulletEngine engine);

// Classic link stiffness kLST in [0, 1] for a spring of stiffness k between particles of inverse
// masses wa + wb = w at step h, with n solver iterations. A compliant constraint (XPBD, Macklin
// et al. 2016) solved exactly closes  alpha = k h^2 w / (1 + k h^2 w)  of a link's error in a
// step; n passes of kLST on a lone link close 1 - (1 - kLST)^n of it, so
//   kLST = 1 - (1 - alpha)^(1/n).
// Exact for a lone link; on a mesh the Gauss-Seidel passes couple links, so it is approximate
// (measured in docs/reference.md).
double classicLinkStiffness(double k, double h, double inverse_mass_sum, int iterations);

}  // namespace reference
