// The run loop: determinism, blow-up detection, wind, energy bookkeeping.
// ctest-label: unit
// ctest-label ExternalWork: physics
#include "mysim/simulation.h"

#include <gtest/gtest.h>

#include <functional>

#include "mysim/scene_file.h"
#include "test_support.h"

namespace mysim {
namespace {

Scene sceneFile(const std::string& name) {
  auto scene = loadScene(std::string(SPRINGCHECK_SOURCE_DIR "/scenes/seed/") + name);
  EXPECT_TRUE(scene) << scene.error();
  return *scene;
}

RunRecord runScene(const Scene& scene) { return testing::simulateScene(scene); }

// FNV-1a over the bytes of every sampled frame.
std::uint64_t hashFrames(const RunRecord& r) {
  std::uint64_t h = 1469598103934665603ULL;
  for (const ParticleRows& f : r.frames) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(f.data());
    for (std::size_t i = 0; i < f.size() * sizeof(double); ++i)
      h = (h ^ bytes[i]) * 1099511628211ULL;
  }
  return h;
}

TEST(Determinism, SameWindySceneGivesBitIdenticalTrajectories) {
  Scene scene = sceneFile("cloth_wind.json");
  scene.duration = 1.0;
  const RunRecord a = runScene(scene), b = runScene(scene);
  ASSERT_FALSE(a.blowup);
  EXPECT_EQ(hashFrames(a), hashFrames(b));
  // And the seed matters: another seed, other gusts, another trajectory.
  scene.wind->seed += 1;
  EXPECT_NE(hashFrames(runScene(scene)), hashFrames(a));
}

TEST(Wind, ForceIsAPureFunctionOfSeedParticleAndGustWindow) {
  const Wind w{Vec3::UnitZ(), 2.0, 0.5, 0.1, 1.0, 7};
  EXPECT_EQ(windForce(w, 3, 0.01), windForce(w, 3, 0.09));  // same window
  EXPECT_NE(windForce(w, 3, 0.01), windForce(w, 3, 0.11));  // next window
  EXPECT_NE(windForce(w, 3, 0.01), windForce(w, 4, 0.01));  // another particle
  double mean = 0.0;
  for (int p = 0; p < 20000; ++p) {
    const Vec3 f = windForce(w, p, 0.0);
    EXPECT_NEAR(f.z(), 2.0, 1.0 + 1e-12);  // strength (1 +- gust)
    EXPECT_EQ(f.x(), 0.0);
    mean += f.z() / 20000;
  }
  EXPECT_NEAR(mean, 2.0, 0.02);  // uniform gusts: standard error 2 * 0.5 / sqrt(3 * 20000) = 0.004
}

TEST(Wind, CoverageSelectsAboutThatFractionOfParticles) {
  const Wind w{Vec3::UnitX(), 1.0, 0.0, 0.1, 0.3, 11};
  int touched = 0;
  for (int p = 0; p < 10000; ++p) touched += windForce(w, p, 0.25).norm() > 0;
  EXPECT_NEAR(touched / 10000.0, 0.3, 0.02);  // binomial standard error 0.0046
}

TEST(BlowUp, ExplicitEulerOnTheStiffClothIsStoppedWithTimeAndCheck) {
  Scene scene = sceneFile("cloth.json");
  scene.integrator.name = "euler";
  scene.dt = 0.02;
  const RunRecord r = runScene(scene);
  ASSERT_TRUE(r.blowup.has_value());
  EXPECT_GT(r.blowup->time, 0.0);
  EXPECT_LT(r.blowup->time, scene.duration);
  EXPECT_NEAR(r.blowup->time, r.blowup->step * scene.dt, 1e-9);
  EXPECT_EQ(r.steps, r.blowup->step);
  EXPECT_FALSE(r.blowup->check.empty());
  for (const ParticleRows& f : r.frames) EXPECT_TRUE(f.allFinite());  // no NaN ever recorded
  EXPECT_LT(r.times.back(), r.blowup->time);
}

TEST(BlowUp, NonFiniteStateIsCaughtAtTheStepItAppears) {
  testing::Oscillator osc;
  ParticleSystem system(osc.model(), {});
  State s = system.initialState();
  s.y[4] = std::numeric_limits<double>::quiet_NaN();
  auto bad = system.checkHealth(s);
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->check, "non-finite");
}

TEST(EnergyTerms, HandMadeCaseSplitsKineticGravityAndSpring) {
  Model m;
  m.mass = (Vector(2) << 2.0, 3.0).finished();
  m.pinned = {1, 0};
  m.start_position = (Vector(6) << 0, 0, 0, 0, -2, 0).finished();
  m.start_velocity = Vector::Zero(6);
  m.gravity = Vec3(0, -10, 0);
  m.springs.push_back({0, 1, 1.5, 8.0, 0.0, SpringFamily::Custom});
  Vector v = (Vector(6) << 5, 5, 5, 1, 2, 0).finished();  // the pinned particle's v is ignored
  const EnergyTerms e = mechanicalEnergy(m, m.start_position, v);
  EXPECT_DOUBLE_EQ(e.kinetic, 0.5 * 3 * 5);    // 7.5 J
  EXPECT_DOUBLE_EQ(e.gravity, -3 * 10 * 2);    // -m g.x = 3 * (-10) * (-2) -> -60 J
  EXPECT_DOUBLE_EQ(e.spring, 0.5 * 8 * 0.25);  // stretched 0.5 m: 1 J
}

TEST(EnergyTerms, DampedChainNeverGainsEnergyBeyondRoundOff) {
  Scene scene = sceneFile("chain.json");
  const RunRecord r = runScene(scene);
  ASSERT_FALSE(r.blowup);
  for (std::size_t f = 1; f < r.energies.size(); ++f) {
    // Spring damping and drag only remove energy; RK4's own error at this step is ~1e-7 J.
    EXPECT_LE(r.energies[f].total(), r.energies[f - 1].total() + 1e-6) << r.times[f];
  }
}

}  // namespace
}  // namespace mysim

namespace mysim {
namespace {

// An undamped chain driven from outside: whatever energy it gains is the work done on it, so
// E(t) - E(0) - W(t) stays at the integrator's error (RK4 at a small step: tiny) - and would be
// of the order of W itself with a wrong sign or a missing term.
class ExternalWork : public ::testing::TestWithParam<std::string> {};

TEST_P(ExternalWork, AccountsForEveryJouleTheDriverPutsIn) {
  Scene scene = sceneFile("chain.json");
  std::get<ChainScene>(scene.system).shape.damping = 0.0;
  scene.drag = 0.0;
  scene.dt = 0.001;
  scene.duration = 3.0;
  if (GetParam() == "pins") scene.pin_motion = PinMotion{Vec3::UnitY(), 0.1, 1.0};
  if (GetParam() == "wind") scene.wind = Wind{Vec3::UnitZ(), 0.05, 0.5, 0.1, 1.0, 3};
  const RunRecord r = runScene(scene);
  ASSERT_FALSE(r.blowup);
  double worst = 0.0, work = 0.0;
  for (const EnergyTerms& e : r.energies) {
    worst = std::max(worst, std::abs(e.total() - r.energies.front().total() - e.external_work));
    work = std::max(work, std::abs(e.external_work));
  }
  EXPECT_GT(work, 0.01);          // the driver did real work
  EXPECT_LT(worst, 1e-3 * work);  // and every joule of it is accounted for
}

INSTANTIATE_TEST_SUITE_P(Drivers, ExternalWork, ::testing::Values("pins", "wind"));

}  // namespace
}  // namespace mysim

namespace mysim {
namespace {

RunRecord runUntilRest(Scene scene, double rest_displacement) {
  auto system = makeSystem(scene);
  IntegratorStepper stepper(*system, std::move(makeIntegrator(scene.integrator).value()));
  RunSettings settings{scene.dt, scene.duration, scene.sample_interval};
  settings.rest_displacement = rest_displacement;
  return simulate(*system, stepper, system->initialState(), settings);
}

// RunSettings::rest_displacement: the seed chain, damped hard, comes to rest and its run stops
// there, at the state the whole run ends in; the undamped pendulum swings and runs whole.
TEST(RestStop, ADampedChainEndsAtItsRestAndASwingingPendulumRunsWhole) {
  Scene chain = sceneFile("chain.json");
  chain.integrator.name = "backward-euler";
  chain.drag = 0.25;  // 5 /s
  chain.dt = 0.01;
  chain.duration = 60.0;
  const RunRecord whole = runUntilRest(chain, 0.0);
  const RunRecord rested = runUntilRest(chain, 1e-11);
  ASSERT_TRUE(rested.rested_at);
  EXPECT_FALSE(whole.rested_at);
  EXPECT_LT(*rested.rested_at, 0.5 * chain.duration);
  EXPECT_EQ(rested.steps, std::lround(*rested.rested_at / chain.dt));
  const double apart =
      (whole.frames.back() - rested.frames.back()).leftCols<3>().cwiseAbs().maxCoeff();
  EXPECT_LT(apart, 1e-9) << "the rest it stopped at is the whole run's end";

  Scene pendulum = sceneFile("pendulum.json");
  pendulum.integrator.name = "verlet";
  const RunRecord swinging = runUntilRest(pendulum, 1e-6);
  EXPECT_FALSE(swinging.rested_at);
  EXPECT_EQ(swinging.steps, stepCount({pendulum.dt, pendulum.duration}));
}

}  // namespace
}  // namespace mysim
