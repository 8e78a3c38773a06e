#pragma once
// Test helpers for the engine-level tests: a registry with an engines file of the source tree
// added, and a shipped scene loaded through it.
#include <gtest/gtest.h>

#include <string>

#include "compare/engines/engine_registry.h"

namespace springcheck::test_support {

inline EngineRegistry registryWith(const std::string& engines_file) {
  EngineRegistry registry;
  auto added = registry.addEnginesFile(std::string(SPRINGCHECK_SOURCE_DIR) + "/" + engines_file);
  EXPECT_TRUE(added) << added.error();
  return registry;
}

inline mysim::Scene shippedScene(const EngineRegistry& registry, const std::string& name) {
  auto s = registry.loadScene(std::string(SPRINGCHECK_SOURCE_DIR) + "/scenes/" + name);
  EXPECT_TRUE(s) << s.error();
  return *s;
}

}  // namespace springcheck::test_support
