#pragma once
// The joint grid of a trade study (docs/trade.md): the material scene written out at each
// resolution, and the sweep spec that crosses them with engines, integrators and steps. The
// sweep machinery runs it (sweep.h: parallel, resumable, sharded, on Slurm too).
#include <expected>
#include <map>
#include <string>
#include <vector>

#include "compare/studies/sweep.h"

namespace springcheck {

struct TradeAxes {
  std::vector<int> resolutions;          // increasing, distinct
  std::vector<std::string> engines;      // registry engines; "mysim" is crossed with integrators
  std::vector<std::string> integrators;  // mysim's, NAME[:PARAMETER=VALUE...]
  std::vector<double> dts;               // s; each divides the largest (frames line up)
};

struct TradeGridScene {
  std::string file;  // relative to the grid's folder
  std::string name;  // the scene's name in the table: "NAME_r16"
  int resolution = 0;
  std::string text;  // the scene file
};

struct TradeGrid {
  std::vector<TradeGridScene> scenes;
  std::string spec_file = "trade_sweep.json";
  std::string spec_text;
};

// The scene file at `path` (a material scene: system.material) with system.resolution set and,
// when `name` is not empty, its name replaced. An error names the file and the field.
[[nodiscard]] std::expected<std::string, std::string> sceneTextAtResolution(
    const std::string& path, int resolution, const std::string& name = "");
// The resolution the scene file asks for (system.resolution).
[[nodiscard]] std::expected<int, std::string> sceneResolution(const std::string& path);

[[nodiscard]] std::expected<TradeGrid, std::string> planTradeGrid(const std::string& scene_path,
                                                                  const std::string& scene_name,
                                                                  const TradeAxes& axes);

// Writes the grid's scenes and spec into the folder `work` (the spec's path returned), ready for
// `springcheck sweep` or Slurm (examples/slurm/submit.sh).
[[nodiscard]] std::expected<std::string, std::string> writeTradeGrid(const TradeGrid& grid,
                                                                     const std::string& work);
// Writes the grid and runs its (remaining) cases into `table` (sweep.h's options: jobs, timing,
// shard, resume).
[[nodiscard]] std::expected<void, std::string> runTradeGrid(EngineRegistry& registry,
                                                            const TradeGrid& grid,
                                                            const std::string& work,
                                                            const std::string& table,
                                                            const SweepOptions& options);

// Each scene of a grid table that is a resolution of the scene named `name` (the grid's file
// NAME_r16.json; the table's scene column holds its path) -> its resolution.
std::map<std::string, int> tradeResolutions(const std::vector<SweepRow>& rows,
                                            const std::string& name);

// Default axes for a scene whose own resolution is `resolution` and step `dt`: resolutions
// r/4, r/2, r, 2r (at least 1; the limit needs three, the orders' agreement four); steps 8, 2
// and 1/2 times dt (8 dt is 1/62 s at the shipped 2 ms: a game's frame); the mysim integrators
// of the implicit, position-based, local-global and block-descent families at their defaults and
// at four times their passes (the grid's converged solver, for the budget); Bullet's deformable
// world both ways.
TradeAxes defaultTradeAxes(int resolution, double dt, const std::string& scene_integrator);

}  // namespace springcheck
