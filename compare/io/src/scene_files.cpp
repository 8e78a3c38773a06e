#include "compare/io/scene_files.h"

#include <algorithm>
#include <filesystem>

namespace springcheck {

std::expected<std::vector<std::string>, std::string> sceneFiles(const std::string& dir) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir, ec)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  }
  if (ec) return std::unexpected(dir + ": " + ec.message());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace springcheck
