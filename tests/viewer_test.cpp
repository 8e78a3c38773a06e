// Every viewer key, through the same handler the window calls (no window needed).
// ctest-label: viewer
#include <gtest/gtest.h>

#include <algorithm>

#include "viewer/viewer_session.h"

namespace viewer {
namespace {

const std::string kRoot = SPRINGCHECK_SOURCE_DIR "/scenes/";

ViewerSession session(const std::string& first = kRoot + "matched/cloth_hanging.json") {
  return ViewerSession(
      springcheck::EngineRegistry(),
      {kRoot + "seed/circle.json", kRoot + "seed/pendulum.json", kRoot + "matched/chain_swing.json",
       kRoot + "matched/cloth_hanging.json", kRoot + "matched/cloth_on_sphere.json"},
      first, {"mysim", "bullet-deformable"}, "", 0.0);
}

double firstPosition(const ViewerSession& s) { return s.engines()[0].state.y[3 * 5 + 1]; }

// Real-time frames of 1/20 s (advance() takes at most 0.1 s a frame), with no wall-time budget.
void run(ViewerSession& s, double seconds) {
  for (int k = 0; k < std::lround(seconds * 20); ++k) s.advance(0.05, 1e9);
}

double meanZ(const EngineView& e) {
  const int n = static_cast<int>(e.state.y.size() / 6);
  double z = 0;
  for (int p = 0; p < n; ++p) z += e.state.y[3 * p + 2] / n;
  return z;
}

TEST(ViewerKeys, TCyclesScenesInOrderAndWraps) {
  ViewerSession s = session();
  EXPECT_EQ(s.config().scene_name, "cloth_hanging");
  ASSERT_TRUE(s.handleKey('t'));
  EXPECT_EQ(s.config().scene_name, "cloth_on_sphere");
  ASSERT_TRUE(s.handleKey('t'));
  EXPECT_EQ(s.config().scene_name, "circle");
  // Bullet runs the circle as its mechanical twin, beside mysim.
  EXPECT_TRUE(s.engines()[1].running()) << s.engines()[1].refused;
}

TEST(ViewerKeys, DTurnsWindOnAndOffInEveryEngine) {
  ViewerSession calm = session(), windy = session();
  EXPECT_FALSE(windy.model().wind);
  windy.handleKey('d');
  EXPECT_TRUE(windy.wind());
  ASSERT_TRUE(windy.model().wind);
  run(calm, 1.0);
  run(windy, 1.0);
  // Wind along +z pushes both engines' cloth towards +z, against the same cloth without it.
  for (std::size_t k = 0; k < windy.engines().size(); ++k) {
    ASSERT_TRUE(windy.engines()[k].running()) << windy.engines()[k].refused;
    EXPECT_GT(meanZ(windy.engines()[k]), meanZ(calm.engines()[k]) + 0.01)
        << windy.engines()[k].engine;
  }
  windy.handleKey('d');
  EXPECT_FALSE(windy.model().wind);
}

TEST(ViewerKeys, SSwingsThePinnedCorners) {
  ViewerSession s = session();
  s.handleKey('s');
  ASSERT_TRUE(s.model().pin_motion);
  run(s, 0.5);  // a quarter period of 0.5 Hz: the corners are 0.2 m along z
  EXPECT_NEAR(s.time(), 0.5, 1e-9);
  const EngineView& e = s.engines()[0];
  EXPECT_NEAR(e.state.y[2], 0.2 * std::sin(2 * M_PI * 0.5 * s.time()), 1e-9);
}

TEST(ViewerKeys, WSwitchesShadedClothAndSprings) {
  ViewerSession s = session();
  EXPECT_TRUE(s.shaded());
  s.handleKey('w');
  EXPECT_FALSE(s.shaded());
}

TEST(ViewerKeys, RResetsToTheStart) {
  ViewerSession s = session();
  const double start = firstPosition(s);
  run(s, 0.3);
  EXPECT_NE(firstPosition(s), start);
  s.handleKey('r');
  EXPECT_EQ(s.time(), 0.0);
  EXPECT_EQ(firstPosition(s), start);
}

// The integrator after `name` in the catalogue's order (wrapping), among those that take a
// first-order system when first_order_only.
std::string nextIntegrator(const std::string& name, bool first_order_only) {
  const auto& catalog = mysim::integratorCatalog();
  auto it = std::find_if(catalog.begin(), catalog.end(), [&](const auto& i) { return i.name == name; });
  do {
    if (++it == catalog.end()) it = catalog.begin();
  } while (first_order_only && it->needs_particles);
  return it->name;
}

TEST(ViewerKeys, ICyclesIntegratorsAndSkipsSecondOrderOnesForTheCircle) {
  ViewerSession s = session();
  EXPECT_EQ(s.integrator(), "rk4");
  s.handleKey('i');
  EXPECT_EQ(s.integrator(), nextIntegrator("rk4", false));
  ViewerSession circle = session(kRoot + "seed/circle.json");
  circle.handleKey('i');  // those that need particles are skipped
  EXPECT_EQ(circle.integrator(), nextIntegrator("rk4", true));
}

TEST(ViewerKeys, TheCircleNamesTheIntegratorThatRunsAndRefusesWindAndSwing) {
  ViewerSession s = session();
  s.handleKey('i');  // the one after rk4 chosen on the cloth (symplectic Euler)
  ASSERT_TRUE(mysim::findIntegrator(s.integrator())->needs_particles);
  const std::string chosen = s.integrator();
  s.handleKey('t');  // -> on to the next scenes until the circle
  while (s.config().scene_name != "circle") s.handleKey('t');
  EXPECT_EQ(s.integrator(), chosen);
  EXPECT_EQ(s.activeIntegrator(), "rk4");  // what the circle really steps with
  EXPECT_EQ(s.engines()[0].integrator, "rk4");
  EXPECT_FALSE(s.togglesApply());
  s.handleKey('d');
  EXPECT_FALSE(s.wind());
  EXPECT_NE(s.notice().find("wind does not apply"), std::string::npos);
  EXPECT_EQ(s.summary().find("wind"), std::string::npos);  // not shown where it cannot act
  s.handleKey('r');
  EXPECT_TRUE(s.notice().empty());
}

TEST(ViewerKeys, SpacePausesAndDotStepsOnce) {
  ViewerSession s = session();
  s.handleKey(' ');
  EXPECT_TRUE(s.paused());
  run(s, 0.5);
  EXPECT_EQ(s.time(), 0.0);
  s.handleKey('.');
  EXPECT_DOUBLE_EQ(s.time(), s.dt());
  s.handleKey(' ');
  run(s, 0.1);
  EXPECT_NEAR(s.time(), 0.1 + s.dt(), s.dt());
}

TEST(ViewerKeys, UnknownKeysDoNothing) {
  ViewerSession s = session();
  EXPECT_FALSE(s.handleKey('z'));
  EXPECT_EQ(s.config().scene_name, "cloth_hanging");
}

TEST(ViewerMetrics, EnginesStayCloseOnTheMatchedClothAndNothingEntersTheSphere) {
  ViewerSession s = session(kRoot + "matched/cloth_on_sphere.json");
  run(s, 1.0);
  ASSERT_TRUE(s.engineDistance());
  EXPECT_LT(*s.engineDistance(), 0.005);  // the compare gate holds these within millimetres
  ASSERT_TRUE(s.penetration());
  EXPECT_LT(*s.penetration(), 0.005);
}

}  // namespace
}  // namespace viewer
