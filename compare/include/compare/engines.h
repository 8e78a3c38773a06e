#pragma once
#include <expected>
#include <string>
#include <vector>

#include "mysim/scene.h"
#include "mysim/simulation.h"

namespace springcheck {

// Engines a scene can run in. mysim is our simulator; the Bullet twins come from reference/.
const std::vector<std::string>& engineNames();

// Whether `engine` names an engine: one of engineNames() or "mysim:INTEGRATOR".
[[nodiscard]] std::expected<void, std::string> checkEngineName(const std::string& engine);

// Runs the scene in one engine: set-up errors (unknown engine, an integrator the system cannot
// take) come back as the error; a blow-up is part of the record.
[[nodiscard]] std::expected<mysim::RunRecord, std::string> runEngine(const mysim::Scene& scene,
                                                                     const std::string& engine);

}  // namespace springcheck
