#include "data_dir.h"

#include <cstdlib>
#include <filesystem>

namespace springcheck {

std::string dataDir() {
  if (const char* env = std::getenv("SPRINGCHECK_DATA_DIR"); env && *env) return env;
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return "share/springcheck";  // no /proc: relative to the working folder
  return (exe.parent_path().parent_path() / "share" / "springcheck").lexically_normal().string();
}

std::string dataFile(const std::string& relative) { return dataDir() + "/" + relative; }

}  // namespace springcheck
