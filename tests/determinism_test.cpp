// Same input, same output, at any thread count (in the manner of Box2D's determinism test): a
// cloth above the parallel threshold (24 x 24 = 576 > 512 particles), with every force term,
// runs 40 steps under every integrator at 1, 2 and 3 threads; the final states' hashes must be
// equal, and equal to the hash stored for this build type (tests/data/determinism_hashes.json),
// so a change that moves a single bit of any integrator's result shows here.
// ctest-label: unit
#include <gtest/gtest.h>
#include <omp.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "mysim/scene_file.h"
#include "mysim/state_hash.h"
#include "test_support.h"

namespace mysim {
namespace {

std::string finalHash(const std::string& integrator, int threads) {
  auto scene = parseScene(R"({
    "system": {"type": "cloth", "rows": 24, "cols": 24, "width": 1, "height": 1,
               "particle_mass": 0.001, "structural": {"stiffness": 60, "damping": 0.01},
               "shear": {"stiffness": 30, "damping": 0.005}, "flex": {"stiffness": 6},
               "pins": "top_corners"},
    "forces": {"gravity": [0, -9.8, 0], "drag": 0.002,
               "wind": {"strength": 0.002, "gust": 0.5, "coverage": 0.5, "seed": 7}},
    "integrator": {"dt": 0.0005, "duration": 0.02, "cg_tolerance": 1e-10}})",
                          "determinism.json");
  EXPECT_TRUE(scene) << scene.error();
  scene->integrator.name = integrator;
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  const RunRecord r = testing::simulateScene(*scene);
  omp_set_num_threads(before);
  EXPECT_FALSE(r.blowup) << integrator;
  return hashRows(r.frames.back());
}

TEST(Determinism, EveryIntegratorGivesTheStoredHashAtOneTwoAndThreeThreads) {
  std::ifstream in(SPRINGCHECK_SOURCE_DIR "/tests/data/determinism_hashes.json");
  const nlohmann::json stored = nlohmann::json::parse(in);
  const std::string build = SPRINGCHECK_BUILD_TYPE;
  nlohmann::json measured;
  for (const IntegratorInfo& info : integratorCatalog()) {
    const std::string one = finalHash(info.name, 1);
    EXPECT_EQ(finalHash(info.name, 2), one) << info.name << ": 2 threads differ from 1";
    EXPECT_EQ(finalHash(info.name, 3), one) << info.name << ": 3 threads differ from 1";
    measured[info.name] = one;
  }
  ASSERT_TRUE(stored.contains(build))
      << "no stored hashes for build type '" << build << "'; measured: " << measured.dump();
  for (const IntegratorInfo& info : integratorCatalog()) {
    EXPECT_EQ(measured[info.name], stored[build].value(info.name, ""))
        << info.name << " changed its result; if on purpose, store: " << measured.dump();
  }
}

}  // namespace
}  // namespace mysim
