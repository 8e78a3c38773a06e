#pragma once
// The numbers the report's first page states, found here from the tables (the report only
// draws them): the largest final-frame disagreement between engines on a cloth where every engine
// has settled (mirror-aware), apart from it the largest trajectory difference on a cloth still
// moving or driven at its last frame, each cloth comparison's state (settled at t, moving,
// driven: the drape pages' titles), each free body's
// worst linear and worst angular momentum drift, and per scene and engine where it goes unstable
// (worst and median h w_max over the cells it was mapped on, at the lowest mass ratio).
#include <nlohmann/json.hpp>

namespace springcheck {

// `comparisons` and `stability_scenes`: the manifest's entries (report_manifest.h).
nlohmann::json reportHeadlines(const nlohmann::json& comparisons,
                               const nlohmann::json& stability_scenes);

}  // namespace springcheck
