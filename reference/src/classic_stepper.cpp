// bullet-classic: btSoftRigidDynamicsWorld, Bullet's position-based soft body solver. Springs
// become links whose stiffness kLST is mapped from k (see classicLinkStiffness); the solver
// makes `bullet.classic_iterations` passes per step.
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>

#include <map>

#include "engine_support.h"
#include "soft_body.h"
#include "static_collider.h"
#include "steppers.h"

namespace reference {
namespace {

class ClassicStepper final : public BulletStepper {
 public:
  ClassicStepper(const mysim::Model& model, const BulletSettings& settings) : model_(model) {
    config_ = std::make_unique<btSoftBodyRigidBodyCollisionConfiguration>();
    dispatcher_ = std::make_unique<btCollisionDispatcher>(config_.get());
    broadphase_ = std::make_unique<btDbvtBroadphase>();
    constraint_solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
    world_ = std::make_unique<btSoftRigidDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                        constraint_solver_.get(), config_.get());
    const btVector3 g = toBt(model.gravity);
    world_->setGravity(g);
    btSoftBodyWorldInfo& info = world_->getWorldInfo();
    info.m_gravity = g;  // the world info keeps its own gravity (default -10)
    info.m_sparsesdf.Initialize();
    info.m_sparsesdf.setDefaultVoxelsz(sdfVoxelSize(model.colliders));
    info.m_sparsesdf.Reset();

    // Materials shared by links of equal kLST (a cloth has a handful).
    std::map<double, btSoftBody::Material*> materials;
    const double h = settings.dt;
    const int iterations = settings.classic_iterations;
    auto material = [&](btSoftBody& body, const mysim::Spring& s) {
      const double w = (model.pinned[s.i] ? 0.0 : 1.0 / model.mass[s.i]) +
                       (model.pinned[s.j] ? 0.0 : 1.0 / model.mass[s.j]);
      const double k_lst = classicLinkStiffness(s.stiffness, h, w, iterations);
      btSoftBody::Material*& m = materials[k_lst];
      if (!m) {
        m = body.appendMaterial();
        m->m_kLST = k_lst;
        m->m_kAST = m->m_kVST = 1.0;
      }
      return m;
    };
    body_.reset(buildSoftBody(info, model, material));
    body_->m_cfg.piterations = iterations;
    body_->setActivationState(DISABLE_DEACTIVATION);
    body_->getCollisionShape()->setMargin(softBodyMargin(model.colliders));
    if (model.drag > 0.0) {
      // The classic solver sets v = (x - x_old) / h * (1 - kDP): viscous drag c is c h / m.
      body_->m_cfg.kDP = model.drag * h / uniformFreeMass(model);
      notes_.push_back("drag applied as Bullet's per-step velocity scale 1 - kDP, kDP = c h / m");
    }
    body_->m_cfg.collisions = 0;
    if (!model.colliders.empty()) {
      body_->m_cfg.collisions = btSoftBody::fCollision::SDF_RS;
      body_->m_cfg.kKHR = 1.0;
      body_->m_cfg.kDF = anyFriction(model.colliders) ? 1.0 : 0.0;  // x each body's friction
      colliders_ = addColliders(*world_, model.colliders);
    }
    if (model.wind) {
      // Bullet's aero model (setWindVelocity with kLF/kDG) is a drag on relative velocity over
      // node normals: another force law. mysim's wind is a force per particle, which the classic
      // body takes as it is through addForce before each step.
      notes_.push_back(
          "wind applied per node through btSoftBody::addForce (mysim's force law), "
          "not Bullet's aero model");
    }
    notes_.push_back(
        "springs mapped to links with kLST = 1 - (1 - a)^(1/n), a = k h^2 w / (1 + k h^2 w), n = " +
        std::to_string(iterations));
    world_->addSoftBody(body_.get());
  }

  ~ClassicStepper() override {
    world_->removeSoftBody(body_.get());
    colliders_.clear();
  }

  mysim::StepCounts step(mysim::State& state, double h) override {
    if (model_.wind) {
      for (int p = 0; p < model_.particleCount(); ++p) {
        body_->addForce(toBt(mysim::windForce(*model_.wind, p, state.t)), p);
      }
    }
    stepWorld(*world_, *body_, model_, state, h);
    // Its cost beyond the step: the position solver's passes over every link.
    return {.accepted = 1, .linear_iterations = body_->m_cfg.piterations};
  }

  const btSoftBody& body() const override { return *body_; }
  const std::vector<std::string>& notes() const override { return notes_; }

 private:
  mysim::Model model_;  // pins follow its pin motion; wind from its wind
  std::vector<std::string> notes_;
  std::unique_ptr<btSoftBodyRigidBodyCollisionConfiguration> config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btDbvtBroadphase> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> constraint_solver_;
  std::unique_ptr<btSoftRigidDynamicsWorld> world_;
  std::unique_ptr<btSoftBody> body_;
  std::vector<std::unique_ptr<StaticCollider>> colliders_;
};

}  // namespace

std::unique_ptr<BulletStepper> makeClassicStepper(const mysim::Model& model,
                                                  const BulletSettings& settings) {
  return std::make_unique<ClassicStepper>(model, settings);
}

}  // namespace reference
