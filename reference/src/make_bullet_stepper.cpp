#include "mysim/circle_system.h"
#include "reference/bullet_engine.h"
#include "steppers.h"

namespace reference {
namespace {

// The circle through its mechanical twin: Bullet steps the twin (a unit mass on a zero-length
// spring from a pin), and the run sees the circle's own state, y = (x, y) of the mass.
class CircleTwinStepper final : public BulletStepper {
 public:
  CircleTwinStepper(std::unique_ptr<BulletStepper> twin, const mysim::Model& twin_model)
      : twin_(std::move(twin)) {
    twin_state_.y.resize(6 * twin_model.particleCount());
    twin_state_.y << twin_model.start_position, twin_model.start_velocity;
    notes_ = twin_->notes();
    notes_.push_back(
        "the circle runs as its mechanical twin: a unit mass on a zero-length spring of "
        "stiffness 1 from a pin at the origin");
  }

  mysim::StepCounts step(mysim::State& state, double h) override {
    twin_state_.t = state.t;
    const mysim::StepCounts counts = twin_->step(twin_state_, h);
    state.t = twin_state_.t;
    state.y = mysim::at3(twin_state_.y, mysim::kCircleTwinParticle).head<2>();
    return counts;
  }
  const btSoftBody& body() const override { return twin_->body(); }
  const std::vector<std::string>& notes() const override { return notes_; }

 private:
  std::unique_ptr<BulletStepper> twin_;
  mysim::State twin_state_;
  std::vector<std::string> notes_;
};

}  // namespace

std::expected<std::unique_ptr<BulletStepper>, std::string> makeBulletStepper(
    const mysim::Model& model, BulletEngine engine, const BulletSettings& settings) {
  if (model.isCircle()) {
    const mysim::Model twin = mysim::circleTwin(model);
    auto stepper = makeBulletStepper(twin, engine, settings);
    if (!stepper) return stepper;
    return std::make_unique<CircleTwinStepper>(std::move(*stepper), twin);
  }
  if (auto supported = checkSupported(model, engine, settings); !supported) {
    return std::unexpected(supported.error());
  }
  if (engine == BulletEngine::Classic) return makeClassicStepper(model, settings);
  return makeDeformableStepper(model, settings, engine == BulletEngine::Implicit);
}

}  // namespace reference
