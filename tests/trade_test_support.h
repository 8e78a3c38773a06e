#pragma once
// A trade study run in process for tests: the grid planned, run one case at a time in a folder
// of its own under the test's temporary folder, and answered (compare/studies/trade.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "compare/engines/engine_registry.h"
#include "compare/studies/trade.h"
#include "compare/studies/trade_grid.h"
#include "mysim/scene_file.h"

namespace springcheck::test_support {

// The trade of `scene` over `axes` (a grid run in a folder of its own, one case at a time), the
// settling judged against a relative bound `bound`.
inline TradeAnswer tradeOver(EngineRegistry& registry, const std::string& scene,
                             const TradeAxes& axes, const std::string& folder, double bound,
                             const std::string& quantity) {
  const std::string work = testing::TempDir() + "/" + folder;
  std::filesystem::remove_all(work);
  const auto grid = planTradeGrid(scene, "case", axes);
  EXPECT_TRUE(grid) << grid.error();
  const auto ran = runTradeGrid(registry, *grid, work, work + "/grid.csv", {.jobs = 1, .resume = false});
  EXPECT_TRUE(ran) << ran.error();
  const auto rows = readSweepTable(work + "/grid.csv");
  EXPECT_TRUE(rows) << rows.error();
  const auto loaded = registry.loadScene(scene);
  EXPECT_TRUE(loaded) << loaded.error();
  TradeInputs in{*rows, tradeResolutions(*rows, "case"),
                 closedFormReference(*loaded, mysim::buildModel(*loaded), quantity), "mysim",
                 "backward-euler", nullptr};
  return analyseTrade(in, {quantity, bound, true, Cost::WallTime});
}

// The same with the built-in engines only.
inline TradeAnswer tradeOver(const std::string& scene, const TradeAxes& axes,
                             const std::string& folder, double bound = 0.1,
                             const std::string& quantity = "tip_drop") {
  EngineRegistry registry;
  return tradeOver(registry, scene, axes, folder, bound, quantity);
}

}  // namespace springcheck::test_support
