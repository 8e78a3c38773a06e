#include <expected>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "commands.h"
#include "compare/io/scene_files.h"
#include "compare/studies/comparison.h"
#include "compare/io/atomic_file.h"
#include "compare/io/text_format.h"
#include "compare/studies/gate.h"
#include "compare/studies/gate_report_formats.h"
#include "compare/studies/parallel_jobs.h"
#include "mysim/thread_budget.h"
#include "data_dir.h"

namespace springcheck {
namespace {

struct SuiteOptions {
  std::string dir = dataFile("scenes");
  std::string out = "out/suite";
  std::vector<std::string> engines_files;
  std::string engines;  // comma-separated; empty: every engine of the registry
  Timing timing;
  std::string tolerances;  // also gate the runs against this file
  std::string gate_json;   // and write the gate's results here
  // Scenes side by side (0: every free core). 1 by default: each run then has the machine to
  // itself and its wall time in the tables means what it says.
  int jobs = 1;
};

// The gate on the suite's runs (a scene run in every engine its checks name is not run again).
// A failed check makes the exit code 1 even where a run blew up or stopped at a solver limit
// (3, 5): the gate is what CI reads, and a blow-up on some scene must not hide it.
int gateSuite(const EngineRegistry& registry, const Tolerances& tolerances,
              const ComparisonCache& done, const SuiteOptions& o, int code) {
  const auto report = runGate(registry, tolerances, done);
  if (!report) {
    std::cerr << "error: gate: " << report.error() << '\n';
    return kBadInput;
  }
  printGate(std::cout, *report);
  if (!o.gate_json.empty()) {
    auto written = writeFileAtomically(
        o.gate_json, [&](std::ostream& out) { writeGateJson(out, *report, o.tolerances); });
    if (!written) {
      std::cerr << "error: --gate-json: " << written.error() << '\n';
      return kFailure;
    }
  }
  const bool hidden = code == kOk || code == kBlowUp || code == kSolverLimit;
  return !report->passed() && hidden ? kFailure : code;
}

// One scene's comparison, printed and written as soon as it is made (a run's trajectories are
// not held for a whole suite), or why it could not be made (a scene file that does not load, an
// unknown engine).
struct SceneOutcome {
  std::string error;    // the scene could not be compared: nothing else is set
  std::string printed;  // its table, printed in the files' order once all are done
  std::string write_error;  // its results could not be written (said on stderr)
  int code = kOk;       // what it adds to the suite's exit code
  std::optional<Comparison> kept;  // for the gate, with --tolerances
};

SceneOutcome compareOneScene(const EngineRegistry& registry, const std::string& file,
                             const std::vector<std::string>& engines, const SuiteOptions& o,
                             const Timing& timing, int jobs) {
  SceneOutcome outcome;
  auto scene = registry.loadScene(file);
  if (!scene) {
    outcome.error = scene.error();
    return outcome;
  }
  auto comparison = compareScene(registry, *scene, engines, timing);
  if (!comparison) {
    outcome.error = comparison.error();
    return outcome;
  }
  comparison->jobs = jobs;
  std::ostringstream printed;
  printComparison(printed, *comparison);
  outcome.printed = printed.str();
  if (!comparison->failed.empty()) outcome.code = kEngineFailed;
  for (const EngineMetrics& m : comparison->engines) {
    // The seed scenes run at the seed's own (stable) settings: a blow-up there is a bug.
    if (m.status != "ok" && outcome.code == kOk) outcome.code = exitCodeForStatus(m.status);
  }
  if (auto written = writeComparison(o.out + "/" + scene->name, *comparison); !written) {
    outcome.write_error = written.error();
    outcome.code = kFailure;
  }
  if (!o.tolerances.empty()) outcome.kept = std::move(*comparison);
  return outcome;
}

// Every scene in every engine, --jobs scenes side by side (each mysim run on its share of the
// cores), in the files' order.
std::vector<SceneOutcome> compareScenes(const EngineRegistry& registry,
                                        const std::vector<std::string>& files,
                                        const std::vector<std::string>& engines,
                                        const SuiteOptions& o) {
  const int jobs = jobCount(o.jobs, files.size());
  Timing timing = o.timing;
  if (timing.threads == 0 && jobs > 1) timing.threads = std::max(1, mysim::availableCores() / jobs);
  std::vector<SceneOutcome> outcomes(files.size());
  forEachInParallel(files.size(), jobs, [&](std::size_t k) {
    outcomes[k] = compareOneScene(registry, files[k], engines, o, timing, jobs);
  });
  return outcomes;
}

// The engines --engines names ("all" and the like expanded), each one the registry knows; every
// engine of the registry when it names none.
std::expected<std::vector<std::string>, std::string> suiteEngines(const EngineRegistry& registry,
                                                                  const std::string& listed) {
  if (listed.empty()) return registry.names();
  std::vector<std::string> engines = registry.expand(splitList(listed));
  if (engines.empty()) return std::unexpected("expected at least one engine, got '" + listed + "'");
  for (const std::string& spec : engines) {
    if (auto known = registry.check(spec); !known) return std::unexpected(known.error());
  }
  return engines;
}

// Every scene under a directory in every engine that takes it (every engine of the registry,
// the user's own included; an engine that refuses a scene says why, and that is listed), with
// the comparison table of each. A scene file that does not load, a run that blows up or an
// external engine that fails makes the suite fail; the other scenes still run.
int runSuite(const SuiteOptions& o) {
  std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  auto files = sceneFiles(o.dir);
  if (!files) {
    std::cerr << "error: " << files.error() << '\n';
    return kBadInput;
  }
  if (!o.gate_json.empty() && o.tolerances.empty()) {
    std::cerr << "error: --gate-json: expected --tolerances too (the gate it writes)\n";
    return kBadInput;
  }
  std::optional<Tolerances> tolerances;
  if (!o.tolerances.empty()) {
    auto loaded = loadTolerances(o.tolerances, *registry);
    if (!loaded) {
      std::cerr << "error: --tolerances: " << loaded.error() << '\n';
      return kBadInput;
    }
    tolerances = std::move(*loaded);
  }
  const auto engines = suiteEngines(*registry, o.engines);
  if (!engines) {
    std::cerr << "error: --engines: " << engines.error() << '\n';
    return kBadInput;
  }
  std::vector<SceneOutcome> outcomes = compareScenes(*registry, *files, *engines, o);
  int code = kOk;
  ComparisonCache done;
  for (std::size_t k = 0; k < files->size(); ++k) {
    SceneOutcome& outcome = outcomes[k];
    if (!outcome.error.empty()) {
      std::cerr << "error: " << outcome.error << '\n';
      code = kBadInput;
      continue;
    }
    std::cout << outcome.printed;
    if (!outcome.write_error.empty()) std::cerr << "error: " << outcome.write_error << '\n';
    std::cout << '\n';
    // The first scene's trouble sets the code; an unwritable result overrides it.
    if (outcome.code == kFailure || (code == kOk && outcome.code != kOk)) code = outcome.code;
    std::error_code ec;
    const std::string key = std::filesystem::weakly_canonical((*files)[k], ec).string();
    if (outcome.kept) done.emplace(key, std::move(*outcome.kept));
  }
  if (tolerances) code = gateSuite(*registry, *tolerances, done, o, code);
  std::cout << "results in " << o.out << "/<scene>/\n";
  return code;
}

}  // namespace

void addSuiteCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<SuiteOptions>();
  CLI::App* suite = app.add_subcommand(
      "suite", "Run every scene under a directory in every engine that takes it, and compare");
  suite->add_option("dir", options->dir, "Scene directory")->capture_default_str();
  suite->add_option("--out", options->out, "Output root")->capture_default_str();
  suite->add_option("--engines", options->engines,
                    "Comma-separated engines (default: every engine, your own included; all: "
                    "every engine with mysim once per integrator). Engines the tolerances' checks "
                    "name but this leaves out are run by the gate");
  addEnginesFileOption(suite, options->engines_files);
  addTimingOptions(suite, options->timing, 1);
  suite->add_option("--tolerances", options->tolerances,
                    "Then check these bounds against the runs (a tolerances file, which may "
                    "name its own engines_file); the exit code says whether they held");
  suite->add_option("--gate-json", options->gate_json,
                    "With --tolerances: also write every check's result to this JSON file");
  suite->add_option("--jobs", options->jobs,
                    "Scenes run side by side (0: every free core); the tables keep each run's "
                    "wall time, measured beside the others")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  suite->callback([options, &exit_code] { exit_code = runSuite(*options); });
}

}  // namespace springcheck
