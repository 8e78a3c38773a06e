#include "compare/studies/trade_grid.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "mysim/json_input.h"

namespace springcheck {
namespace {

using nlohmann::json;

std::expected<json, std::string> materialScene(const std::string& path) {
  auto root = mysim::readJsonFile(path, "scene file");
  if (!root) return std::unexpected(root.error());
  if (!root->is_object() || !root->contains("system") || !(*root)["system"].is_object() ||
      !(*root)["system"].contains("material")) {
    return std::unexpected(path + ": system.material: expected a material scene (docs/materials.md): "
                           "the resolution can vary only where the model is derived from a material");
  }
  return root;
}

}  // namespace

std::expected<std::string, std::string> sceneTextAtResolution(const std::string& path,
                                                              int resolution,
                                                              const std::string& name) {
  auto root = materialScene(path);
  if (!root) return std::unexpected(root.error());
  (*root)["system"]["resolution"] = resolution;
  if (!name.empty()) (*root)["name"] = name;
  return root->dump(1);
}

std::expected<int, std::string> sceneResolution(const std::string& path) {
  auto root = materialScene(path);
  if (!root) return std::unexpected(root.error());
  const json& r = (*root)["system"]["resolution"];
  if (!r.is_number_integer()) {
    return std::unexpected(path + ": system.resolution: expected an integer number of cells");
  }
  return r.get<int>();
}

std::expected<TradeGrid, std::string> planTradeGrid(const std::string& scene_path,
                                                    const std::string& scene_name,
                                                    const TradeAxes& axes) {
  TradeGrid grid;
  json scenes = json::array();
  for (int n : axes.resolutions) {
    TradeGridScene s;
    s.resolution = n;
    s.name = scene_name + "_r" + std::to_string(n);
    s.file = "scenes/" + scene_name + "_r" + std::to_string(n) + ".json";
    auto text = sceneTextAtResolution(scene_path, n, s.name);
    if (!text) return std::unexpected(text.error());
    s.text = *text;
    scenes.push_back(s.file);
    grid.scenes.push_back(std::move(s));
  }
  const double largest = *std::max_element(axes.dts.begin(), axes.dts.end());
  json spec = {{"name", scene_name + "_trade"},
               {"scenes", scenes},
               {"engines", axes.engines},
               {"dt", axes.dts},
               {"sample_interval", largest},
               // No reference runs: the trade holds each run's settled quantity against the
               // physical reference itself; the closed form's error comes free where there is one.
               {"reference", "closed_form"}};
  if (!axes.integrators.empty()) spec["integrators"] = axes.integrators;
  grid.spec_text = spec.dump(1);
  return grid;
}

TradeAxes defaultTradeAxes(int resolution, double dt, const std::string& scene_integrator) {
  TradeAxes axes;
  for (int n : {resolution / 4, resolution / 2, resolution, 2 * resolution}) {
    n = std::max(1, n);
    if (std::find(axes.resolutions.begin(), axes.resolutions.end(), n) == axes.resolutions.end()) {
      axes.resolutions.push_back(n);
    }
  }
  axes.engines = {"mysim", "bullet-implicit", "bullet-deformable"};
  axes.integrators = {"backward-euler", "xpbd", "xpbd:substeps=4", "local-global",
                      "local-global:iterations=40", "vbd", "vbd:iterations=40"};
  if (std::find(axes.integrators.begin(), axes.integrators.end(), scene_integrator) ==
      axes.integrators.end()) {
    axes.integrators.insert(axes.integrators.begin(), scene_integrator);
  }
  axes.dts = {8 * dt, 2 * dt, dt / 2};
  return axes;
}

}  // namespace springcheck
