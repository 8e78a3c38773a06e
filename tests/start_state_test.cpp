// A start inside a collider is refused before the run, naming the collider (it blew up with a NaN
// at the first step: a row of nodes pushed out through one face lands on itself); a start on the
// collider's surface or within its margin runs.
// ctest-label: validation
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "compare/engines/engine_registry.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

std::expected<mysim::RunRecord, EngineError> dropClothFrom(double height, double size) {
  nlohmann::json j = nlohmann::json::parse(
      std::ifstream(SPRINGCHECK_SOURCE_DIR "/scenes/matched/cloth_on_box.json"));
  j["system"]["width"] = j["system"]["height"] = size;
  j["system"]["origin"] = {-size / 2, height, size / 2};
  j["integrator"]["duration"] = 0.1;
  auto scene = mysim::parseScene(j.dump(), "cloth_in_box.json");
  if (!scene) return std::unexpected(EngineError{EngineError::Kind::Invalid, scene.error()});
  return EngineRegistry().run("mysim", *scene);
}

TEST(StartState, AClothStartingInsideABoxIsRefusedNamingTheCollider) {
  // The box spans y 0 .. 0.3 and x, z -0.2 .. 0.2; the ground is colliders[1].
  auto inside = dropClothFrom(0.2, 0.3);  // wholly inside
  ASSERT_FALSE(inside);
  EXPECT_NE(inside.error().message.find("cloth_in_box.json: colliders[0]: 144 free particle(s) "
                                        "start inside this box"),
            std::string::npos) << inside.error().message;
  auto across = dropClothFrom(0.2, 1.0);  // through its walls
  ASSERT_FALSE(across);
  EXPECT_NE(across.error().message.find("colliders[0]"), std::string::npos);
  auto below = dropClothFrom(-0.01, 0.3);  // under the ground
  ASSERT_FALSE(below);
  EXPECT_NE(below.error().message.find("colliders[1]"), std::string::npos);
  auto on_top = dropClothFrom(0.3005, 1.0);  // within the box's 1 mm margin: fine
  ASSERT_TRUE(on_top) << on_top.error().message;
  EXPECT_FALSE(on_top->blowup);
}

}  // namespace
}  // namespace springcheck
