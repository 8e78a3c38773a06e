// bullet-deformable and bullet-implicit: btDeformableMultiBodyDynamicsWorld with Bullet's own
// mass-spring and gravity forces, set up in the order docs/reference.md gives. Springs Bullet's
// mass-spring force cannot hold (a stiffness per family, a damping per link) go through our
// per-link spring force on Bullet's force interface; the solver, contacts and stepping stay
// Bullet's.
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletSoftBody/btDeformableBodySolver.h>
#include <BulletSoftBody/btDeformableGravityForce.h>
#include <BulletSoftBody/btDeformableMassSpringForce.h>
#include <BulletSoftBody/btDeformableMultiBodyConstraintSolver.h>
#include <BulletSoftBody/btDeformableMultiBodyDynamicsWorld.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>

#include "deformable_forces.h"
#include "mysim/cloth_surface.h"
#include "engine_support.h"
#include "soft_body.h"
#include "static_collider.h"
#include "steppers.h"

namespace reference {
namespace {

// Bullet's own self-collision (btSoftBody::defaultCollisionHandler with itself): the cloth's
// triangles as faces, VF_DD with setSelfCollision(true), so the deformable world adds face-face
// contacts (CollideFF_DD, within twice the body's margin) and its CCD pass
// (performGeometricCollisions). One margin serves the colliders and the self-contacts: half the
// thickness, or the colliders' if larger (checkSupported refuses a chain, which has no faces).
void enableSelfCollision(btSoftBody& body, const mysim::Model& model, std::vector<std::string>& notes) {
  for (const Eigen::Vector3i& t : mysim::clothTriangles(model)) body.appendFace(t[0], t[1], t[2]);
  body.m_cfg.collisions |= btSoftBody::fCollision::VF_DD;
  body.setSelfCollision(true);
  const double margin = std::max(softBodyMargin(model.colliders), 0.5 * *model.self_collision_thickness);
  body.getCollisionShape()->setMargin(margin);
  notes.push_back("self-collision by Bullet's own face-face contacts (VF_DD) at twice the soft "
                  "body's margin, " + std::to_string(margin) + " m");
}

// Counts what Bullet's Krylov solver does, which Bullet does not report: it wraps the
// preconditioner, which the solver applies once per iteration plus a fixed number of times per
// solve (CG, the projected implicit solve: 2; conjugate residual, the explicit one: 1, see
// btConjugateGradient.h and btConjugateResidual.h).
class CountingPreconditioner final : public Preconditioner {
 public:
  CountingPreconditioner(Preconditioner* inner, long applications_so_far)
      : applications(applications_so_far), inner_(inner) {}
  void operator()(const TVStack& x, TVStack& b) override {
    ++applications;
    (*inner_)(x, b);
  }
  void reinitialize(bool node_updated) override { inner_->reinitialize(node_updated); }
  long applications = 0;

 private:
  Preconditioner* inner_;
};

// m_cg and the Newton settings are protected: a subclass is the only way to set them.
class TunedDeformableSolver final : public btDeformableBodySolver {
 public:
  // Krylov iterations so far: preconditioner applications less the fixed ones of each solve.
  long iterations() const { return counter_ ? counter_->applications - fixed_ * solves_ : 0; }
  void countIterations(bool implicit) { fixed_ = implicit ? 2 : 1; }
  void solveDeformableConstraints(btScalar solverdt) override {
    // Bullet sets its preconditioner again as it sets up a step: wrap whichever it now uses.
    if (m_objective->m_preconditioner != counter_.get()) {
      counter_ = std::make_unique<CountingPreconditioner>(m_objective->m_preconditioner,
                                                          counter_ ? counter_->applications : 0);
      m_objective->m_preconditioner = counter_.get();
    }
    ++solves_;  // one Newton iteration: one linear solve
    btDeformableBodySolver::solveDeformableConstraints(solverdt);
  }

  void tune(double cg_tolerance, int cg_max_iterations, int newton_iterations) {
    // Bullet's CG stops at r.z <= tol * min(1, r0.z): a squared, preconditioned residual. Our
    // cg_tolerance bounds |r| / |b|, so the matching Bullet tolerance is its square.
    m_cg.m_tolerance = cg_tolerance * cg_tolerance;
    m_cg.m_maxIterations = cg_max_iterations;
    m_maxNewtonIterations = newton_iterations;
  }

 private:
  std::unique_ptr<CountingPreconditioner> counter_;
  long fixed_ = 2;
  long solves_ = 0;
};

class DeformableStepper final : public BulletStepper {
 public:
  DeformableStepper(const mysim::Model& model, const BulletSettings& settings, bool implicit)
      : model_(model) {
    config_ = std::make_unique<btSoftBodyRigidBodyCollisionConfiguration>();
    dispatcher_ = std::make_unique<btCollisionDispatcher>(config_.get());
    broadphase_ = std::make_unique<btDbvtBroadphase>();
    solver_ = std::make_unique<TunedDeformableSolver>();
    constraint_solver_ = std::make_unique<btDeformableMultiBodyConstraintSolver>();
    constraint_solver_->setDeformableSolver(solver_.get());
    world_ = std::make_unique<btDeformableMultiBodyDynamicsWorld>(
        dispatcher_.get(), broadphase_.get(), constraint_solver_.get(), config_.get(),
        solver_.get());
    // Gravity both ways (the world info defaults to -10) and, below, as a deformable force: the
    // only gravity the implicit solve sees.
    const btVector3 g = toBt(model.gravity);
    world_->setGravity(g);
    btSoftBodyWorldInfo& info = world_->getWorldInfo();
    info.m_gravity = g;
    info.m_sparsesdf.setDefaultVoxelsz(sdfVoxelSize(model.colliders));
    info.m_sparsesdf.Reset();

    body_.reset(
        buildSoftBody(info, model, [](btSoftBody&, const mysim::Spring&) { return nullptr; }));
    body_->setActivationState(DISABLE_DEACTIVATION);  // else it sleeps below 0.04 m/s
    body_->getCollisionShape()->setMargin(softBodyMargin(model.colliders));
    addContacts(model, implicit);
    world_->addSoftBody(body_.get());

    addSprings(model, settings);
    if (!model.hinges.empty()) {
      hinges_ = std::make_unique<DeformableHingeForce>(model.hinges);
      world_->addForce(body_.get(), hinges_.get());
      notes_.push_back(
          "hinge bending through springcheck's hinge force on Bullet's force interface (the "
          "force law is mysim's, docs/materials.md; the solver is Bullet's)");
    }
    gravity_ = std::make_unique<btDeformableGravityForce>(g);
    world_->addForce(body_.get(), gravity_.get());
    if (model.wind) {
      wind_ = std::make_unique<DeformableWindForce>(*model.wind, &time_);
      world_->addForce(body_.get(), wind_.get());
    }
    if (model.drag > 0.0) {
      drag_ = std::make_unique<DeformableDragForce>(model.drag);
      world_->addForce(body_.get(), drag_.get());
      notes_.push_back("drag as a custom damping force, solved with Bullet's implicit damping");
    }
    world_->setImplicit(implicit);
    world_->setLineSearch(false);
    world_->setUseProjection(implicit);  // implicit without projection does not move at all
    // One Newton step: Baraff-Witkin's linearised backward Euler, as mysim's backward-euler.
    solver_->tune(settings.cg_tolerance, settings.cg_max_iterations, 1);
    solver_->countIterations(implicit);
  }

  // Bullet's mass-spring force where it holds the model (one stiffness for non-bending links,
  // one for bending (flex) links, one damping; damping along the link, conserve_angular =
  // true, as mysim's); otherwise ours, link by link.
  void addSprings(const mysim::Model& model, const BulletSettings& settings) {
    const std::optional<UniformSprings> uniform = uniformSprings(model);
    if (model.springs.empty()) {
    } else if (uniform && !settings.force_per_link_springs) {
      mass_spring_ = std::make_unique<btDeformableMassSpringForce>(
          uniform->stiffness, uniform->damping, true, uniform->bending_stiffness);
      world_->addForce(body_.get(), mass_spring_.get());
    } else {
      std::vector<DeformableLinkSpringForce::LinkParameters> links;
      for (const mysim::Spring& s : model.springs) links.push_back({s.stiffness, s.damping});
      link_springs_ = std::make_unique<DeformableLinkSpringForce>(std::move(links));
      world_->addForce(body_.get(), link_springs_.get());
      notes_.push_back(
          "springs through springcheck's per-link spring force on Bullet's force interface "
          "(the force law is ours, a stiffness and damping per link; the solver, contacts and "
          "time stepping are Bullet's)");
    }
  }

  // The static colliders (node contacts against their SDF, with friction) and self-collision.
  void addContacts(const mysim::Model& model, bool implicit) {
    body_->m_cfg.collisions = 0;
    if (!model.colliders.empty()) {
      body_->m_cfg.collisions = btSoftBody::fCollision::SDF_RD | btSoftBody::fCollision::SDF_RDN;
      body_->m_cfg.kKHR = 1.0;  // contact hardness against static bodies: 0.1 by default (soft)
      if (anyFriction(model.colliders)) body_->m_cfg.kDF = 1.0;  // x each body's friction
      colliders_ = addColliders(*world_, model.colliders);
      if (implicit) {
        notes_.push_back(
            "implicit mode with static colliders: against a sphere it exploded in most set-ups "
            "tried (docs/reference.md); a blow-up here is Bullet's, reported as is");
      }
    }
    if (model.self_collision_thickness) enableSelfCollision(*body_, model, notes_);
  }

  ~DeformableStepper() override {
    world_->removeSoftBody(body_.get());
    colliders_.clear();
  }

  mysim::StepCounts step(mysim::State& state, double h) override {
    time_ = state.t;
    const long before = solver_->iterations();
    stepWorld(*world_, *body_, model_, state, h);
    return {.accepted = 1, .linear_iterations = solver_->iterations() - before};
  }

  const btSoftBody& body() const override { return *body_; }
  const std::vector<std::string>& notes() const override { return notes_; }

 private:
  mysim::Model model_;  // pins follow its pin motion
  double time_ = 0.0;
  std::vector<std::string> notes_;
  std::unique_ptr<btSoftBodyRigidBodyCollisionConfiguration> config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btDbvtBroadphase> broadphase_;
  std::unique_ptr<TunedDeformableSolver> solver_;
  std::unique_ptr<btDeformableMultiBodyConstraintSolver> constraint_solver_;
  std::unique_ptr<btDeformableMultiBodyDynamicsWorld> world_;
  std::unique_ptr<btSoftBody> body_;
  std::unique_ptr<btDeformableMassSpringForce> mass_spring_;
  std::unique_ptr<DeformableLinkSpringForce> link_springs_;
  std::unique_ptr<btDeformableGravityForce> gravity_;
  std::unique_ptr<DeformableWindForce> wind_;
  std::unique_ptr<DeformableDragForce> drag_;
  std::unique_ptr<DeformableHingeForce> hinges_;
  std::vector<std::unique_ptr<StaticCollider>> colliders_;
};

}  // namespace

std::unique_ptr<BulletStepper> makeDeformableStepper(const mysim::Model& model,
                                                     const BulletSettings& settings,
                                                     bool implicit) {
  return std::make_unique<DeformableStepper>(model, settings, implicit);
}

}  // namespace reference
