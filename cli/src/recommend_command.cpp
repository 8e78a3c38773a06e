// springcheck recommend: the cheapest engine, integrator and step under an error bound, from a
// sweep table, a sweep spec (run first) or a scene (a sweep around its step is run first).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "compare/io/atomic_file.h"
#include "compare/io/progress.h"
#include "compare/studies/recommend.h"
#include "compare/studies/sweep.h"
#include "mysim/json_input.h"
#include "mysim/thread_budget.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct RecommendOptions {
  std::string target;
  double max_error = 0.0;
  std::string cost = "wall";
  std::string json_out;
  std::string table_out;
  int jobs = 0;
  std::vector<std::string> engines_files;
  Timing timing;
};

json choiceJson(const std::optional<Choice>& c) {
  if (!c) return nullptr;
  return {{"engine", c->engine},
          {"integrator", c->integrator},
          {"family", c->family},
          {"tolerance", c->tolerance},
          {"dt", c->dt},
          {"error", c->error},
          {"wall_seconds", c->wall_seconds},
          {"realtime_factor", c->realtime_factor},
          {"work", c->work},
          {"reference", c->reference},
          {"summary", describe(*c)}};
}

// The table to recommend from: the target itself, or the table of the sweep it names (a spec,
// or a sweep around a scene's step), run first. Empty (after a message) on failure; `code` says
// which.
std::string tableFor(const RecommendOptions& o, EngineRegistry& registry, int& code) {
  if (fs::path(o.target).extension() == ".csv") return o.target;
  // A sweep spec has "scenes"; anything else is read as a scene.
  auto root = mysim::readJsonFile(o.target, "sweep spec or scene");
  code = kBadInput;
  if (!root) {
    std::cerr << "error: " << root.error() << '\n';
    return "";
  }
  std::expected<SweepSpec, std::string> spec = std::unexpected("");
  if (root->is_object() && root->contains("scenes")) {
    spec = loadSweepSpec(o.target, registry);
  } else {
    auto scene = registry.loadScene(o.target);
    if (!scene) {
      std::cerr << "error: " << scene.error() << '\n';
      return "";
    }
    spec = sweepAroundScene(registry, o.target, std::move(*scene));
  }
  if (!spec) {
    std::cerr << "error: " << spec.error() << '\n';
    return "";
  }
  const std::string table =
      o.table_out.empty() ? "out/recommend/" + spec->name + ".csv" : o.table_out;
  std::error_code ec;
  fs::create_directories(fs::path(table).parent_path(), ec);
  SweepOptions options{.jobs = o.jobs,
                       .repeats = o.timing.repeats,
                       .threads = o.timing.threads,
                       .fixed_threads = o.timing.fixed_threads,
                       .resume = false};
  auto progress = std::make_shared<Progress>("recommend " + spec->name, isatty(STDERR_FILENO));
  options.progress = [progress](int done, int total) { progress->update(done, total); };
  if (auto ran = runSweep(registry, *spec, table, options); !ran) {
    std::cerr << "error: " << ran.error() << '\n';
    code = kFailure;
    return "";
  }
  code = kOk;
  return table;
}

// Prints one recommendation and returns it as JSON: the best and the runner-up, every engine's
// own cheapest (speed at equal accuracy), and mysim's best realtime factor over Bullet's best.
json reportRecommendation(const Recommendation& r, Cost cost, const EngineRegistry& registry) {
  std::cout << r.scene << " (stiffness x" << r.stiffness_scale << "), error <= " << r.max_error
            << " m, cheapest by " << (cost == Cost::Work ? "work" : "wall time") << ":\n";
  if (r.best) {
    std::cout << "  best:      " << describe(*r.best) << '\n';
    std::cout << "  runner-up: " << (r.runner_up ? describe(*r.runner_up) : "none") << '\n';
  } else {
    std::cout << "  none of the " << r.candidates << " finished runs stays under " << r.max_error
              << " m\n";
  }
  std::cout << "  (" << r.meeting << " of " << r.candidates << " finished runs meet the bound; "
            << "error against " << (r.best ? r.best->reference : "the sweep's reference") << ")\n";
  json per_engine = json::array();
  double mysim_best = 0.0, bullet_best = 0.0;
  if (!r.per_engine.empty()) std::cout << "  each engine's cheapest under the bound:\n";
  for (const Choice& c : r.per_engine) {
    std::cout << "    " << describe(c) << '\n';
    per_engine.push_back(choiceJson(c));
    const Engine* engine = registry.find(c.engine);
    const std::string kind = engine ? engine->kind : "";
    if (kind == "mysim") mysim_best = std::max(mysim_best, c.realtime_factor);
    if (kind == "bullet") bullet_best = std::max(bullet_best, c.realtime_factor);
  }
  json per_family = json::array();
  if (!r.per_family.empty()) std::cout << "  each solver family's cheapest under the bound:\n";
  for (const Choice& c : r.per_family) {
    std::cout << "    " << c.family << ": " << describe(c) << '\n';
    per_family.push_back(choiceJson(c));
  }
  json closest = json::array();
  for (const Choice& c : r.closest_per_family) closest.push_back(choiceJson(c));
  json ratio = nullptr;
  if (mysim_best > 0 && bullet_best > 0) {
    ratio = mysim_best / bullet_best;
    std::cout << "  mysim's best runs " << ratio.get<double>()
              << "x the realtime factor of Bullet's best at this accuracy\n";
  }
  return {{"scene", r.scene},           {"stiffness_scale", r.stiffness_scale},
          {"candidates", r.candidates}, {"meeting", r.meeting},
          {"best", choiceJson(r.best)}, {"runner_up", choiceJson(r.runner_up)},
          {"per_engine", per_engine},   {"per_family", per_family},
          {"closest_per_family", closest},
          {"mysim_over_bullet_realtime", ratio}};
}

int recommendCommand(const RecommendOptions& o) {
  const Cost cost = o.cost == "work" ? Cost::Work : Cost::WallTime;
  std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  int code = kOk;
  const std::string table = tableFor(o, *registry, code);
  if (table.empty()) return code;
  auto rows = readSweepTable(table);
  if (!rows) {
    std::cerr << "error: " << rows.error() << '\n';
    return kBadInput;
  }
  const std::vector<Recommendation> found = recommend(*rows, o.max_error, cost);
  if (found.empty()) {
    std::cerr << "error: " << table << ": no rows to recommend from\n";
    return kBadInput;
  }
  json out = {{"table", table},
              {"max_error", o.max_error},
              {"cost", cost == Cost::Work ? "work" : "wall_seconds"},
              {"recommendations", json::array()}};
  bool all_met = true;
  for (const Recommendation& r : found) {
    all_met &= r.best.has_value();
    out["recommendations"].push_back(reportRecommendation(r, cost, *registry));
  }
  if (!o.json_out.empty()) {
    if (auto written = writeFileAtomically(
            o.json_out, [&](std::ostream& file) { file << jsonText(out, 2) << '\n'; });
        !written) {
      std::cerr << "error: " << written.error() << '\n';
      return kFailure;
    }
  }
  return all_met ? kOk : kFailure;
}

}  // namespace

void addRecommendCommand(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<RecommendOptions>();
  CLI::App* cmd = app.add_subcommand(
      "recommend",
      "The cheapest engine, integrator and step whose error stays under --max-error, and the "
      "runner-up (exit 1 if none does)");
  cmd->add_option("target", o->target,
                  "A sweep table (.csv), a sweep spec (run first) or a scene (a sweep of every "
                  "engine around its step is run first)")
      ->required();
  cmd->add_option("--max-error", o->max_error,
                  "Largest acceptable error, m (the sweep's error column: max over frames of the "
                  "RMS node distance to its reference)")
      ->required()
      ->check(kPositive);
  cmd->add_option("--cost", o->cost,
                  "What cheapest means: wall (wall time, the fastest of the timing rounds) or "
                  "work (derivative evaluations + iterations, the same on any machine)")
      ->check(CLI::IsMember({"wall", "work"}))
      ->capture_default_str();
  cmd->add_option("--json", o->json_out, "Also write the answer as JSON here");
  cmd->add_option("--table", o->table_out,
                  "Where a sweep it runs writes its table (default out/recommend/NAME.csv)");
  cmd->add_option("--jobs", o->jobs, "Parallel runs of a sweep it runs (default: all cores)");
  addEnginesFileOption(cmd, o->engines_files);
  addTimingOptions(cmd, o->timing, 3);
  cmd->callback([o, &exit_code] { exit_code = recommendCommand(*o); });
}

}  // namespace springcheck
