#pragma once
#include <expected>
#include <string>

#include "mysim/scene.h"

namespace mysim {

// Reads and validates a scene file. On failure the message names the file, the field and what
// was expected, e.g. "scenes/a.json: system.rows: expected an integer >= 2, got -3".
// `sections`: the engine settings sections the scene may carry (see EngineSection).
[[nodiscard]] std::expected<Scene, std::string> loadScene(
    const std::string& path, const std::vector<EngineSection>& sections = {});

// The same from text already read; `source` names it in messages.
[[nodiscard]] std::expected<Scene, std::string> parseScene(
    const std::string& text, const std::string& source,
    const std::vector<EngineSection>& sections = {});

}  // namespace mysim
