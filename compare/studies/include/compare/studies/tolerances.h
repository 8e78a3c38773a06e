#pragma once
#include <expected>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "compare/engines/engine_registry.h"
#include "mysim/scene.h"

namespace springcheck {

// One bound of a tolerances file: metric(engines on scene) <= bound, and why it is that number.
struct ToleranceCheck {
  std::string scene;                 // path, resolved against the file's scene_root
  std::vector<std::string> engines;  // one for a per-engine metric, two for a pair metric
  std::string metric;
  double bound = 0.0;
  std::string why;
  // The engine's known bias this bound allows (it passes while the engine is off by that much):
  // said beside the gate count on the report's first page, so a pass does not read as "accurate".
  // Empty: none.
  std::string known_bias;
  // A variant of a material scene (docs/compare.md): at another resolution and step, as a trade
  // recommends it. Absent: the scene as written.
  std::optional<int> resolution;
  std::optional<double> dt;
  // "absolute" or "relative": the check holds the metric's error against the scene's physical
  // reference (its closed form, physical_reference.h), not the metric itself. Empty: the metric.
  std::string physical_error;
  double reference = 0.0;  // that reference, in the metric's unit

  bool isVariant() const { return resolution || dt; }
  std::string sceneKey() const;  // the scene and its variant: what runs once
  std::string variantLabel() const;  // "" or " at resolution 10, dt 0.016 s"
  std::string metricLabel() const;   // "tip_drop" or "tip_drop relative physical error"
};

struct Tolerances {
  std::string source;
  std::vector<ToleranceCheck> checks;
  // Every check's scene (by sceneKey: a variant is its own scene), read and validated once.
  std::map<std::string, mysim::Scene> scenes;
  std::string engines_file;  // the user's engines the checks name, if any (resolved path)
};

// Reads and validates a tolerances file (schema in docs/compare.md). Refuses, naming the file,
// the check and the field: a missing or mistyped field, an unknown scene (no such file, or one
// that does not load), an unknown engine or metric, an engine count that does not fit the
// metric, a negative or non-finite bound, an empty `why`, a variant of a scene that is not a
// material scene, a physical error of a metric the scene has no closed form for. An
// `engines_file` the tolerances name (relative to their file) is added to `registry`.
// The scene file a check runs: the file with the check's resolution (a material scene's
// system.resolution) and step applied.
[[nodiscard]] std::expected<nlohmann::json, std::string> sceneVariantJson(
    const ToleranceCheck& check);

[[nodiscard]] std::expected<Tolerances, std::string> loadTolerances(const std::string& path,
                                                                    EngineRegistry& registry);
[[nodiscard]] std::expected<Tolerances, std::string> parseTolerances(const std::string& text,
                                                                     const std::string& source,
                                                                     const std::string& base_dir,
                                                                     EngineRegistry& registry);

}  // namespace springcheck
