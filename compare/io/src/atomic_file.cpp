#include "compare/io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace springcheck {

std::expected<void, std::string> writeFileAtomically(
    const std::string& path, const std::function<void(std::ostream&)>& body) {
  namespace fs = std::filesystem;
  static std::atomic<long> writes{0};
  const std::string tmp =
      path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(++writes);
  std::error_code ec;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      return std::unexpected("cannot write " + path + ": " + std::strerror(errno));
    }
    try {
      body(out);
    } catch (const std::exception& e) {
      out.close();
      fs::remove(tmp, ec);
      return std::unexpected("cannot write " + path + ": " + e.what());
    }
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

std::string jsonText(const nlohmann::json& value, int indent) {
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace springcheck
