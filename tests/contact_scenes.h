#pragma once
// A shipped contact scene (scenes/contact/NAME.json), for the friction, self-collision and
// capstan tests.
#include <gtest/gtest.h>

#include <string>

#include "mysim/scene_file.h"
#include "source_root.h"

namespace springcheck::test {

inline mysim::Scene contactScene(const std::string& name) {
  auto scene = mysim::loadScene(kRoot + "/scenes/contact/" + name + ".json");
  EXPECT_TRUE(scene) << scene.error();
  return *scene;
}

}  // namespace springcheck::test
