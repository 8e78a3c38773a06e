#include "compare/engines/python_interpreter.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>

#include "process.h"

namespace springcheck {
namespace fs = std::filesystem;
namespace {

// Whether `python` imports `modules`; "" if it does, else what it said last (or why it did not
// start).
std::string importFailure(const std::string& python, const std::vector<std::string>& modules) {
  std::string imports = "import ";
  for (std::size_t k = 0; k < modules.size(); ++k) imports += (k ? ", " : "") + modules[k];
  const fs::path log =
      fs::temp_directory_path() / ("springcheck_python_" + std::to_string(::getpid()) + ".log");
  // 60 s: a cold matplotlib import on a loaded machine takes seconds, never a minute.
  const ProcessResult r = runProcess({python, "-c", imports}, log.string(), 60.0);
  std::string said = r.started ? lastLines(log.string(), 1) : r.error;
  std::error_code ec;
  fs::remove(log, ec);
  if (r.started && !r.timed_out && r.signal == 0 && r.exit_code == 0) return "";
  while (!said.empty() && (said.front() == ' ' || said.front() == '\n')) said.erase(0, 1);
  while (!said.empty() && said.back() == '\n') said.pop_back();
  return said.empty() ? "it failed" : said;
}

std::string joined(const std::vector<std::string>& modules, const char* separator) {
  std::string s;
  for (std::size_t k = 0; k < modules.size(); ++k) s += (k ? separator : "") + modules[k];
  return s;
}

std::expected<std::string, std::string> search(const std::vector<std::string>& modules) {
  const std::string wanted = "a python3 with " + joined(modules, " and ");
  std::string packages;
  for (const std::string& m : modules) packages += " python3-" + m;
  if (const char* chosen = std::getenv("SPRINGCHECK_PYTHON"); chosen && *chosen) {
    if (std::string failure = importFailure(chosen, modules); !failure.empty()) {
      return std::unexpected("SPRINGCHECK_PYTHON=" + std::string(chosen) + " is not " + wanted +
                             ": " + failure);
    }
    return std::string(chosen);
  }
  std::vector<std::string> candidates;
  if (std::string(SPRINGCHECK_PYTHON).size()) candidates.push_back(SPRINGCHECK_PYTHON);
  for (const char* c : {"/usr/bin/python3", "python3"}) {
    if (std::find(candidates.begin(), candidates.end(), c) == candidates.end()) {
      candidates.push_back(c);
    }
  }
  std::string tried;
  for (const std::string& c : candidates) {
    const std::string failure = importFailure(c, modules);
    if (failure.empty()) return c;
    tried += "\n  " + c + (c == "python3" ? " (on PATH)" : "") + ": " + failure;
  }
  return std::unexpected("no " + wanted + " found (SPRINGCHECK_PYTHON is not set); tried:" + tried +
                         "\n  install" + packages + " (Debian), or set SPRINGCHECK_PYTHON to an "
                         "interpreter that has them");
}

}  // namespace

std::expected<std::string, std::string> findPython(const std::vector<std::string>& modules) {
  static std::mutex mutex;
  static std::map<std::vector<std::string>, std::expected<std::string, std::string>> found;
  const std::lock_guard lock(mutex);
  auto it = found.find(modules);
  if (it == found.end()) it = found.emplace(modules, search(modules)).first;
  return it->second;
}

}  // namespace springcheck
