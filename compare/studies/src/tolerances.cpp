#include "compare/studies/tolerances.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "compare/metrics/run_metrics.h"
#include "mysim/json_input.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;
using mysim::FieldError;
using mysim::FieldReader;

constexpr const char* kSchema = "docs/compare.md";

ToleranceCheck readCheck(FieldReader& r, const fs::path& root, const EngineRegistry& registry,
                         std::map<std::string, mysim::Scene>& scenes) {
  ToleranceCheck c;
  // A path relative to scene_root, or a shipped scene by name ("chain_hanging": no folder, no
  // .json), found wherever springcheck is installed.
  const std::string given = r.text("scene");
  const bool by_name = !given.empty() && given.find('/') == std::string::npos && !given.ends_with(".json");
  if (by_name) {
    auto shipped = registry.shippedScene(given);
    if (!shipped) throw FieldError{r.field("scene"), shipped.error()};
    c.scene = *shipped;
  } else {
    c.scene = (root / given).lexically_normal().string();
  }
  if (!scenes.count(c.scene)) {  // each scene file read once, however many checks name it
    auto scene = registry.loadScene(c.scene);
    if (!scene) throw FieldError{r.field("scene"), "unknown scene: " + scene.error()};
    scenes.emplace(c.scene, std::move(*scene));
  }
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
  c.bound = r.number("bound");
  if (c.bound < 0) mysim::failField(r.field("bound"), "a finite number >= 0", r.raw("bound"));
  c.why = r.text("why");
  if (c.why.empty()) {
    throw FieldError{r.field("why"), "expected the reason for this bound (a non-empty string)"};
  }
  r.refuseUnknown(kSchema);
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
    top.refuseUnknown(kSchema);
    return t;
  });
}

}  // namespace

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
