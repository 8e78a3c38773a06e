#include "compare/studies/tolerances.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "compare/io/text_format.h"
#include "compare/metrics/run_metrics.h"
#include "compare/studies/physical_reference.h"
#include "compare/studies/trade_grid.h"
#include "mysim/json_input.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;
using mysim::FieldError;
using mysim::FieldReader;

constexpr const char* kToleranceSchema = "docs/compare.md";

// A path relative to scene_root, or a shipped scene by name ("chain_hanging": no folder, no
// .json), found wherever springcheck is installed.
std::string scenePath(FieldReader& r, const fs::path& root, const EngineRegistry& registry) {
  const std::string given = r.text("scene");
  const bool by_name =
      !given.empty() && given.find('/') == std::string::npos && !given.ends_with(".json");
  if (!by_name) return (root / given).lexically_normal().string();
  auto shipped = registry.shippedScene(given);
  if (!shipped) throw FieldError{r.field("scene"), shipped.error()};
  return *shipped;
}

mysim::Scene loadVariant(FieldReader& r, const ToleranceCheck& c, const EngineRegistry& registry) {
  if (auto file = mysim::readJsonFile(c.scene, "scene file"); !file) {
    throw FieldError{r.field("scene"), "unknown scene: " + file.error()};
  }
  auto root = sceneVariantJson(c);
  if (!root) throw FieldError{r.field("resolution"), "no variant at a resolution: " + root.error()};
  auto scene = mysim::parseScene(root->dump(), c.scene, registry.sceneSections());
  if (!scene) {
    throw FieldError{r.field(c.resolution ? "resolution" : "dt"),
                     "the scene's variant does not load: " + scene.error()};
  }
  return std::move(*scene);
}

void readScene(FieldReader& r, ToleranceCheck& c, const fs::path& root,
               const EngineRegistry& registry, std::map<std::string, mysim::Scene>& scenes) {
  c.scene = scenePath(r, root, registry);
  if (r.has("resolution")) c.resolution = static_cast<int>(r.integer("resolution", 1, 100000));
  if (r.has("dt")) c.dt = r.positive("dt");
  if (scenes.count(c.sceneKey())) return;  // each scene (and variant) read once
  if (c.isVariant()) {
    scenes.emplace(c.sceneKey(), loadVariant(r, c, registry));
    return;
  }
  auto scene = registry.loadScene(c.scene);
  if (!scene) throw FieldError{r.field("scene"), "unknown scene: " + scene.error()};
  scenes.emplace(c.sceneKey(), std::move(*scene));
}

void readMetric(FieldReader& r, ToleranceCheck& c, const EngineRegistry& registry) {
  for (const std::string& e : r.textList("engines")) {
    if (auto known = registry.check(e); !known) throw FieldError{r.field("engines"), known.error()};
    c.engines.push_back(e);
  }
  c.metric = r.text("metric");
  const MetricInfo* info = findMetric(c.metric);
  if (!info) {
    std::string names;
    for (const MetricInfo& m : metricCatalog()) names += (names.empty() ? "" : ", ") + m.name;
    throw FieldError{r.field("metric"), "unknown metric '" + mysim::clip(c.metric, 40) +
                                            "'; expected one of " + names};
  }
  if (c.engines.size() != (info->pair ? 2u : 1u)) {
    throw FieldError{r.field("engines"), "metric '" + c.metric + "' takes " +
                                             (info->pair ? "two engines" : "one engine")};
  }
}

// The error against the physical reference: of a settled quantity the scene has a closed form
// for (a Richardson limit would need a refinement the gate does not run).
void readPhysicalError(FieldReader& r, ToleranceCheck& c, const mysim::Scene& scene) {
  c.physical_error = r.text("physical_error");
  if (c.physical_error != "absolute" && c.physical_error != "relative") {
    mysim::failField(r.field("physical_error"), "\"absolute\" or \"relative\"",
                     r.raw("physical_error"));
  }
  const auto reference = closedFormReference(scene, mysim::buildModel(scene), c.metric);
  if (!reference || !reference->value) {
    throw FieldError{r.field("physical_error"),
                     "the scene has no closed form for '" + c.metric +
                         "' (closed forms: tip_drop, chord_angle, bending_length of a level "
                         "clamped strip; sag_lowest of a level cable; docs/trade.md)"};
  }
  if (c.physical_error == "relative" && *reference->value == 0.0) {
    throw FieldError{r.field("physical_error"), "the reference is 0: no relative error"};
  }
  c.reference = *reference->value;
}

ToleranceCheck readCheck(FieldReader& r, const fs::path& root, const EngineRegistry& registry,
                         std::map<std::string, mysim::Scene>& scenes) {
  ToleranceCheck c;
  readScene(r, c, root, registry, scenes);
  readMetric(r, c, registry);
  if (r.has("physical_error")) readPhysicalError(r, c, scenes.at(c.sceneKey()));
  c.bound = r.number("bound");
  if (c.bound < 0) mysim::failField(r.field("bound"), "a finite number >= 0", r.raw("bound"));
  c.why = r.text("why");
  if (c.why.empty()) {
    throw FieldError{r.field("why"), "expected the reason for this bound (a non-empty string)"};
  }
  if (r.has("known_bias")) {
    c.known_bias = r.text("known_bias");
    if (c.known_bias.empty()) {
      throw FieldError{r.field("known_bias"), "expected the bias this bound allows, in words "
                                              "(a non-empty string), or no field"};
    }
  }
  r.refuseUnknown(kToleranceSchema);
  return c;
}

std::expected<Tolerances, std::string> readTolerances(const nlohmann::json& root,
                                                      const std::string& source,
                                                      const std::string& base_dir,
                                                      EngineRegistry& registry) {
  return mysim::readFields<Tolerances>(source, [&] {
    FieldReader top(root, "");
    Tolerances t{source, {}, {}, ""};
    const fs::path scene_root = fs::path(base_dir) / top.text("scene_root", "");
    if (top.has("engines_file")) {
      t.engines_file = (fs::path(base_dir) / top.text("engines_file")).lexically_normal().string();
      const auto& read = registry.enginesFiles();
      if (std::find(read.begin(), read.end(), t.engines_file) == read.end()) {
        if (auto added = registry.addEnginesFile(t.engines_file); !added) {
          throw FieldError{"engines_file", added.error()};
        }
      }
    }
    top.objects("checks", [&](FieldReader& check, std::size_t) {
      t.checks.push_back(readCheck(check, scene_root, registry, t.scenes));
    });
    top.refuseUnknown(kToleranceSchema);
    return t;
  });
}

}  // namespace

std::expected<nlohmann::json, std::string> sceneVariantJson(const ToleranceCheck& check) {
  std::expected<nlohmann::json, std::string> root;
  if (check.resolution) {  // GCC 12's <expected> has no and_then
    auto text = sceneTextAtResolution(check.scene, *check.resolution);
    if (!text) return std::unexpected(text.error());
    root = mysim::parseJson(*text, check.scene);
  } else {
    root = mysim::readJsonFile(check.scene, "scene file");
  }
  if (!root) return std::unexpected(root.error());
  if (check.dt) (*root)["integrator"]["dt"] = *check.dt;
  return root;
}

std::string ToleranceCheck::sceneKey() const {
  if (!isVariant()) return scene;
  return scene + (resolution ? "@r" + std::to_string(*resolution) : "") +
         (dt ? "@dt" + formatNumber(*dt, 17) : "");
}

std::string ToleranceCheck::variantLabel() const {
  std::string label;
  if (resolution) label += " at resolution " + std::to_string(*resolution);
  if (dt) label += std::string(resolution ? "," : "") + " dt " + formatNumber(*dt, 4) + " s";
  return label;
}

std::string ToleranceCheck::metricLabel() const {
  return physical_error.empty() ? metric : metric + " " + physical_error + " physical error";
}

std::expected<Tolerances, std::string> parseTolerances(const std::string& text,
                                                       const std::string& source,
                                                       const std::string& base_dir,
                                                       EngineRegistry& registry) {
  auto root = mysim::parseJson(text, source);
  if (!root) return std::unexpected(root.error());
  return readTolerances(*root, source, base_dir, registry);
}

std::expected<Tolerances, std::string> loadTolerances(const std::string& path,
                                                      EngineRegistry& registry) {
  auto root = mysim::readJsonFile(path, "tolerances file");
  if (!root) return std::unexpected(root.error());
  return readTolerances(*root, path, fs::path(path).parent_path().string(), registry);
}

}  // namespace springcheck
