#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <thread>

#include "commands.h"
#include "compare/io/progress.h"
#include "compare/studies/parallel_jobs.h"
#include "compare/studies/sweep.h"
#include "mysim/thread_budget.h"

namespace springcheck {
namespace {

struct SweepCommandOptions {
  std::string spec;
  std::string out;
  int jobs = 0;
  std::string shard = "0/1";
  bool fresh = false;
  std::vector<std::string> engines_files;
  Timing timing;
};

int sweep(const SweepCommandOptions& o) {
  std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  auto spec = loadSweepSpec(o.spec, *registry);
  if (!spec) {
    std::cerr << "error: " << spec.error() << '\n';
    return kBadInput;
  }
  SweepOptions options;
  options.jobs = o.jobs;
  if (!parseShard(o.shard, options.shard_index, options.shard_count)) return kBadInput;
  options.resume = !o.fresh;
  options.repeats = o.timing.repeats;
  options.fixed_threads = o.timing.fixed_threads;
  options.threads = o.timing.threads;
  auto progress = std::make_shared<Progress>("sweep " + spec->name, isatty(STDERR_FILENO));
  options.progress = [progress](int done, int total) { progress->update(done, total); };
  auto timing =
      std::make_shared<Progress>("sweep " + spec->name + " timing", isatty(STDERR_FILENO));
  options.timing_progress = [timing](int done, int total) { timing->update(done, total); };
  const std::string out = o.out.empty() ? "out/sweep/" + spec->name + ".csv" : o.out;
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(out).parent_path(), ec);
  const auto total = expandSweep(*spec).size();
  auto ran = runSweep(*registry, *spec, out, options);
  if (!ran) {
    std::cerr << "error: " << ran.error() << '\n';
    return kFailure;
  }
  std::cout << "sweep " << spec->name << ": " << *ran << " runs now (shard " << o.shard << " of "
            << total << " cases, " << jobCount(o.jobs, total) << " jobs; "
            << (options.repeats > 1
                    ? "timed alone, fastest of " + std::to_string(options.repeats) + " rounds"
                    : std::string("timed once, cases side by side"))
            << ") -> " << out << '\n';
  return kOk;
}

}  // namespace

void addSweepCommands(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<SweepCommandOptions>();
  CLI::App* cmd = app.add_subcommand("sweep", "Run a grid of runs and write one results table");
  cmd->add_option("spec", o->spec, "Sweep spec (JSON, see docs/sweeps.md)")->required();
  cmd->add_option("--out", o->out, "Results table (default out/sweep/NAME.csv)");
  cmd->add_option("--jobs", o->jobs, "Parallel runs (default: all cores)");
  cmd->add_option("--shard", o->shard, "Run only cases with id % n == i, as i/n")
      ->capture_default_str();
  cmd->add_flag("--fresh", o->fresh, "Start over instead of resuming an existing table");
  addEnginesFileOption(cmd, o->engines_files);
  addTimingOptions(cmd, o->timing, 3);
  cmd->callback([o, &exit_code] { exit_code = sweep(*o); });

  auto inputs = std::make_shared<std::vector<std::string>>();
  auto merged = std::make_shared<std::string>();
  CLI::App* merge = app.add_subcommand("sweep-merge", "Join shard tables of one sweep");
  merge->add_option("out", *merged, "Merged table")->required();
  merge->add_option("inputs", *inputs, "Shard tables")->required();
  merge->callback([inputs, merged, &exit_code] {
    auto rows = mergeSweepTables(*inputs, *merged);
    if (!rows) {
      std::cerr << "error: " << rows.error() << '\n';
      exit_code = kBadInput;
      return;
    }
    std::cout << *rows << " rows -> " << *merged << '\n';
    exit_code = kOk;
  });
}

}  // namespace springcheck
