// Contact at the steps the large-step families are sold for. The closing contact pass alone
// (moving a particle found inside a collider back to its surface after the step) puts about
// (h w)^2 times more energy into its springs than it takes out of its motion; at 1/60 s every
// implicit family blew up landing a cloth (cloth_on_box at 0.25 s, cloth_fold_on_ground at
// 0.28 s, by the energy-rise check, which allows a rise of a quarter of the energy scale). With
// the particles held on the collider inside the solve (integrators/contact_holds.h) the landing
// is an inelastic impact like any other: the total energy never rises by more than a thousandth of
// the energy scale, and friction keeps its closed form.
// ctest-label: physics
// The landings run three whole scenes in each family: 1 to 3 s a family in Release, 16 to 48 s
// under the sanitizers, where the holds run in every family in the thin wall's half second below
// (a box), FrictionAtLargeSteps (the ground, with friction) and SelfCollisionOpening:
// ctest-label ContactLandingAtOneSixtieth: physics,releaseonly
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "mysim/integrator.h"
#include "mysim/scene_file.h"
#include "test_support.h"

namespace mysim {
namespace {

// The families sold for steps past the explicit limit: every family of the catalogue but the
// explicit, symplectic and adaptive ones (the catalogue's rows, not names written here).
std::vector<std::string> largeStepIntegrators() {
  std::vector<std::string> names;
  for (const IntegratorInfo& info : integratorCatalog()) {
    if (info.family == IntegratorFamily::Implicit || iterativeFamily(info.family)) names.push_back(info.name);
  }
  return names;
}

// The most the total energy rises above its lowest earlier value, over the energy scale the
// health check uses (max of |E(0)| and the peak kinetic energy).
double largestEnergyRise(const RunRecord& run) {
  double lowest = run.energies.front().total(), rise = 0.0, peak_kinetic = 0.0;
  for (const EnergyTerms& e : run.energies) {
    lowest = std::min(lowest, e.total());
    rise = std::max(rise, e.total() - lowest);
    peak_kinetic = std::max(peak_kinetic, e.kinetic);
  }
  return rise / std::max(std::abs(run.energies.front().total()), peak_kinetic);
}

class ContactAtOneSixtieth : public ::testing::TestWithParam<std::string> {};
class ContactLandingAtOneSixtieth : public ::testing::TestWithParam<std::string> {};

// A free cloth dropped on a frictionless box on the ground, a hanging cloth landing on gripping
// ground and folding onto itself (self-collision), a pinned cloth draped on a sphere: whole at
// 1/60 s (h w = 2.8 on their springs), nothing inside a collider at the end, and the energy
// never up by 1e-3 of its scale (measured: at most 9.8e-5, backward Euler on the box; the three
// others below 3e-5; before the holds, the rises were over 0.25, where the run was stopped).
TEST_P(ContactLandingAtOneSixtieth, ALandingClothLosesEnergyAsAnyInelasticImpactDoes) {
  for (const char* file : {"scenes/matched/cloth_on_box.json", "scenes/contact/cloth_fold_on_ground.json",
                           "scenes/matched/cloth_on_sphere.json"}) {
    auto scene = loadScene(std::string(SPRINGCHECK_SOURCE_DIR "/") + file);
    ASSERT_TRUE(scene) << scene.error();
    scene->integrator.name = GetParam();
    scene->dt = 1.0 / 60.0;
    scene->sample_interval = scene->dt;  // every step
    const RunRecord run = testing::simulateScene(*scene);
    ASSERT_FALSE(run.blowup) << GetParam() << " on " << file << ": " << run.blowup->detail;
    EXPECT_LT(largestEnergyRise(run), 1e-3) << GetParam() << " on " << file;
    const ParticleRows& last = run.frames.back();
    for (const Collider& collider : scene->colliders) {
      for (Eigen::Index p = 0; p < last.rows(); ++p) {
        EXPECT_GE(signedDistance(collider, last.row(p).head<3>().transpose()), -1e-9) << GetParam() << " on " << file;
      }
    }
  }
}

// A free cloth falling 2 cm onto the edge of a 2 cm thick wall hangs over it (its shipped run:
// lowest node 0.13 m, highest at the wall's top, 0.6 m). At 1/60 s a step carried the middle
// column's nodes deeper into the wall than its half thickness, the nearest face was then a side,
// and backward Euler, local/global and VBD pushed them out there: the cloth slid off and fell
// 9 m in 3 s, a run reported whole and ok. A node now leaves the way it came in (box_collider.h).
// Half a second shows it: by then the old runs' highest node was 12 cm below the wall's top.
TEST_P(ContactAtOneSixtieth, AClothDroppedOnAThinWallHangsOverIt) {
  auto scene = loadScene(SPRINGCHECK_SOURCE_DIR "/scenes/contact/cloth_over_thin_wall.json");
  ASSERT_TRUE(scene) << scene.error();
  scene->integrator.name = GetParam();
  scene->dt = 1.0 / 60.0;
  scene->duration = 0.5;
  const RunRecord run = testing::simulateScene(*scene);
  ASSERT_FALSE(run.blowup) << GetParam() << ": " << run.blowup->detail;
  const auto heights = run.frames.back().col(1);
  EXPECT_NEAR(heights.maxCoeff(), 0.6, 0.01) << GetParam() << ": still on the wall's top";
  EXPECT_GT(heights.minCoeff(), 0.1) << GetParam() << ": its skirts hang, none fell";
}

INSTANTIATE_TEST_SUITE_P(LargeStepFamilies, ContactAtOneSixtieth, ::testing::ValuesIn(largeStepIntegrators()),
                         testing::IntegratorParamName());
INSTANTIATE_TEST_SUITE_P(LargeStepFamilies, ContactLandingAtOneSixtieth,
                         ::testing::ValuesIn(largeStepIntegrators()), testing::IntegratorParamName());

}  // namespace
}  // namespace mysim
