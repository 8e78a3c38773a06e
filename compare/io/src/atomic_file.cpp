#include "compare/io/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace springcheck {

std::expected<void, std::string> writeFileAtomically(
    const std::string& path, const std::function<void(std::ostream&)>& body) {
  namespace fs = std::filesystem;
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  std::error_code ec;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      return std::unexpected("cannot write " + path + ": " + std::strerror(errno));
    }
    body(out);
    out.close();
    if (!out) {
      fs::remove(tmp, ec);
      return std::unexpected("cannot write " + path + " (disk full or I/O error)");
    }
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    return std::unexpected("cannot write " + path + ": " + ec.message());
  }
  return {};
}

}  // namespace springcheck
