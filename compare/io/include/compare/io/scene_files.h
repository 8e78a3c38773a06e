#pragma once
#include <expected>
#include <string>
#include <vector>

namespace springcheck {

// The *.json files of a directory and its subdirectories, sorted by path (so runs and tables come
// in a fixed order).
[[nodiscard]] std::expected<std::vector<std::string>, std::string> sceneFiles(
    const std::string& dir);

}  // namespace springcheck
