// Backward Euler with its step matrix factored whole (the "cholesky" preconditioner,
// solvers/step_factor.h): the same steps as block Jacobi's CG to the solver's tolerance, in a few
// iterations where CG needs hundreds (a hinge strip, which Auto therefore factors), and with
// contacts held on a collider, whose filtered solves take the factor too.
// ctest-label: physics
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "mysim/scene_file.h"
#include "test_support.h"

namespace mysim {
namespace {

Scene shipped(const std::string& file, const nlohmann::json& integrator, int resolution = 0) {
  std::ifstream in(std::string(SPRINGCHECK_SOURCE_DIR) + "/scenes/" + file);
  nlohmann::json j = nlohmann::json::parse(in);
  if (resolution > 0) j["system"]["resolution"] = resolution;
  j["integrator"] = integrator;
  auto scene = parseScene(j.dump(), file);
  EXPECT_TRUE(scene) << scene.error();
  return *scene;
}

double largestDifference(const RunRecord& a, const RunRecord& b) {
  const ParticleRows& x = a.frames.back();
  const ParticleRows& y = b.frames.back();
  return (x.leftCols<3>() - y.leftCols<3>()).cwiseAbs().maxCoeff();  // positions, m
}

nlohmann::json backwardEuler(const char* preconditioner, double dt, double duration) {
  return {{"name", "backward-euler"}, {"dt", dt}, {"duration", duration},
          {"cg_preconditioner", preconditioner}};
}

// The 16-cell cantilever at a game's step: hinges make its matrix stiff (h^2 k / m near 1e5).
TEST(StepFactor, AHingeStripTakesTheStepsOfBlockJacobiInAFewIterationsAndAutoFactorsIt) {
  const double h = 1.0 / 60.0;
  const RunRecord block = testing::simulateScene(
      shipped("material/cantilever_strip.json", backwardEuler("block-jacobi", h, 0.5), 16));
  const RunRecord factored = testing::simulateScene(
      shipped("material/cantilever_strip.json", backwardEuler("cholesky", h, 0.5), 16));
  const RunRecord automatic = testing::simulateScene(
      shipped("material/cantilever_strip.json", backwardEuler("auto", h, 0.5), 16));
  ASSERT_EQ(block.status(), "ok");
  ASSERT_EQ(factored.status(), "ok");
  // Both solve every step to a relative residual of 1e-8: the 10 cm strip's nodes agree to a
  // micrometre (measured 1e-10 m).
  EXPECT_LT(largestDifference(block, factored), 1e-6);
  // Measured over its 30 steps: block Jacobi 4061 iterations, the factor 231.
  EXPECT_LT(10 * factored.counts.linear_iterations, block.counts.linear_iterations);
  EXPECT_EQ(automatic.frames.back(), factored.frames.back());
}

// The cloth draping over the sphere: rows held on the collider are filtered out of the solve,
// and the factor preconditions the filtered system.
TEST(StepFactor, ContactsHeldOnASphereGiveTheStepsOfBlockJacobi) {
  const double h = 1.0 / 60.0;
  const RunRecord block = testing::simulateScene(
      shipped("matched/cloth_on_sphere.json", backwardEuler("block-jacobi", h, 1.0)));
  const RunRecord factored = testing::simulateScene(
      shipped("matched/cloth_on_sphere.json", backwardEuler("cholesky", h, 1.0)));
  ASSERT_EQ(block.status(), "ok");
  ASSERT_EQ(factored.status(), "ok");
  // The cloth reaches the sphere within the first second (its corners are held 0.05 m above it).
  EXPECT_LT(largestDifference(block, factored), 1e-6);
  EXPECT_LT(factored.counts.linear_iterations, block.counts.linear_iterations);
}

}  // namespace
}  // namespace mysim
