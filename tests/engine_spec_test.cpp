// One engine-spec grammar for every command: "mysim:INTEGRATOR:PARAM=VALUE".
// ctest-label: unit
#include <gtest/gtest.h>

#include "compare/engines/engine_registry.h"

namespace springcheck {
namespace {

// One engine-spec grammar for every command: "mysim:xpbd:substeps=3:iterations=2" (the sweeps'
// integrator text) sets the integrator's parameters wherever an engine is named (compare, suite,
// gate), and a parameter the integrator does not declare is refused naming it.
TEST(EngineSpec, AnIntegratorVariantSetsItsParametersInEveryCommand) {
  const EngineRegistry registry;
  auto scene = registry.loadScene(SPRINGCHECK_SOURCE_DIR "/scenes/matched/chain_hanging.json");
  ASSERT_TRUE(scene) << scene.error();
  scene->duration = 10 * scene->dt;
  auto run = registry.run("mysim:xpbd:substeps=3:iterations=2", *scene);
  ASSERT_TRUE(run) << run.error().message;
  EXPECT_EQ(run->integrator, "xpbd");
  EXPECT_EQ(run->counts.derivative_evaluations, 3 * 10);  // a substep each
  EXPECT_EQ(run->counts.linear_iterations, 3 * 2 * 10);   // passes in each substep
  auto bad = registry.run("mysim:xpbd:substep=3", *scene);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("no parameter 'substep'"), std::string::npos)
      << bad.error().message;
  EXPECT_EQ(registry.schemeOf("mysim:xpbd:substeps=3", "rk4"), "xpbd");
}

}  // namespace
}  // namespace springcheck
