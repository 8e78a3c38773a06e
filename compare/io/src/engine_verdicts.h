#pragma once
// Each engine's verdict over the suite, in numbers (internal to compare/io; the report words and
// draws them): the engine it is closest to on settled cloths, its errors against every closed form
// it ran (which it meets to 1 %, which not), its worst energy drift where nothing drives or damps,
// its worst momentum drift on a free body, its step rule on each mapped scene, the scenes it did
// not finish cleanly. Each number with its cut: the scene and the time window it is over.
#include <nlohmann/json.hpp>
#include <vector>

#include "report_tables.h"

namespace springcheck {

// Within these of the closed form an engine is "trusted" for a scene: 1 % of the exact value (the
// question users bring: within 1 % of the real answer); where the exact value is 0 (a body that
// must not move: a stuck block, a capstan that holds), 1 mm, the recommendation's error bound.
inline constexpr double kTrustedRelativeError = 0.01;
inline constexpr double kTrustedErrorAtRest = 1e-3;  // m

// `comparisons`: the manifest's, read (report_tables.h); `stability_scenes`: its entries
// (report_manifest.h).
nlohmann::json engineVerdicts(const std::vector<report_tables::LoadedComparison>& comparisons,
                              const nlohmann::json& stability_scenes);

}  // namespace springcheck
