// Round-off sensitivity (compare/studies/roundoff.h): a nudge of a few ulps grows by orders of
// magnitude on the undamped swinging chain and stays at its size on the damped hanging one; two
// engines' difference is told apart as identical, round-off, or real.
// ctest-label: physics,external
#include "compare/studies/roundoff.h"

#include <gtest/gtest.h>

#include <cmath>

namespace springcheck {
namespace {

mysim::Scene shipped(const EngineRegistry& registry, const std::string& name, double duration) {
  auto scene = registry.loadScene(SPRINGCHECK_SOURCE_DIR "/scenes/" + name);
  EXPECT_TRUE(scene) << scene.error();
  scene->duration = duration;
  return *scene;
}

TEST(Roundoff, TheNudgeMovesEveryFreeCoordinateByAFewUlpsOfTheSceneAndNoPin) {
  const EngineRegistry registry;
  const mysim::Model model = mysim::buildModel(shipped(registry, "matched/cloth_hanging.json", 1));
  const mysim::Model nudged = nudgedModel(model, 4);
  const double ulp = std::nextafter(1.0, 2.0) - 1.0;  // the cloth spans 1 m
  int moved = 0;
  for (int p = 0; p < model.particleCount(); ++p) {
    for (int c = 0; c < 3; ++c) {
      const double d = std::abs(nudged.start_position[3 * p + c] - model.start_position[3 * p + c]);
      if (model.pinned[p]) {
        EXPECT_EQ(d, 0.0);
        continue;
      }
      EXPECT_GE(d, 0.99 * ulp);
      EXPECT_LE(d, 4.01 * ulp);
      ++moved;
    }
  }
  EXPECT_GT(moved, 0);
  EXPECT_EQ(nudgedModel(model, 4).start_position, nudged.start_position);  // deterministic
}

TEST(Roundoff, AnUndampedSwingAmplifiesRoundOffAndADampedChainDoesNot) {
  const EngineRegistry registry;
  const mysim::Scene swing = shipped(registry, "matched/chain_swing.json", 4.0);
  auto chaotic = measureRoundoff(registry, "mysim:symplectic-euler", mysim::buildModel(swing),
                                 runConfig(swing), 4);
  ASSERT_TRUE(chaotic) << chaotic.error().message;
  // Measured: 4e-16 m grows to 8.4e-6 m (x 1.9e10) at an e-folding rate of 5.6 /s.
  EXPECT_GT(chaotic->amplification, 1e6);
  EXPECT_GT(chaotic->growth_rate, 1.0);
  const mysim::Scene hanging = shipped(registry, "matched/chain_hanging.json", 2.0);
  auto damped = measureRoundoff(registry, "mysim:rk4", mysim::buildModel(hanging),
                                runConfig(hanging), 4);
  ASSERT_TRUE(damped) << damped.error().message;
  EXPECT_LT(damped->amplification, 100.0);  // measured x 6.5
}

TEST(Roundoff, AnEnginePairIsIdenticalRoundOffOrReal) {
  EngineRegistry registry;
  ASSERT_TRUE(registry.addEnginesFile(SPRINGCHECK_SOURCE_DIR "/examples/external/engines.json"));
  ASSERT_TRUE(registry.addEnginesFile(SPRINGCHECK_SOURCE_DIR "/tests/data/declared_engines.json"));
  auto verdict = [&](const std::string& scene_name, double duration, const std::string& a,
                     const std::string& b) {
    const mysim::Scene s = shipped(registry, scene_name, duration);
    const mysim::Model model = mysim::buildModel(s);
    auto ra = measureRoundoff(registry, a, model, runConfig(s), 4);
    auto rb = measureRoundoff(registry, b, model, runConfig(s), 4);
    EXPECT_TRUE(ra && rb);
    std::vector<double> difference;
    for (std::size_t f = 0; f < ra->run.frames.size() && f < rb->run.frames.size(); ++f) {
      difference.push_back((ra->run.frames[f].leftCols<3>() - rb->run.frames[f].leftCols<3>())
                               .rowwise().norm().maxCoeff());
    }
    return classifyDifference(difference, *ra, *rb).verdict;
  };
  // The example engine follows mysim's rules to the bit.
  EXPECT_EQ(verdict("matched/cloth_hanging.json", 1.0, "mysim:symplectic-euler", "pysim"),
            "identical");
  // A float32 engine on the chaotic swing: 6e-8 m apart, within its precision and the drift.
  EXPECT_EQ(verdict("matched/chain_swing.json", 2.0, "mysim:symplectic-euler", "pysim-float32"),
            "round-off amplification");
  // Two methods: millimetres apart where each one's nudge stays below 1e-9 m.
  EXPECT_EQ(verdict("matched/cloth_hanging.json", 1.0, "mysim:rk4", "mysim:symplectic-euler"),
            "real");
}

}  // namespace
}  // namespace springcheck
