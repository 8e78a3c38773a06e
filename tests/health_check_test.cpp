// The run's health checks never flag physically right motion: long falls, slides and swings,
// whose kinetic energy grows far past the start's energy scale, run through; a real blow-up is
// still stopped (BlowUp.* in simulation_test.cpp).
// ctest-label: physics
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mysim/scene_file.h"
#include "test_support.h"

namespace mysim {
namespace {

Scene sceneFrom(const std::string& text) {
  auto scene = parseScene(text, "health_check_test.json");
  EXPECT_TRUE(scene) << scene.error();
  return *scene;
}

// A single frictionless particle on a plane tilted by theta, released at rest on it: it slides
// s(t) = g sin(theta) t^2 / 2 (symplectic Euler's s_n = g sin(theta) h^2 n (n + 1) / 2, longer by
// the factor 1 + h / t). Its kinetic energy ends at m g s sin(theta), about 300 times what the
// start's energy scale (m g times a millimetre of extent) holds.
TEST(HealthCheck, AFrictionlessSlideDownAnInclineRunsThroughAtTheClosedFormDistance) {
  for (double degrees : {10.0, 30.0, 60.0}) {
    const double theta = degrees * std::numbers::pi / 180.0;
    const Scene scene = sceneFrom(R"({"system": {"type": "particles", "particles": [
        {"position": [0, 0, 0], "mass": 0.1}]},
      "forces": {"gravity": [0, -9.8, 0]},
      "colliders": [{"type": "plane", "point": [0, 0, 0], "margin": 0, "normal": [)" +
                                  std::to_string(std::sin(theta)) + ", " +
                                  std::to_string(std::cos(theta)) + R"(, 0]}],
      "integrator": {"name": "symplectic-euler", "dt": 0.001, "duration": 1.0}})");
    const RunRecord r = testing::simulateScene(scene);
    ASSERT_FALSE(r.blowup) << degrees << " degrees: " << r.blowup->check << ": "
                           << r.blowup->detail;
    const double t = r.times.back();
    const double slid = (r.frames.back().row(0).head<3>() - r.frames.front().row(0).head<3>()).norm();
    const double expected = 0.5 * 9.8 * std::sin(theta) * t * t;
    // The normal given to 6 digits tilts gravity's share by < 1e-6; the rest is h / t = 1e-3.
    EXPECT_NEAR(slid / expected, 1.0 + 0.001 / t, 1e-5) << degrees << " degrees";
  }
}

// A free fall of 10 s (490 m) and a 20 m pendulum chain swung down from level: kinetic energy
// thousands of times the start's, all of it released by gravity.
TEST(HealthCheck, ALongFreeFallAndAFallingChainAreNotRunaways) {
  const Scene fall = sceneFrom(R"({"system": {"type": "particles", "particles": [
      {"position": [0, 0, 0], "mass": 2.0}]}, "forces": {"gravity": [0, -9.8, 0]},
    "integrator": {"name": "rk4", "dt": 0.01, "duration": 10.0}})");
  const RunRecord r = testing::simulateScene(fall);
  ASSERT_FALSE(r.blowup) << r.blowup->check << ": " << r.blowup->detail;
  EXPECT_NEAR(r.frames.back()(0, 1), -0.5 * 9.8 * 100.0, 1e-9);  // RK4 is exact on a parabola
  const Scene swing = sceneFrom(R"({"system": {"type": "chain", "particles": 21, "rest_length": 1.0,
      "direction": [1, 0, 0], "stiffness": 5000, "particle_mass": 0.05},
    "forces": {"gravity": [0, -9.8, 0]},
    "integrator": {"name": "rk4", "dt": 0.0005, "duration": 4.0}})");
  const RunRecord s = testing::simulateScene(swing);
  EXPECT_FALSE(s.blowup) << s.blowup->check << ": " << s.blowup->detail;
}

}  // namespace
}  // namespace mysim
