// A run without a closed form says why, in words a table and the report can show: a blank cell
// cannot tell "does not apply" from "not computed" or "failed".
// ctest-label: unit
#include <gtest/gtest.h>

#include <string>

#include "compare/metrics/closed_form.h"
#include "mysim/scene_file.h"
#include "source_root.h"

namespace springcheck {
namespace {

mysim::Model shippedModel(const std::string& scene) {
  auto loaded = mysim::loadScene(test::kRoot + "/scenes/" + scene);
  EXPECT_TRUE(loaded) << loaded.error();
  return mysim::buildModel(*loaded);
}

// A record of two frames, both at the model's start (what the reasons below do not depend on).
mysim::RunRecord startFrames(const mysim::Model& model) {
  mysim::RunRecord run;
  mysim::ParticleRows rows = mysim::ParticleRows::Zero(model.particleCount(), 6);
  for (int p = 0; p < model.particleCount(); ++p) rows.row(p).head<3>() = mysim::at3(model.start_position, p).transpose();
  for (double t : {0.0, 1.0}) {
    run.times.push_back(t);
    run.frames.push_back(rows);
  }
  return run;
}

// The reason given for a model, or a note that it had a closed form after all.
std::string reasonFor(const mysim::Model& model, const mysim::RunRecord& run) {
  const ClosedFormResult result = closedFormError(model, run);
  return result ? "has one: " + result->quantity : result.error();
}

// Each kind of scene without a closed form is told apart by its reason.
TEST(ClosedFormReason, EachSceneWithoutAClosedFormSaysWhy) {
  const mysim::Model flex = shippedModel("material/cantilever_strip_flex.json");
  EXPECT_NE(reasonFor(flex, startFrames(flex)).find("flex springs"), std::string::npos);
  const mysim::Model swing = shippedModel("matched/chain_swing.json");
  EXPECT_NE(reasonFor(swing, startFrames(swing)).find("several links"), std::string::npos);
  const mysim::Model cloth = shippedModel("matched/cloth_hanging.json");
  EXPECT_NE(reasonFor(cloth, startFrames(cloth)).find("closed forms only for"),
            std::string::npos);
  mysim::Model windy = shippedModel("matched/chain_hanging.json");
  windy.wind = mysim::Wind{};
  EXPECT_NE(reasonFor(windy, startFrames(windy)).find("wind"), std::string::npos);
  mysim::Model damped_pendulum = shippedModel("seed/pendulum.json");
  damped_pendulum.drag = 0.1;
  EXPECT_NE(reasonFor(damped_pendulum, startFrames(damped_pendulum)).find("damped pendulum"),
            std::string::npos);
}

// A scene that has a closed form gets none from a run that blew up, and the reason gives the time.
TEST(ClosedFormReason, ARunThatBlewUpHasNoClosedFormAndSaysWhen) {
  const mysim::Model chain = shippedModel("matched/chain_hanging.json");
  mysim::RunRecord run = startFrames(chain);
  ASSERT_TRUE(closedFormError(chain, run).has_value());  // the scene has one
  run.blowup = mysim::BlowUp{0.25, 250, "energy"};
  const std::string why = reasonFor(chain, run);
  EXPECT_NE(why.find("blew up at t = 0.25"), std::string::npos) << why;
}

}  // namespace
}  // namespace springcheck
