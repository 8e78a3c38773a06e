#include "compare/studies/trade_grid.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "compare/io/atomic_file.h"
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

std::expected<std::string, std::string> writeTradeGrid(const TradeGrid& grid,
                                                       const std::string& work) {
  namespace fs = std::filesystem;
  auto write = [](const std::string& path, const std::string& text) {
    std::error_code ec;
    fs::create_directories(fs::path(path).parent_path(), ec);
    return writeFileAtomically(path, [&](std::ostream& f) { f << text; });
  };
  for (const TradeGridScene& s : grid.scenes) {
    if (auto ok = write(work + "/" + s.file, s.text); !ok) return std::unexpected(ok.error());
  }
  const std::string spec = work + "/" + grid.spec_file;
  if (auto ok = write(spec, grid.spec_text); !ok) return std::unexpected(ok.error());
  return spec;
}

std::expected<void, std::string> runTradeGrid(EngineRegistry& registry, const TradeGrid& grid,
                                              const std::string& work, const std::string& table,
                                              const SweepOptions& options) {
  const auto spec_path = writeTradeGrid(grid, work);
  if (!spec_path) return std::unexpected(spec_path.error());
  auto spec = loadSweepSpec(*spec_path, registry);
  if (!spec) return std::unexpected(spec.error());
  auto ran = runSweep(registry, *spec, table, options);
  if (!ran) return std::unexpected(ran.error());
  return {};
}

std::map<std::string, int> tradeResolutions(const std::vector<SweepRow>& rows,
                                            const std::string& name) {
  std::map<std::string, int> out;
  const std::string prefix = name + "_r";
  for (const SweepRow& row : rows) {
    const std::string s = std::filesystem::path(row.c.scene).stem().string();
    if (s.size() <= prefix.size() || s.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string digits = s.substr(prefix.size());
    if (!digits.empty() && digits.size() <= 6 &&
        digits.find_first_not_of("0123456789") == std::string::npos) {
      out[row.c.scene] = std::stoi(digits);
    }
  }
  return out;
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
