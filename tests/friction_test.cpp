// Coulomb friction on colliders, held to the rigid block's closed forms (sliding_contact.h): a
// particle or a cloth at rest on an incline sticks when tan(theta) <= mu_s and otherwise slides
// with g (sin(theta) - mu_k cos(theta)); a sliding one stops after v0^2 / (2 mu_k g). In every
// mysim integrator, at angles and coefficients on both sides of the threshold; Bullet's engines
// as measured (docs/contact.md); bad coefficients refused naming file and field.
// ctest-label: physics,bullet
// ctest-label FrictionInput: validation,bullet,external
// ctest-label FrictionOfACloth: physics,slow
// ctest-label FrictionAtLargeSteps: physics
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "compare/engines/engine_registry.h"
#include "compare/metrics/closed_form.h"
#include "mysim/integrator.h"
#include "mysim/scene_file.h"
#include "contact_scenes.h"
#include "source_root.h"

namespace springcheck {
namespace {

constexpr double kG = 9.8;
// "Sticks": the issue's bound, 1e-6 m over the second (mysim holds 1e-13: the slide is undone
// exactly each step, only rounding remains).
constexpr double kStuck = 1e-6;
// "Slides within 1 % of the closed form": first-order integrators are h / t = 0.1 % long at
// h = 1 ms over 1 s (s_n = a h^2 n (n + 1) / 2); 1 % leaves ten times that.
constexpr double kSlideRelative = 0.01;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// One 100 g particle at rest on an incline of `degrees`, on the surface grown by the 1 mm margin:
// the plane tilted (gravity down) or, with tilt_gravity, the ground level and gravity turned.
std::string inclineScene(double degrees, double mu_s, double mu_k, bool tilt_gravity,
                         const std::string& integrator, double speed = 0.0) {
  const double s = std::sin(radians(degrees)), c = std::cos(radians(degrees));
  std::ostringstream j;
  j.precision(17);
  const double nx = tilt_gravity ? 0.0 : s, ny = tilt_gravity ? 1.0 : c;
  // Down the slope: along the plane, away from the normal's tilt.
  const double dx = tilt_gravity ? 1.0 : c, dy = tilt_gravity ? 0.0 : -s;
  j << R"({"system": {"type": "particles", "particles": [{"position": [)" << 1e-3 * nx << ", "
    << 1e-3 * ny << R"(, 0], "velocity": [)" << speed * dx << ", " << speed * dy
    << R"(, 0], "mass": 0.1}]}, "forces": {"gravity": [)"
    << (tilt_gravity ? kG * s : 0.0) << ", " << (tilt_gravity ? -kG * c : -kG)
    << R"(, 0]}, "colliders": [{"type": "plane", "point": [0, 0, 0], "normal": [)" << nx << ", "
    << ny << R"(, 0], "margin": 0.001, "friction": {"static": )" << mu_s << R"(, "kinetic": )"
    << mu_k << R"(}}], "integrator": {"name": ")" << integrator
    << R"(", "dt": 0.001, "duration": 1.0}})";
  return j.str();
}

struct Judged {
  ClosedFormError error;
  mysim::RunRecord run;
};

Judged runAndJudge(const EngineRegistry& registry, const std::string& spec, const mysim::Scene& scene) {
  auto run = registry.run(spec, scene);
  EXPECT_TRUE(run) << spec << ": " << run.error().message;
  EXPECT_FALSE(run->blowup) << spec << ": blew up at " << run->blowup->time << ": " << run->blowup->detail;
  const ClosedFormResult judged = closedFormError(mysim::buildModel(scene), *run);
  EXPECT_TRUE(judged) << spec << ": " << judged.error();
  return {judged.value_or(ClosedFormError{}), *run};
}

// Whether the block sticks, from the scene's numbers (not from the code under test).
bool sticks(double degrees, double mu_s) { return std::tan(radians(degrees)) <= mu_s; }

void expectClosedForm(const Judged& j, bool stuck, const std::string& what) {
  if (stuck) {
    EXPECT_EQ(j.error.exact, 0.0) << what;
    EXPECT_LT(j.error.error, kStuck) << what;
  } else {
    ASSERT_GT(j.error.exact, 0.0) << what;
    EXPECT_LT(j.error.error / j.error.exact, kSlideRelative) << what << ": " << j.error.error << " m of "
                                                             << j.error.exact << " m";
  }
}

class FrictionInEveryIntegrator : public ::testing::TestWithParam<std::string> {};

// Angles one degree either side of atan(mu_s), and far from it, with mu_s = mu_k and mu_s > mu_k,
// the plane tilted and gravity turned.
TEST_P(FrictionInEveryIntegrator, AParticleSticksUpToTanThetaEqualMuSAndElseSlidesTheClosedFormDistance) {
  const EngineRegistry registry;
  struct Case { double mu_s, mu_k, degrees; };
  std::vector<Case> cases;
  for (auto [mu_s, mu_k] : {std::pair{0.3, 0.3}, {0.6, 0.35}, {1.2, 0.9}}) {
    const double threshold = std::atan(mu_s) * 180.0 / std::numbers::pi;
    for (double degrees : {threshold - 1.0, threshold + 1.0, 5.0, 70.0}) cases.push_back({mu_s, mu_k, degrees});
  }
  for (const Case& c : cases) {
    for (bool tilt_gravity : {false, true}) {
      std::ostringstream what;
      what << GetParam() << ", " << c.degrees << " deg, mu " << c.mu_s << "/" << c.mu_k
           << (tilt_gravity ? ", gravity turned" : ", plane tilted");
      auto scene = mysim::parseScene(inclineScene(c.degrees, c.mu_s, c.mu_k, tilt_gravity, GetParam()), "incline.json");
      ASSERT_TRUE(scene) << scene.error();
      expectClosedForm(runAndJudge(registry, "mysim", *scene), sticks(c.degrees, c.mu_s), what.str());
    }
  }
}

// Started at v0 on level ground it stops after v0^2 / (2 mu_k g); sent up a 20 degree slope it
// stops, then sticks (mu_s 0.5 > tan 20) or slides back (mu_s 0.3).
TEST_P(FrictionInEveryIntegrator, ASlidingParticleStopsAtTheClosedFormDistanceAndThenSticksOrSlidesBack) {
  const EngineRegistry registry;
  for (double v0 : {1.0, 3.0}) {
    for (double mu_k : {0.25, 0.7}) {
      auto level = mysim::parseScene(inclineScene(0.0, mu_k, mu_k, false, GetParam(), v0), "stop.json");
      ASSERT_TRUE(level) << level.error();
      const Judged j = runAndJudge(registry, "mysim", *level);
      // Stopped within the second: v0^2 / (2 mu_k g); still sliding: v0 t - mu_k g t^2 / 2.
      const double a = mu_k * kG;
      const double distance = v0 / a <= 1.0 ? v0 * v0 / (2.0 * a) : v0 - 0.5 * a;
      EXPECT_NEAR(j.error.exact, distance, 1e-12) << "the reference is v0^2 / (2 mu_k g)";
      expectClosedForm(j, false, GetParam() + ": stopping from " + std::to_string(v0) + " m/s, mu_k " + std::to_string(mu_k));
    }
  }
  for (double mu_s : {0.5, 0.3}) {
    auto up = mysim::parseScene(inclineScene(20.0, mu_s, 0.3, false, GetParam(), -2.0), "up.json");
    ASSERT_TRUE(up) << up.error();
    expectClosedForm(runAndJudge(registry, "mysim", *up), false, GetParam() + ": up the slope, mu_s " + std::to_string(mu_s));
  }
}

// With drag the block still moves as one (equal masses): dv/dt = a - k v with k = drag / m; the
// closed form's exponentials hold a slide down 30 degrees and a stop from 2 m/s within 1 %.
TEST_P(FrictionInEveryIntegrator, DragSlowsTheSlideAndTheStopAsTheClosedFormSays) {
  const EngineRegistry registry;
  for (auto [degrees, speed] : {std::pair{30.0, 0.0}, {0.0, 2.0}}) {
    auto scene = mysim::parseScene(inclineScene(degrees, 0.3, 0.25, false, GetParam(), speed), "drag.json");
    ASSERT_TRUE(scene) << scene.error();
    scene->drag = 0.05;  // N s/m on 0.1 kg: k = 0.5 /s, a tenth of the speed lost in 0.2 s
    const Judged j = runAndJudge(registry, "mysim", *scene);
    expectClosedForm(j, false, GetParam() + ": with drag, " + std::to_string(degrees) + " deg");
  }
}

INSTANTIATE_TEST_SUITE_P(Friction, FrictionInEveryIntegrator,
                         ::testing::ValuesIn(mysim::integratorNames()),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::erase(name, '-');
                           return name;
                         });

// The cloth (144 nodes, springs at rest) moves as one rigid sheet: sticking at 30 degrees with
// mu 0.7, held by mu_s 0.8 at 35 degrees although mu_k 0.5 would slide, sliding at 35 with 0.5.
// Forward Euler is left out: it is unstable on undamped springs at any step (the catalogue).
// (Release only: 37 s under the sanitizers; the particle tests reach the same friction code.)
TEST(FrictionOfACloth, OnAnInclineItSticksOrSlidesAsOneRigidSheetInEveryStableIntegrator) {
  const EngineRegistry registry;
  for (const std::string& integrator : mysim::integratorNames()) {
    if (integrator == "euler") continue;
    for (auto [name, stuck] : {std::pair{"incline_cloth_sticks", true}, {"incline_cloth_held_by_static", true},
                               {"incline_cloth_slides", false}}) {
      mysim::Scene scene = test::contactScene(name);
      scene.integrator.name = integrator;
      expectClosedForm(runAndJudge(registry, "mysim", scene), stuck, integrator + " on " + name);
    }
  }
}

// At 1/60 s (the step users take) the families sold for large steps hold the same closed forms:
// backward Euler, local/global and VBD hold the cloth's nodes on the incline inside their solve
// with Coulomb on the holds' reactions (integrators/contact_holds.h). Sticking: no drift (measured:
// 0 m). Sliding: within h / t + 1 % (the first-order step's own error on the constant
// acceleration is h / t = 1.7 % at 1 s; measured: backward Euler and local/global 1.74 %, VBD
// 2.09 %, XPBD on its substeps 0.24 %).
TEST(FrictionAtLargeSteps, TheLargeStepFamiliesStickAndSlideAsTheClosedFormSaysAtOneSixtieth) {
  const EngineRegistry registry;
  constexpr double kStep = 1.0 / 60.0;
  for (const mysim::IntegratorInfo& info : mysim::integratorCatalog()) {
    if (info.family != mysim::IntegratorFamily::Implicit && !mysim::iterativeFamily(info.family)) continue;
    for (auto [name, stuck] : {std::pair{"incline_cloth_sticks", true}, {"incline_cloth_held_by_static", true},
                               {"incline_cloth_slides", false}}) {
      mysim::Scene scene = test::contactScene(name);
      scene.integrator.name = info.name;
      scene.dt = kStep;
      const Judged j = runAndJudge(registry, "mysim", scene);
      const std::string what = info.name + " on " + name + " at 1/60 s";
      if (stuck) {
        EXPECT_LT(j.error.error, kStuck) << what;
      } else {
        EXPECT_LT(j.error.error / j.error.exact, kStep / scene.duration + 0.01) << what;
      }
    }
  }
}

// What Bullet does with its one coefficient (kDF x the body's friction), measured on the shipped
// particle and cloth scenes at 1 ms: the deformable solver's contact is Coulomb's law (its error
// is mysim's symplectic-Euler h / t, to 1e-12); the implicit mode creeps 1.6e-5 to 2.1e-5 m while
// stuck (bound 1e-4: five times) and slides within 1 %; the classic solver removes the fraction
// mu of the tangential velocity at each contact solve, a velocity damping, not Coulomb's law:
// the particle that should slide 0.51 m before stopping stops within a centimetre.
TEST(Friction, BulletDeformableAndImplicitFollowCoulombAndTheClassicSolverDampsInstead) {
  const EngineRegistry registry;
  for (const char* engine : {"bullet-deformable", "bullet-implicit"}) {
    const double stuck_bound = std::string(engine) == "bullet-deformable" ? kStuck : 1e-4;
    for (const char* name : {"incline_particle_sticks", "incline_cloth_sticks"}) {
      const Judged j = runAndJudge(registry, engine, test::contactScene(name));
      EXPECT_LT(j.error.error, stuck_bound) << engine << " on " << name;
    }
    for (const char* name : {"incline_particle_slides", "incline_cloth_slides", "stopping_particle"}) {
      const Judged j = runAndJudge(registry, engine, test::contactScene(name));
      EXPECT_LT(j.error.error / j.error.exact, kSlideRelative) << engine << " on " << name;
    }
  }
  const Judged classic = runAndJudge(registry, "bullet-classic", test::contactScene("stopping_particle"));
  const double travelled = classic.error.exact - classic.error.error;  // it slid the same way
  EXPECT_LT(travelled, 0.02 * classic.error.exact) << "the classic solver's friction damps the slide";
}

// mysim and the example external engine (pysim, symplectic Euler) apply the protocol's friction
// rule operation by operation: the same trajectory to the last bit on a slide and a stop.
TEST(FrictionInput, TheExampleExternalEngineAppliesTheProtocolsFrictionToTheBit) {
  EngineRegistry registry;
  ASSERT_TRUE(registry.addEnginesFile(test::kRoot + "/examples/external/engines.json"));
  for (const char* name : {"incline_cloth_slides", "stopping_particle"}) {
    mysim::Scene scene = test::contactScene(name);
    scene.integrator.name = "symplectic-euler";
    const auto ours = registry.run("mysim", scene);
    const auto theirs = registry.run("pysim", scene);
    ASSERT_TRUE(ours && theirs) << name;
    ASSERT_EQ(ours->frames.size(), theirs->frames.size());
    EXPECT_EQ(ours->frames.back(), theirs->frames.back()) << name;
  }
}

std::string withFriction(const std::string& friction) {
  return R"({"system": {"type": "particles", "particles": [{"position": [0, 0.001, 0], "mass": 0.1}]},
    "colliders": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "friction": )" +
         friction + R"(}], "integrator": {"name": "rk4", "dt": 0.001, "duration": 0.1}})";
}

TEST(FrictionInput, EveryBadCoefficientIsRefusedNamingTheFileAndTheField) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {R"({"static": -0.1})", "colliders[0].friction.static"},
      {R"({"static": 0.3, "kinetic": 0.5})", "colliders[0].friction.kinetic"},
      {R"({"static": 0.3, "kinetic": -1})", "colliders[0].friction.kinetic"},
      {R"({"static": 101})", "colliders[0].friction.static"},
      {R"({"static": "nan"})", "colliders[0].friction.static"},
      {R"({"kinetic": 0.2})", "colliders[0].friction.static"},
      {R"({"static": 0.3, "dynamic": 0.2})", "colliders[0].friction.dynamic"},
      {"0.5", "colliders[0].friction"},
  };
  for (const auto& [friction, field] : bad) {
    auto scene = mysim::parseScene(withFriction(friction), "bad_friction.json");
    ASSERT_FALSE(scene) << friction;
    EXPECT_NE(scene.error().find("bad_friction.json: " + field), std::string::npos)
        << friction << " -> " << scene.error();
  }
  auto fine = mysim::parseScene(withFriction(R"({"static": 0.4})"), "fine.json");
  ASSERT_TRUE(fine) << fine.error();
  const mysim::Friction& f = mysim::colliderFriction(fine->colliders.front());
  EXPECT_EQ(f.kinetic, 0.4) << "kinetic defaults to static";
}

// An engine that cannot apply the scene's friction refuses it, naming the field, instead of
// running it frictionless: Bullet's one coefficient cannot hold mu_s > mu_k; an external engine
// must declare "friction": true.
TEST(FrictionInput, AnEngineThatCannotApplyTheFrictionRefusesTheScene) {
  EngineRegistry registry;
  ASSERT_TRUE(registry.addEnginesFile(test::kRoot + "/tests/data/declared_engines.json"));
  const mysim::Scene scene = test::contactScene("incline_cloth_held_by_static");
  for (const char* engine : {"bullet-deformable", "bullet-implicit", "bullet-classic", "pysim-static"}) {
    auto run = registry.run(engine, scene);
    ASSERT_FALSE(run) << engine << " ran a scene it cannot apply";
    EXPECT_EQ(run.error().kind, EngineError::Kind::Refused) << engine;
    EXPECT_NE(run.error().message.find("friction"), std::string::npos) << run.error().message;
  }
}

}  // namespace
}  // namespace springcheck
