// Inputs whose derived numbers double precision cannot step (masses, stiffnesses, sizes, steps
// out of scale, or a step that swamps the stiffest spring) are refused before a run, naming the
// scene field they came from: never a run that says "ok" and does nothing.
// ctest-label: validation
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "compare/engines/engine_registry.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

// The shipped cantilever strip at 4 cells with one field set to a value.
std::expected<mysim::RunRecord, EngineError> runStrip(const std::string& pointer, double value) {
  nlohmann::json j = nlohmann::json::parse(
      std::ifstream(SPRINGCHECK_SOURCE_DIR "/scenes/material/cantilever_strip.json"));
  j["system"]["resolution"] = 4;
  j["integrator"]["duration"] = 0.02;
  j[nlohmann::json::json_pointer(pointer)] = value;
  auto scene = mysim::parseScene(j.dump(), "strip.json");
  if (!scene) return std::unexpected(EngineError{EngineError::Kind::Invalid, scene.error()});
  return EngineRegistry().run("mysim", *scene);
}

TEST(ModelScales, EveryInputOutOfDoublesReachIsRefusedNamingItsField) {
  struct Case {
    std::string pointer;
    double value;
    std::string field;
  };
  for (const Case& c : std::vector<Case>{
           {"/system/material/density", 1e300, "system.material.density"},
           {"/system/material/density", 1e-300, "system.material.density"},
           {"/system/material/stretch_stiffness", 1e300, "system.material.stretch_stiffness"},
           {"/system/material/shear_stiffness", 1e-300, "system.material.shear_stiffness"},
           {"/system/material/bending/rigidity", 1e-300, "system.material.bending.rigidity"},
           {"/system/material/bending/rigidity", 1e290, "system.material.bending.rigidity"},
           {"/system/width", 1e60, "system"},
           {"/system/width", 1e-60, ""},  // a strip too small: its masses or springs say which
           {"/forces/gravity/1", -1e60, "forces.gravity"},
       }) {
    auto run = runStrip(c.pointer, c.value);
    ASSERT_FALSE(run) << c.pointer << " = " << c.value << " ran";
    EXPECT_NE(run.error().message.find("strip.json: " + c.field), std::string::npos)
        << c.pointer << " = " << c.value << ": " << run.error().message;
  }
  // Stiff membrane, long step: h w = 2e8, past what a step can hold.
  nlohmann::json j = nlohmann::json::parse(
      std::ifstream(SPRINGCHECK_SOURCE_DIR "/scenes/material/cantilever_strip.json"));
  j["system"]["material"]["stretch_stiffness"] = 1e20;
  auto stiff = mysim::parseScene(j.dump(), "strip.json");
  ASSERT_TRUE(stiff) << stiff.error();
  auto run = EngineRegistry().run("mysim", *stiff);
  ASSERT_FALSE(run);
  EXPECT_NE(run.error().message.find("strip.json: integrator.dt: "), std::string::npos)
      << run.error().message;
  // The shipped strip itself runs.
  EXPECT_TRUE(runStrip("/system/material/density", 0.2));
}

}  // namespace
}  // namespace springcheck
