#pragma once
#include <expected>
#include <map>
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
};

struct Tolerances {
  std::string source;
  std::vector<ToleranceCheck> checks;
  std::map<std::string, mysim::Scene> scenes;  // every check's scene, read and validated once
  std::string engines_file;  // the user's engines the checks name, if any (resolved path)
};

// Reads and validates a tolerances file (schema in docs/compare.md). Refuses, naming the file,
// the check and the field: a missing or mistyped field, an unknown scene (no such file, or one
// that does not load), an unknown engine or metric, an engine count that does not fit the
// metric, a negative or non-finite bound, an empty `why`. An `engines_file` the tolerances name
// (relative to their file) is added to `registry`.
[[nodiscard]] std::expected<Tolerances, std::string> loadTolerances(const std::string& path,
                                                                    EngineRegistry& registry);
[[nodiscard]] std::expected<Tolerances, std::string> parseTolerances(const std::string& text,
                                                                     const std::string& source,
                                                                     const std::string& base_dir,
                                                                     EngineRegistry& registry);

}  // namespace springcheck
