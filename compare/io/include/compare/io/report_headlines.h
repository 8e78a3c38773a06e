#pragma once
// The numbers the report's first page states, found here from the tables (the report only
// draws them): the largest final-frame disagreement between engines on a cloth, each free body's
// worst linear and worst angular momentum drift, and per scene and engine where it goes unstable
// (worst and median h w_max over the cells it was mapped on, at the lowest mass ratio).
#include <nlohmann/json.hpp>

namespace springcheck {

// `comparisons` and `stability_scenes`: the manifest's entries (report_manifest.h).
nlohmann::json reportHeadlines(const nlohmann::json& comparisons,
                               const nlohmann::json& stability_scenes);

}  // namespace springcheck
