// springcheck trade: the cheapest setup (resolution, engine, integrator and its parameters, step)
// whose settled quantity stays within a bound of its physical reference (docs/trade.md).
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "compare/io/atomic_file.h"
#include "compare/io/invocation.h"
#include "compare/io/progress.h"
#include "compare/io/whole_folder.h"
#include "compare/metrics/run_metrics.h"
#include "compare/studies/ablation.h"
#include "compare/studies/sweep.h"
#include "compare/studies/trade.h"
#include "compare/studies/trade_grid.h"
#include "mysim/integrator.h"
#include "mysim/scene_file.h"
#include "trade_output.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;

struct TradeOptions {
  std::string scene, quantity;
  double max_error = 0.0;
  bool relative = false;
  std::string cost = "wall";
  std::string json_out, out, table;
  std::vector<int> resolutions;
  std::vector<std::string> engines, integrators;
  std::vector<double> dts;
  int jobs = 1;
  std::string shard = "0/1";
  bool fresh = false, plan_only = false, ablate = false;
  std::vector<std::string> engines_files;
  Timing timing;
};

// The scene's settled quantities: those of the catalogue's refined metrics that one step of it
// already has (they read the shape, so a step is enough to know which apply).
std::vector<std::string> quantitiesOf(const EngineRegistry& registry, const mysim::Scene& scene) {
  RunConfig config = runConfig(scene);
  config.run.duration = scene.dt;
  const mysim::Model model = mysim::buildModel(scene);
  std::vector<std::string> names;
  auto record = registry.run("mysim", model, config);
  if (!record) return names;
  const EngineMetrics m = engineMetrics(model, {"mysim", *record});
  for (const MetricInfo& info : metricCatalog()) {
    if (info.refined && !info.pair && metricValue(m, info.name)) names.push_back(info.name);
  }
  return names;
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// The axes: the defaults around the scene, each replaced by its flag; every entry checked.
std::expected<TradeAxes, std::string> axesFor(const TradeOptions& o, const EngineRegistry& registry,
                                              const mysim::Scene& scene, int resolution) {
  TradeAxes axes = defaultTradeAxes(resolution, scene.dt, scene.integrator.name);
  if (!o.resolutions.empty()) axes.resolutions = o.resolutions;
  if (!o.engines.empty()) axes.engines = o.engines;
  if (!o.integrators.empty()) axes.integrators = o.integrators;
  if (!o.dts.empty()) axes.dts = o.dts;
  std::sort(axes.resolutions.begin(), axes.resolutions.end());
  if (std::adjacent_find(axes.resolutions.begin(), axes.resolutions.end()) != axes.resolutions.end()) {
    return std::unexpected("--resolutions: a resolution given twice; expected distinct ones");
  }
  for (const std::string& e : axes.engines) {
    if (auto ok = registry.check(e); !ok) return std::unexpected("--engines: " + ok.error());
    if (e.find(':') != std::string::npos) {
      return std::unexpected("--engines: " + e + ": expected an engine name; mysim's integrators "
                             "go in --integrators");
    }
  }
  for (const std::string& i : axes.integrators) {
    if (auto v = mysim::parseIntegratorVariant(i); !v) return std::unexpected("--integrators: " + v.error());
  }
  const double largest = *std::max_element(axes.dts.begin(), axes.dts.end());
  for (double dt : axes.dts) {
    const double ratio = largest / dt;
    if (std::abs(ratio - std::round(ratio)) > 1e-9 * ratio) {
      return std::unexpected("--dts: " + std::to_string(dt) + " s does not divide the largest step " +
                             std::to_string(largest) + " s a whole number of times; expected steps " +
                             "whose frames line up (for example 0.016, 0.004, 0.001)");
    }
  }
  return axes;
}

// Writes the grid into `work` and, unless --plan, runs its (remaining) cases into `table`.
int runGrid(const TradeOptions& o, EngineRegistry& registry, const TradeGrid& grid,
            const std::string& work, const std::string& table) {
  if (o.plan_only) {
    auto spec = writeTradeGrid(grid, work);
    if (!spec) {
      std::cerr << "error: " << spec.error() << '\n';
      return kFailure;
    }
    std::cout << "trade grid written: " << *spec << " (run it with springcheck sweep, or on "
              << "Slurm with examples/slurm/submit.sh; then springcheck trade ... --table TABLE)\n";
    return kOk;
  }
  SweepOptions options{.jobs = o.jobs, .repeats = o.timing.repeats, .threads = o.timing.threads,
                       .fixed_threads = o.timing.fixed_threads, .resume = !o.fresh};
  if (!parseShard(o.shard, options.shard_index, options.shard_count)) return kBadInput;
  auto progress = std::make_shared<Progress>("trade " + fs::path(o.scene).stem().string(),
                                             isatty(STDERR_FILENO));
  options.progress = [progress](int done, int total) { progress->update(done, total); };
  if (auto ran = runTradeGrid(registry, grid, work, table, options); !ran) {
    std::cerr << "error: " << ran.error() << '\n';
    return kFailure;
  }
  return kOk;
}

int writeAnswer(const TradeOptions& o, const TradeAnswer& a, const TradeReport& r,
                const nlohmann::json& ablation) {
  static const FolderKind kind{"trade folder", {"trade.csv", "trade.json", "trade.csv.command"}};
  const std::string csv = tradeTableCsv(a);
  nlohmann::json body = tradeJson(a, r);
  body["ablation"] = ablation;
  const std::string answer = jsonText(body, 2) + "\n";
  auto written = writeFolderWhole(o.out, kind, [&](const std::string& staging)
                                                   -> std::expected<void, std::string> {
    if (auto ok = writeFileAtomically(staging + "/trade.csv", [&](std::ostream& f) { f << csv; }); !ok) {
      return ok;
    }
    if (auto ok = writeFileAtomically(staging + "/trade.json", [&](std::ostream& f) { f << answer; });
        !ok) {
      return ok;
    }
    return writeInvocationBeside(staging + "/trade.csv");
  });
  if (written && !o.json_out.empty()) {
    written = writeFileAtomically(o.json_out, [&](std::ostream& f) { f << answer; });
  }
  if (!written) {
    std::cerr << "error: " << written.error() << '\n';
    return kFailure;
  }
  return kOk;
}

// With --ablate: the recommended setup (else the closest) with each model term taken out.
std::expected<nlohmann::json, std::string> ablationOf(const TradeOptions& o,
                                                      const EngineRegistry& registry,
                                                      const TradeAnswer& a) {
  const std::optional<std::size_t> at = a.recommended ? a.recommended : a.closest;
  if (!o.ablate || !at || !a.reference.value) return nullptr;
  auto found = ablate(registry, o.scene, a.setups[*at], o.quantity, *a.reference.value, a.bound);
  if (!found) return std::unexpected(found.error());
  printAblation(*found, describeSetup(a.setups[*at], a));
  return ablationJson(*found);
}

int answer(const TradeOptions& o, const EngineRegistry& registry, const std::string& scene,
           const TradeInputs& in) {
  const TradeQuestion question{o.quantity, o.max_error, o.relative,
                               o.cost == "work" ? Cost::Work : Cost::WallTime};
  const TradeAnswer a = analyseTrade(in, question);
  const TradeReport report{scene, o.quantity, findMetric(o.quantity)->unit, question,
                           o.out + "/trade.csv"};
  printTradeAnswer(a, report);
  const auto ablation = ablationOf(o, registry, a);
  if (!ablation) {
    std::cerr << "error: " << ablation.error() << '\n';
    return kBadInput;
  }
  if (int code = writeAnswer(o, a, report, *ablation); code != kOk) return code;
  return a.recommended ? kOk : kFailure;
}

int trade(TradeOptions o) {
  std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  const std::optional<mysim::Scene> scene = loadSceneOrSay(*registry, o.scene);
  if (!scene) return kBadInput;
  const auto resolution = sceneResolution(o.scene);
  if (!resolution) {
    std::cerr << "error: " << resolution.error() << '\n';
    return kBadInput;
  }
  const std::vector<std::string> quantities = quantitiesOf(*registry, *scene);
  if (std::find(quantities.begin(), quantities.end(), o.quantity) == quantities.end()) {
    std::cerr << "error: --quantity: " << o.quantity << " is not a settled quantity of " << o.scene
              << "; expected one of: " << (quantities.empty() ? "(none)" : joined(quantities)) << '\n';
    return kBadInput;
  }
  const auto axes = axesFor(o, *registry, *scene, *resolution);
  if (!axes) {
    std::cerr << "error: " << axes.error() << '\n';
    return kBadInput;
  }
  if (o.out.empty()) o.out = "out/trade/" + scene->name;
  const std::string work = o.out + ".grid";
  std::string table = o.table;
  if (table.empty()) {
    const auto grid = planTradeGrid(o.scene, scene->name, *axes);
    if (!grid) {
      std::cerr << "error: " << grid.error() << '\n';
      return kBadInput;
    }
    table = work + (o.shard == "0/1" ? "/grid.csv" : "/grid.shard-" + o.shard.substr(0, o.shard.find('/')) + ".csv");
    if (int code = runGrid(o, *registry, *grid, work, table); code != kOk || o.plan_only) return code;
    if (o.shard != "0/1") {
      std::cout << "shard " << o.shard << " -> " << table << "; join the shards with springcheck "
                << "sweep-merge, then: springcheck trade ... --table MERGED.csv\n";
      return kOk;
    }
  }
  auto rows = readSweepTable(table);
  if (!rows) {
    std::cerr << "error: " << rows.error() << '\n';
    return kBadInput;
  }
  TradeInputs in{*rows, tradeResolutions(*rows, scene->name),
                 closedFormReference(*scene, mysim::buildModel(*scene), o.quantity), "mysim",
                 scene->integrator.name,
                 [&](const std::string& e) { const Engine* x = registry->find(e); return x && x->kind == "bullet"; }};
  if (in.resolution_of_scene.empty()) {
    std::cerr << "error: " << table << ": no rows of " << scene->name << " at any resolution\n";
    return kBadInput;
  }
  return answer(o, *registry, scene->name, in);
}

}  // namespace

void addTradeCommand(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<TradeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "trade",
      "The cheapest resolution, engine, integrator and step whose settled quantity stays within "
      "--max-error of its physical reference, with its error budget (exit 1 if none does; "
      "docs/trade.md)");
  cmd->add_option("scene", o->scene, "A material scene (system.material)")->required();
  cmd->add_option("--quantity", o->quantity,
                  "The settled quantity: a refined metric the scene has (tip_drop, chord_angle, "
                  "bending_length, sag_lowest, drape_coefficient, drape_folds)")
      ->required();
  cmd->add_option("--max-error", o->max_error,
                  "Largest acceptable physical error, in the quantity's unit (a fraction with "
                  "--relative)")
      ->required()
      ->check(kPositive);
  cmd->add_flag("--relative", o->relative, "--max-error is a fraction of the reference (0.01: 1 %)");
  cmd->add_option("--cost", o->cost, "wall (wall time) or work (evaluations and iterations)")
      ->check(CLI::IsMember({"wall", "work"}))
      ->capture_default_str();
  cmd->add_option("--resolutions", o->resolutions, "Resolutions (default r/4, r/2, r, 2r)")
      ->delimiter(',')
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--engines", o->engines,
                  "Engines (default mysim, bullet-implicit, bullet-deformable)")->delimiter(',');
  cmd->add_option("--integrators", o->integrators,
                  "mysim's integrators, NAME[:PARAMETER=VALUE...] (default: docs/trade.md)")
      ->delimiter(',');
  cmd->add_option("--dts", o->dts, "Steps, s (default 8, 2 and 1/2 times the scene's)")
      ->delimiter(',')
      ->check(kPositive);
  cmd->add_option("--jobs", o->jobs, "Cases at once (default 1: each timed alone)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  cmd->add_option("--shard", o->shard, "Run only the grid's cases with id % n == i, as i/n")
      ->capture_default_str();
  cmd->add_flag("--fresh", o->fresh, "Start the grid over instead of resuming it");
  cmd->add_flag("--ablate", o->ablate,
                "Then rerun the recommended setup with each model term taken out (bending, "
                "damping, drag, wind, driven pins, colliders): each term's effect against the bound");
  cmd->add_flag("--plan", o->plan_only, "Write the grid (scenes and sweep spec) and stop");
  cmd->add_option("--table", o->table, "Answer from this grid table (a merged sweep of the plan)");
  cmd->add_option("--out", o->out, "Output folder (default out/trade/NAME; the grid in OUT.grid)");
  cmd->add_option("--json", o->json_out, "Also write the answer (trade.json) here");
  addEnginesFileOption(cmd, o->engines_files);
  addTimingOptions(cmd, o->timing, 1);
  cmd->callback([o, &exit_code] { exit_code = trade(*o); });
}

}  // namespace springcheck
