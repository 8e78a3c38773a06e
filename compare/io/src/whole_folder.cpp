#include "compare/io/whole_folder.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace springcheck {
namespace fs = std::filesystem;
namespace {

// Whether `name` is one of the kind's numbered files: prefix, one or more digits, suffix.
bool isNumbered(const std::string& name, const FolderKind& kind) {
  const std::string& p = kind.numbered_prefix;
  const std::string& s = kind.numbered_suffix;
  if (p.empty() || name.size() <= p.size() + s.size()) return false;
  if (!name.starts_with(p) || !name.ends_with(s)) return false;
  const std::string digits = name.substr(p.size(), name.size() - p.size() - s.size());
  return std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The first entry of `dir` that `kind` does not write, or "" if every one is its own.
std::string foreignEntry(const fs::path& dir, const FolderKind& kind) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (e.is_directory() && !e.is_symlink() && kind.subfolders) {
      if (std::string inner = foreignEntry(e.path(), *kind.subfolders); !inner.empty()) {
        return name + "/" + inner;
      }
      continue;
    }
    const bool leftover_temporary = name.find(".tmp.") != std::string::npos;
    if (!(e.is_regular_file() && !e.is_symlink() &&
          (kind.files.count(name) || leftover_temporary || isNumbered(name, kind)))) {
      return name;
    }
  }
  return ec ? "(unreadable: " + ec.message() + ")" : "";
}

// Staging folders of `folder` left by a springcheck that died mid-write (SIGKILL, a power cut):
// named ".NAME.staging.PID.N" beside it, with no live process PID. Removed, so a result folder's
// parent never fills with halves of runs.
void removeDeadStaging(const fs::path& parent, const std::string& name) {
  const std::string prefix = "." + name + ".staging.";
  std::error_code ec;
  std::vector<fs::path> dead;
  for (const fs::directory_entry& e : fs::directory_iterator(parent, ec)) {
    const std::string entry = e.path().filename().string();
    if (!entry.starts_with(prefix) || !e.is_directory() || e.is_symlink()) continue;
    char* end = nullptr;
    const long pid = std::strtol(entry.c_str() + prefix.size(), &end, 10);
    if (pid <= 0 || end == nullptr || *end != '.') continue;
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) dead.push_back(e.path());
  }
  for (const fs::path& d : dead) fs::remove_all(d, ec);
}

}  // namespace

const FolderKind& objSequenceKind() {
  static const FolderKind kind{"OBJ sequence folder", {"times.csv"}, nullptr, "frame_", ".obj"};
  return kind;
}

const FolderKind& runFolderKind() {
  static const FolderKind kind{"run folder",
                               {"final_state.csv", "trajectory.npy", "times.npy", "energy.csv",
                                "final.obj", "summary.json"},
                               &objSequenceKind()};
  return kind;
}

const FolderKind& comparisonFolderKind() {
  static const FolderKind kind{"comparison folder",
                               {"comparison.json", "engine_metrics.csv", "pair_metrics.csv",
                                "node_distance.csv", "series.csv"},
                               &runFolderKind()};
  return kind;
}

std::expected<void, std::string> writeFolderWhole(
    const std::string& path, const FolderKind& kind,
    const std::function<std::expected<void, std::string>(const std::string& staging)>& body) {
  const fs::path target = fs::path(path).lexically_normal();
  fs::path folder = target.filename().empty() ? target.parent_path() : target;
  std::error_code ec;
  // A link to a folder is followed: the results go into the folder it names (staged beside it, so
  // the swap stays on its file system), and the link stays a link.
  if (fs::is_symlink(fs::symlink_status(folder, ec))) {
    const fs::path real = fs::canonical(folder, ec);
    if (ec || !fs::is_directory(real, ec)) {
      return std::unexpected(folder.string() + ": a symbolic link to " +
                             fs::read_symlink(folder, ec).string() +
                             ", which is not a folder; give a folder or a link to one");
    }
    folder = real;
  }
  const bool existed = fs::exists(fs::symlink_status(folder, ec));
  if (existed) {
    if (!fs::is_directory(fs::symlink_status(folder, ec))) {
      return std::unexpected(folder.string() + ": exists and is not a folder");
    }
    if (std::string foreign = foreignEntry(folder, kind); !foreign.empty()) {
      return std::unexpected(folder.string() + " holds '" + foreign + "', which a " + kind.what +
                             " does not: springcheck replaces only its own results; give an "
                             "empty or new folder");
    }
  }
  const fs::path parent = folder.parent_path().empty() ? fs::path(".") : folder.parent_path();
  fs::create_directories(parent, ec);
  if (ec) return std::unexpected("cannot create " + parent.string() + ": " + ec.message());
  removeDeadStaging(parent, folder.filename().string());
  static std::atomic<long> count{0};
  const fs::path staging = parent / ("." + folder.filename().string() + ".staging." +
                                     std::to_string(::getpid()) + "." + std::to_string(++count));
  fs::create_directory(staging, ec);
  if (ec) return std::unexpected("cannot create " + staging.string() + ": " + ec.message());
  auto written = body(staging.string());
  if (!written) {
    fs::remove_all(staging, ec);
    // Named as the user knows it (the staging folder is gone), and what became of the folder.
    std::string message = written.error();
    for (std::size_t at; (at = message.find(staging.string())) != std::string::npos;) {
      message.replace(at, staging.string().size(), folder.string());
    }
    return std::unexpected(message + "; " + folder.string() +
                           (existed ? " keeps its previous results" : " was not created"));
  }
  // Swap in one step; a plain rename where there is nothing to swap with (or it went meanwhile).
  if (existed && renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, folder.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(staging, ec);  // now the previous run
    return {};
  }
  if (std::rename(staging.c_str(), folder.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    fs::remove_all(staging, ec);
    return std::unexpected("cannot put " + folder.string() + " in place: " + why);
  }
  return {};
}

}  // namespace springcheck
