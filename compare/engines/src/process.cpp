#include "process.h"

#include "compare/engines/interrupts.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <deque>
#include <fstream>
#include <mutex>
#include <thread>

extern char** environ;

namespace springcheck {
namespace {

// The environment variable that marks everything one engine run starts: children inherit it,
// whatever process group or session they move to, so the run's end can find and stop them.
constexpr const char* kRunMarker = "SPRINGCHECK_ENGINE_RUN";

// Once per process: become a subreaper (an engine's orphaned children and grandchildren are
// re-parented to springcheck, not to init, so they can be reaped), and take SIGCHLD back to its
// default (a parent that ignored it would make waitpid fail and an exit status read as 0).
void prepareParent() {
  static std::once_flag once;
  std::call_once(once, [] {
    prctl(PR_SET_CHILD_SUBREAPER, 1);
    signal(SIGCHLD, SIG_DFL);
  });
}

std::string newMarker() {
  static std::atomic<long> runs{0};
  return std::to_string(getpid()) + "." + std::to_string(++runs);
}

}  // namespace

namespace {

// The environment springcheck runs in, but for any run marker it carries, and this run's marker.
// The pointers point into environ and `marker`.
std::vector<char*> markedEnvironment(const std::string& marker) {
  std::vector<char*> env;
  for (char** e = environ; *e; ++e) {
    if (std::strncmp(*e, kRunMarker, std::strlen(kRunMarker)) != 0) env.push_back(*e);
  }
  env.push_back(const_cast<char*>(marker.c_str()));
  env.push_back(nullptr);
  return env;
}

// How posix_spawn starts an engine: stdin from /dev/null, stdout and stderr to the log, its own
// process group, and the default disposition of every signal springcheck handles.
// (springcheck blocks SIGINT and SIGTERM in its threads, compare/engines/interrupts.h: the
// engine starts with none blocked.)
struct SpawnSetup {
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attributes;
  explicit SpawnSetup(const std::string& log_path) {
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_path.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF |
                                              POSIX_SPAWN_SETSIGMASK);
    posix_spawnattr_setpgroup(&attributes, 0);
    sigset_t defaults;
    sigemptyset(&defaults);
    for (int s : {SIGINT, SIGTERM, SIGCHLD, SIGPIPE, SIGHUP}) sigaddset(&defaults, s);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    sigset_t none;
    sigemptyset(&none);
    posix_spawnattr_setsigmask(&attributes, &none);
  }
  ~SpawnSetup() {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
  }
  SpawnSetup(const SpawnSetup&) = delete;
  SpawnSetup& operator=(const SpawnSetup&) = delete;
};

// Waits for pid with a growing poll interval (1 to 50 ms) until it ends, it cannot be waited
// for (result.error) or time_limit passes (result.timed_out). Whether it ended; its status.
bool waitForEnd(pid_t pid, std::chrono::steady_clock::time_point start, double time_limit,
                const std::string& name, int& status, ProcessResult& result) {
  auto waited = std::chrono::milliseconds(1);
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) return true;
    if (done < 0 && errno != EINTR) {
      result.error = "cannot wait for '" + name + "': " + std::strerror(errno);
      return false;
    }
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > time_limit) {
      result.timed_out = true;
      return false;
    }
    std::this_thread::sleep_for(waited);
    waited = std::min(waited * 2, std::chrono::milliseconds(50));
  }
}

}  // namespace

ProcessResult runProcess(const std::vector<std::string>& argv, const std::string& log_path,
                         double time_limit) {
  prepareParent();
  ProcessResult result;
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const std::string marker = std::string(kRunMarker) + "=" + newMarker();
  std::vector<char*> env = markedEnvironment(marker);

  // posix_spawn, not fork: springcheck may have threads running (parallel sweeps).
  const auto start = std::chrono::steady_clock::now();
  int spawned = 0;
  const SpawnSetup setup(log_path);
  const TrackedRun tracked(
      [&] {
        pid_t started = -1;
        spawned = posix_spawnp(&started, args[0], &setup.actions, &setup.attributes, args.data(),
                               env.data());
        return spawned == 0 ? started : -1;
      },
      marker);
  const pid_t pid = tracked.pid();
  if (spawned != 0) {
    result.error = std::string("cannot start '") + argv[0] + "': " + std::strerror(spawned);
    return result;
  }
  result.started = true;

  int status = 0;
  bool ended = waitForEnd(pid, start, time_limit, argv[0], status, result);
  if (!ended) {  // at its limit, or not waitable: the pid itself, whatever group it joined
    kill(pid, SIGKILL);
    ended = waitpid(pid, &status, 0) == pid;
  }
  // Whatever it started is stopped with it: its group, then everything that carries the run's
  // marker (children that left the group or the session).
  stopRun(pid, marker);
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!ended && result.error.empty()) result.error = std::string("lost '") + argv[0] + "'";
  if (ended && WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (ended && WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  return result;
}

std::string lastLines(const std::string& path, int lines) {
  std::ifstream in(path);
  std::deque<std::string> kept;
  for (std::string line; std::getline(in, line);) {
    if (line.size() > 300) line = line.substr(0, 300) + "...";
    kept.push_back(line);
    if (static_cast<int>(kept.size()) > lines) kept.pop_front();
  }
  std::string text;
  for (const std::string& line : kept) text += "\n    " + line;
  return text;
}

}  // namespace springcheck
