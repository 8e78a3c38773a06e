// The discrete two-pin catenary (closed_form.h) against its continuous limit, the elastic
// catenary (elastic_catenary.h): chains of 10 to 80 links of one cable converge at second order.
// ctest-label: unit,physics
#include "compare/metrics/elastic_catenary.h"

#include <gtest/gtest.h>

#include <cmath>

#include "compare/metrics/closed_form.h"
#include "mysim/scene.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

// A 1 m cable of 0.5 N/m and EA = 50 N between level pins 0.8 m apart, as a chain of n links.
double discreteSag(int n) {
  const double length = 1.0, weight = 0.5, axial = 50.0, g = 9.8, span = 0.8;
  const double l0 = length / n;
  const std::string text = R"({"system": {"type": "chain", "particles": )" + std::to_string(n + 1) +
                           R"(, "rest_length": )" + std::to_string(l0) + R"(, "spacing": )" +
                           std::to_string(span / n) + R"(, "particle_mass": )" +
                           std::to_string(weight * l0 / g) + R"(, "stiffness": )" +
                           std::to_string(axial / l0) + R"(, "pins": [0, )" + std::to_string(n) +
                           R"(]}, "forces": {"gravity": [0, -9.8, 0]},
                           "integrator": {"name": "rk4", "dt": 0.001, "duration": 1}})";
  auto scene = mysim::parseScene(text, "test");
  EXPECT_TRUE(scene) << scene.error();
  const mysim::Model model = mysim::buildModel(*scene);
  const auto nodes = twoPinCatenaryNodes(model);
  EXPECT_TRUE(nodes);
  double sag = 0.0;
  for (const mysim::Vec3& x : *nodes) sag = std::max(sag, -x.y());
  return sag;
}

// std::to_string rounds the chain's numbers to 6 digits: the cable they make differs from the
// continuous one by up to 1e-6 relative, below the 80-link chain's discretisation error.
TEST(ElasticCatenary, TheDiscreteChainConvergesToItAtSecondOrder) {
  const ElasticCatenary exact = levelElasticCatenary(0.8, 1.0, 0.5, 50.0);
  ASSERT_GT(exact.horizontal_tension, 0.0);
  double previous = std::abs(discreteSag(10) - exact.midspan_sag);
  for (int n : {20, 40, 80}) {
    const double error = std::abs(discreteSag(n) - exact.midspan_sag);
    EXPECT_NEAR(std::log2(previous / error), 2.0, 0.2) << n << " links: " << error << " m";
    previous = error;
  }
  EXPECT_LT(previous, 1e-4 * exact.midspan_sag);
}

// Inextensible and shallow: the sag approaches the parabola's w D^2 / (8 H), and with EA -> inf
// the reach is the rigid catenary's 2 H / w asinh(w L / (2 H)) = D.
TEST(ElasticCatenary, AStiffCableIsTheRigidCatenary) {
  const double w = 0.5, length = 1.0, span = 0.99;
  const ElasticCatenary c = levelElasticCatenary(span, length, w, 1e12);
  const double h = c.horizontal_tension;
  EXPECT_NEAR(2.0 * h / w * std::asinh(w * length / (2.0 * h)), span, 1e-9);
  EXPECT_NEAR(c.midspan_sag, h / w * (std::cosh(w * span / (2.0 * h)) - 1.0), 1e-9);
}

}  // namespace
}  // namespace springcheck
