// The two-pin catenary recognised from what the model is (a chain between two pins), not from
// what the scene called it.
// ctest-label: physics,bullet
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "compare/engines/engine_registry.h"
#include "compare/metrics/closed_form.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

// The two-pin catenary is what the model is, not what the scene called it: a particle list of
// equal masses joined in order by equal springs (listed in any order, either way round), its two
// ends pinned with slack between them, gets the catenary's closed-form error in every engine.
TEST(CatenaryFromTheModel, AParticleListChainBetweenTwoPinsGetsTheCatenarysError) {
  nlohmann::json particles = nlohmann::json::array(), springs = nlohmann::json::array();
  const int n = 13;
  for (int p = 0; p < n; ++p) {
    particles.push_back({{"position", {0.08 * p, 0.0, 0.0}}, {"mass", 0.05},
                         {"pinned", p == 0 || p == n - 1}});
  }
  for (int s : {5, 0, 11, 3, 8, 1, 10, 6, 2, 9, 4, 7}) {  // shuffled, every other one reversed
    springs.push_back({{"i", s % 2 ? s + 1 : s}, {"j", s % 2 ? s : s + 1}, {"rest_length", 0.1},
                       {"stiffness", 50.0}});
  }
  const nlohmann::json scene{
      {"system", {{"type", "particles"}, {"particles", particles}, {"springs", springs}}},
      {"forces", {{"gravity", {0, -9.8, 0}}, {"drag", 0.5}}},
      {"integrator", {{"name", "rk4"}, {"dt", 0.002}, {"duration", 10.0}}}};
  auto parsed = mysim::parseScene(scene.dump(), "catenary_list.json");
  ASSERT_TRUE(parsed) << parsed.error();
  const EngineRegistry registry;
  const mysim::Model model = mysim::buildModel(*parsed);
  // mysim's RK4 at rest after 10 s of drag: round-off (measured 1.2e-15 m); bullet-deformable
  // still creeps by a few 1e-9 m (measured 9.6e-9 m); 1e-6 m is the bound for both.
  for (const char* engine : {"mysim", "bullet-deformable"}) {
    auto run = registry.run(engine, model, runConfig(*parsed));
    ASSERT_TRUE(run) << run.error().message;
    const auto error = closedFormError(model, *run);
    ASSERT_TRUE(error) << engine << ": no closed form recognised";
    EXPECT_EQ(error->quantity, "two-pin catenary at rest");
    EXPECT_LT(error->error, 1e-6) << engine;
  }
}

}  // namespace
}  // namespace springcheck
