#include "compare/engines/interrupts.h"

#include <dirent.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <thread>

namespace springcheck {
namespace {

struct Registry {
  std::mutex mutex;
  int next = 0;
  std::map<int, std::pair<pid_t, std::string>> runs;  // slot -> pid, marker
  std::map<int, std::string> scratch;                 // slot -> folder
};

Registry& registry() {
  static Registry r;
  return r;
}

// Whether process `pid`'s environment holds `entry`.
bool carries(pid_t pid, const std::string& entry) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/environ", std::ios::binary);
  for (std::string item; std::getline(in, item, '\0');) {
    if (item == entry) return true;
  }
  return false;
}

void stopEverything(int signal_number) {
  Registry& r = registry();
  r.mutex.lock();  // held until exit: no engine starts after this
  for (const auto& [slot, run] : r.runs) {
    kill(run.first, SIGKILL);  // the engine itself, whatever group it joined
    stopRun(run.first, run.second);
  }
  for (const auto& [slot, folder] : r.scratch) {
    std::error_code ec;
    std::filesystem::remove_all(folder, ec);
  }
  const char* name = signal_number == SIGINT ? "SIGINT" : "SIGTERM";
  std::cerr << "\nspringcheck: " << name << ": stopped " << r.runs.size()
            << " engine run(s), removed their scratch; results written before it are kept\n";
  std::cerr.flush();
  std::_Exit(128 + signal_number);
}

}  // namespace

void handleInterrupts() {
  // A parent may have left them ignored (a background job of a non-interactive shell ignores
  // SIGINT): taken back, so the signal reaches the waiting thread instead of vanishing.
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);  // every thread started later inherits it
  std::thread([set] {
    int signal_number = 0;
    while (sigwait(&set, &signal_number) != 0) {
    }
    stopEverything(signal_number);
  }).detach();
}

TrackedRun::TrackedRun(const std::function<pid_t()>& spawn, const std::string& marker) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  pid_ = spawn();
  if (pid_ > 0) {
    slot_ = r.next++;
    r.runs[slot_] = {pid_, marker};
  }
}

TrackedRun::~TrackedRun() {
  if (slot_ < 0) return;
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  r.runs.erase(slot_);
}

TrackedScratch::TrackedScratch(const std::string& path) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  slot_ = r.next++;
  r.scratch[slot_] = path;
}

TrackedScratch::~TrackedScratch() {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  r.scratch.erase(slot_);
}

void stopRun(pid_t pid, const std::string& marker) {
  kill(-pid, SIGKILL);  // its group (none, if it moved to another: then nothing)
  // Everything else it started, found by the marker its environment carries (children that left
  // the group or the session, grandchildren re-parented to springcheck), until none is left (one
  // may fork while the list is read).
  for (int round = 0; round < 50; ++round) {
    std::vector<pid_t> found;
    if (DIR* proc = opendir("/proc")) {
      while (const dirent* e = readdir(proc)) {
        const pid_t p = static_cast<pid_t>(std::atol(e->d_name));
        if (p > 0 && p != getpid() && carries(p, marker)) found.push_back(p);
      }
      closedir(proc);
    }
    if (found.empty()) return;
    for (pid_t p : found) kill(p, SIGKILL);
    for (pid_t p : found) waitpid(p, nullptr, 0);  // not springcheck's child: returns at once
  }
}

}  // namespace springcheck
