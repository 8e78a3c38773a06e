// The Cusick drape test's reading (compare/metrics/drape_test_metric.h) on shapes whose answer is
// known: the flat specimen, one gathered onto its support, and rims of a given number of folds.
// ctest-label: unit
// releaseonly: four readings of a 4096-pixel raster are 15 s under the sanitizers (0.5 s in
// Release); the reading, folds counted, runs there in DrapeTest.AFlatSpecimenHasDrapeCoefficient...
// ctest-label DrapeTestOfAHangingSpecimen: unit,releaseonly
#include "compare/metrics/drape_test_metric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mysim/scene.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

mysim::Model drapeDisc() {
  const std::string text = R"({"system": {"type": "cloth", "mesh": {"shape": "disc", "radius": 0.15},
    "resolution": 15, "material": {"density": 0.2, "stretch_stiffness": 1000,
    "bending": {"model": "hinge", "rigidity": 2e-5}}, "pins": {"within": 0.09}},
    "forces": {"gravity": [0, -9.8, 0]},
    "integrator": {"name": "backward-euler", "dt": 0.002, "duration": 1}})";
  auto scene = mysim::parseScene(text, "test");
  EXPECT_TRUE(scene) << scene.error();
  return mysim::buildModel(*scene);
}

mysim::ParticleRows framed(const mysim::Vector& x) {
  mysim::ParticleRows rows = mysim::ParticleRows::Zero(x.size() / 3, 6);
  for (int p = 0; p < rows.rows(); ++p) rows.row(p).head<3>() = x.segment<3>(3 * p).transpose();
  return rows;
}

// Flat, the shadow is the specimen: DC = 1 within the raster's resolution (4096 pixels across
// 0.3 m: one pixel row along the rim is 2.5e-4 of the area; bound 1e-3). The support's area is
// the ring at 9 cm's circle.
TEST(DrapeTest, AFlatSpecimenHasDrapeCoefficientOneAndNoFolds) {
  const mysim::Model disc = drapeDisc();
  const auto r = readDrapeTest(disc, framed(disc.start_position));
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->drape_coefficient, 1.0, 1e-3);
  EXPECT_NEAR(r->support_area, std::numbers::pi * 0.09 * 0.09, 1e-12);
  EXPECT_EQ(r->folds, 0);
}

// The free part hung straight down along the support's edge: the shadow is the support disc, DC
// = 0 (within the raster and the support's polygon, 3e-3), and a rim that waves with k lobes
// counts k folds.
TEST(DrapeTestOfAHangingSpecimen, HasDrapeCoefficientZeroAndWavesCountAsFolds) {
  const mysim::Model disc = drapeDisc();
  mysim::Vector hung = disc.start_position;
  for (int p = 0; p < disc.particleCount(); ++p) {
    const mysim::Vec3 x = disc.start_position.segment<3>(3 * p);
    const double r = std::hypot(x.x(), x.z());
    if (r <= 0.09 + 1e-12) continue;
    hung.segment<3>(3 * p) = mysim::Vec3(x.x() * 0.09 / r, -(r - 0.09), x.z() * 0.09 / r);
  }
  auto r = readDrapeTest(disc, framed(hung));
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->drape_coefficient, 0.0, 3e-3);
  for (int k : {5, 7, 9}) {
    mysim::Vector waved = disc.start_position;
    for (int p = 0; p < disc.particleCount(); ++p) {
      const mysim::Vec3 x = disc.start_position.segment<3>(3 * p);
      const double phi = std::atan2(-x.z(), x.x());
      waved.segment<3>(3 * p).x() *= 1.0 + 0.05 * std::cos(k * phi + 0.3);
      waved.segment<3>(3 * p).z() *= 1.0 + 0.05 * std::cos(k * phi + 0.3);
    }
    r = readDrapeTest(disc, framed(waved));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->folds, k);
  }
}

}  // namespace
}  // namespace springcheck
