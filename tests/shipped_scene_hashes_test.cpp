// Same scenes, same bits: every shipped scene (scenes/seed, scenes/matched), run whole by every
// engine and with every mysim integrator, ends on the final_state_hash stored in
// tests/data/shipped_scene_hashes.json (taken before the code was restructured), or is refused
// where it was refused then. A redesign must not move a single bit; an engine or integrator with
// no stored hash fails, naming the hash to store. The whole runs are slow under the sanitizers
// (labelled slow: the Release pass runs them); the sanitizer pass runs every scene's opening
// steps in every engine instead, which reaches the same code.
// ctest-label: physics,bullet
// ctest-label ShippedScene: physics,bullet,slow
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "compare/engines/engine_registry.h"
#include "compare/io/scene_files.h"
#include "mysim/state_hash.h"

namespace springcheck {
namespace {

// Every engine spec a scene can be run with: each registered engine, and mysim once per
// integrator of the catalogue ("mysim:rk4", ...).
std::vector<std::string> everyEngineSpec(const EngineRegistry& registry) {
  std::vector<std::string> specs;
  for (const Engine& engine : registry.engines()) {
    if (!engine.takes_integrator) {
      specs.push_back(engine.name);
      continue;
    }
    for (const mysim::IntegratorInfo& info : mysim::integratorCatalog()) {
      specs.push_back(engine.name + ":" + info.name);
    }
  }
  return specs;
}

std::vector<std::string> shippedScenes() {
  std::vector<std::string> files;
  for (const char* dir : {"scenes/seed", "scenes/matched"}) {
    const auto found = sceneFiles(SPRINGCHECK_SOURCE_DIR "/" + std::string(dir));
    for (const std::string& f : found.value()) {
      files.push_back(f.substr(std::string(SPRINGCHECK_SOURCE_DIR "/").size()));
    }
  }
  return files;
}

class ShippedScene : public ::testing::TestWithParam<std::string> {};
class ShippedSceneOpening : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedScene, EveryEngineEndsOnTheStoredFinalStateHash) {
  std::ifstream in(SPRINGCHECK_SOURCE_DIR "/tests/data/shipped_scene_hashes.json");
  const nlohmann::json stored = nlohmann::json::parse(in)["scenes"];
  const EngineRegistry registry;
  const std::string file = GetParam();
  auto scene = registry.loadScene(SPRINGCHECK_SOURCE_DIR "/" + file);
  ASSERT_TRUE(scene) << scene.error();
  ASSERT_TRUE(stored.contains(file)) << file << ": no stored hashes";
  for (const std::string& spec : everyEngineSpec(registry)) {
    auto record = registry.run(spec, *scene);
    std::string measured;
    if (record) {
      ASSERT_FALSE(record->frames.empty()) << file << " " << spec;
      measured = mysim::hashRows(record->frames.back());
    } else {
      ASSERT_EQ(record.error().kind, EngineError::Kind::Refused) << record.error().message;
      measured = "refused";
    }
    EXPECT_EQ(measured, stored[file].value(spec, "(none stored)"))
        << file << " " << spec << ": if this change of result is on purpose, store \"" << spec
        << "\": \"" << measured << "\"";
  }
}

// The first steps of every shipped scene in every engine: refused exactly where the whole run is
// (a refusal is about the model, never the duration), else frames that are all finite and the
// steps asked for, unless a health check stopped the run and said when.
TEST_P(ShippedSceneOpening, EveryEngineStepsFinitelyOrIsRefusedAsInTheWholeRun) {
  constexpr int kOpeningSteps = 10;  // enough to reach every force, contact and solver path
  std::ifstream in(SPRINGCHECK_SOURCE_DIR "/tests/data/shipped_scene_hashes.json");
  const nlohmann::json stored = nlohmann::json::parse(in)["scenes"];
  const EngineRegistry registry;
  const std::string file = GetParam();
  auto scene = registry.loadScene(SPRINGCHECK_SOURCE_DIR "/" + file);
  ASSERT_TRUE(scene) << scene.error();
  scene->duration = kOpeningSteps * scene->dt;
  scene->sample_interval = scene->dt;
  for (const std::string& spec : everyEngineSpec(registry)) {
    const bool refused_whole = stored[file].value(spec, "") == "refused";
    auto record = registry.run(spec, *scene);
    if (!record) {
      EXPECT_EQ(record.error().kind, EngineError::Kind::Refused) << record.error().message;
      EXPECT_TRUE(refused_whole) << file << " " << spec << ": refused, the whole run is not";
      continue;
    }
    EXPECT_FALSE(refused_whole) << file << " " << spec << ": runs, the whole run is refused";
    ASSERT_FALSE(record->frames.empty()) << file << " " << spec;
    for (const mysim::ParticleRows& frame : record->frames) {
      ASSERT_TRUE(frame.allFinite()) << file << " " << spec;
    }
    if (!record->blowup) EXPECT_EQ(record->steps, kOpeningSteps) << file << " " << spec;
  }
}

std::string sceneName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param.substr(std::string("scenes/").size());
  name = name.substr(0, name.size() - std::string(".json").size());
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(SameBits, ShippedScene, ::testing::ValuesIn(shippedScenes()), sceneName);
INSTANTIATE_TEST_SUITE_P(Opening, ShippedSceneOpening, ::testing::ValuesIn(shippedScenes()),
                         sceneName);

}  // namespace
}  // namespace springcheck
