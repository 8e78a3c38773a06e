// springcheck refine: one material scene at several resolutions in each engine, and how each
// quantity converges (compare/studies/refinement.h).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "commands.h"
#include "compare/io/atomic_file.h"
#include "compare/io/csv.h"
#include "compare/io/invocation.h"
#include "compare/io/text_format.h"
#include "compare/io/whole_folder.h"
#include "compare/metrics/cantilever_metric.h"
#include "compare/metrics/closed_form.h"
#include "compare/metrics/run_metrics.h"
#include "compare/studies/physical_reference.h"
#include "compare/studies/refinement.h"
#include "compare/studies/trade_grid.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

struct RefineOptions {
  std::vector<std::string> scenes;
  std::vector<int> resolutions{8, 16, 32};
  std::string engines = "mysim";
  std::string out = "out/refine";
  std::vector<std::string> engines_files;
  Timing timing;
};

// One run's shape measurements: every catalogue metric marked `refined` that the scene has.
struct RefineRow {
  std::string scene, bending, engine, status;
  int resolution = 0;
  int particles = 0;
  double wall_seconds = 0.0;
  std::map<std::string, double> values;
  double reference = NAN;  // the closed form's value (the heavy elastica's tip drop), where one is
  std::string reference_quantity;
};

// The catalogue's refined metrics, in its order.
std::vector<const MetricInfo*> refinedMetrics() {
  std::vector<const MetricInfo*> list;
  for (const MetricInfo& info : metricCatalog()) {
    if (info.refined && !info.pair) list.push_back(&info);
  }
  return list;
}

// The scene file with system.resolution set, read as any scene file is.
std::expected<mysim::Scene, std::string> sceneAt(const EngineRegistry& registry,
                                                 const std::string& path, int resolution) {
  auto text = sceneTextAtResolution(path, resolution);
  if (!text) return std::unexpected(text.error());
  return mysim::parseScene(*text, path, registry.sceneSections());
}

// Tables' number format (text_format.h); empty for a quantity the run does not have.
std::string number(double v) { return std::isfinite(v) ? formatNumber(v) : ""; }

// Sorts the resolutions; refuses one given twice, and says that fewer than three give no order.
bool sortedDistinct(std::vector<int>& resolutions) {
  std::sort(resolutions.begin(), resolutions.end());
  if (auto twice = std::adjacent_find(resolutions.begin(), resolutions.end());
      twice != resolutions.end()) {
    std::cerr << "error: --resolutions: " << *twice
              << " given twice; expected distinct resolutions (three or more for an order)\n";
    return false;
  }
  if (resolutions.size() < 3) {
    std::cerr << "note: --resolutions: " << resolutions.size()
              << " resolution(s): the quantities are measured, but an order and a limit need "
                 "three or more\n";
  }
  return true;
}

int refine(const RefineOptions& o) {
  const std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  std::vector<int> resolutions = o.resolutions;
  if (!sortedDistinct(resolutions)) return kBadInput;
  const std::vector<std::string> engines = splitList(o.engines);
  std::vector<RefineRow> rows;
  int failures = 0;
  for (const std::string& path : o.scenes) {
    for (int resolution : resolutions) {
      auto scene = sceneAt(*registry, path, resolution);
      if (!scene) {
        std::cerr << "error: " << scene.error() << '\n';
        return kBadInput;
      }
      RunConfig config = runConfig(*scene);
      applyTiming(o.timing, config);
      const mysim::Model model = mysim::buildModel(*scene);
      for (const std::string& engine : engines) {
        RefineRow row{scene->name,
                      scene->cloth_material ? mysim::bendingModelName(scene->cloth_material->bending)
                                            : "none (chain)",
                      engine, "", resolution, model.particleCount()};
        auto record = registry->run(engine, model, config);
        if (!record) {
          std::cerr << path << " at resolution " << resolution << ", " << engine << ": "
                    << record.error().message << '\n';
          row.status = "refused";
          ++failures;
          rows.push_back(row);
          continue;
        }
        row.status = record->status();
        row.wall_seconds = record->wall_seconds;
        if (record->blowup) {
          std::cerr << path << " at resolution " << resolution << ", " << engine << ": "
                    << record->status() << " at t = " << record->blowup->time << " s ("
                    << record->blowup->check << ")\n";
          ++failures;
        } else if (!record->frames.empty()) {
          const EngineMetrics m = engineMetrics(model, {engine, *record});
          for (const MetricInfo* info : refinedMetrics()) {
            if (auto v = metricValue(m, info->name)) row.values[info->name] = *v;
          }
          if (m.closed_form && cantileverReference(model)) {
            row.reference = m.closed_form->exact;
            row.reference_quantity = "tip_drop";
          }
          if (auto cable = closedFormReference(*scene, model, "sag_lowest")) {
            row.reference = *cable->value;
            row.reference_quantity = "sag_lowest";
          }
        }
        std::cout << row.scene << " (" << row.bending << ") at " << resolution << " cells, "
                  << engine << ": " << row.status;
        for (const auto& [name, value] : row.values) std::cout << ", " << name << " " << number(value);
        std::cout << " (" << row.wall_seconds << " s)\n";
        rows.push_back(row);
      }
    }
  }

  // Per scene, engine and quantity: the estimate from the completed resolutions.
  std::ostringstream estimates;
  estimates << csvLine({"scene", "bending", "engine", "quantity", "unit", "finest_resolution", "finest",
                        "observed_order", "extrapolated_limit", "finest_vs_limit_rel",
                        "reference", "finest_vs_reference_rel", "note"})
            << '\n';
  std::map<std::pair<std::string, std::string>, std::vector<const RefineRow*>> series;
  for (const RefineRow& r : rows) {
    if (r.status == "ok") series[{r.scene, r.engine}].push_back(&r);
  }
  std::cout << "\nconvergence (the last three resolutions; Richardson limit):\n";
  for (const auto& [key, runs] : series) {
    for (const MetricInfo* info : refinedMetrics()) {
      const std::string& name = info->name;
      std::vector<int> n;
      std::vector<double> q;
      for (const RefineRow* r : runs) {
        if (auto v = r->values.find(name); v != r->values.end()) {
          n.push_back(r->resolution), q.push_back(v->second);
        }
      }
      if (q.empty()) continue;
      const RefinementEstimate e = estimateRefinement(n, q);
      const RefineRow& finest = *runs.back();
      const double reference = finest.reference_quantity == name ? finest.reference : NAN;
      const double vs_limit = e.limit && *e.limit != 0.0 ? (q.back() - *e.limit) / *e.limit : NAN;
      const double vs_reference = std::isfinite(reference) ? (q.back() - reference) / reference : NAN;
      estimates << csvLine({key.first, finest.bending, key.second, name, info->unit,
                            std::to_string(n.back()), number(q.back()),
                            e.order ? number(*e.order) : "", e.limit ? number(*e.limit) : "",
                            number(vs_limit), number(reference), number(vs_reference), e.reason})
                << '\n';
      std::cout << "  " << key.first << " " << key.second << " " << name << " [" << info->unit
                << "]: finest " << number(q.back()) << ", order "
                << (e.order ? number(*e.order) : "- (" + e.reason + ")") << ", limit "
                << (e.limit ? number(*e.limit) : "-")
                << (std::isfinite(vs_reference)
                        ? ", finest vs closed form " + number(100.0 * vs_reference) + " %"
                        : "")
                << '\n';
    }
  }
  std::ostringstream table;
  std::vector<std::string> header{"scene", "bending", "engine", "resolution", "particles",
                                  "status", "wall_seconds"};
  for (const MetricInfo* info : refinedMetrics()) header.push_back(info->name);
  header.push_back("closed_form_value");
  table << csvLine(header) << '\n';
  for (const RefineRow& r : rows) {
    std::vector<std::string> fields{r.scene, r.bending, r.engine, std::to_string(r.resolution),
                                    std::to_string(r.particles), r.status, number(r.wall_seconds)};
    for (const MetricInfo* info : refinedMetrics()) {
      auto v = r.values.find(info->name);
      fields.push_back(v == r.values.end() ? "" : number(v->second));
    }
    fields.push_back(number(r.reference));
    table << csvLine(fields) << '\n';
  }
  static const FolderKind kind{"refinement folder",
                               {"refine.csv", "refine_estimates.csv", "refine.csv.command"}};
  auto written = writeFolderWhole(o.out, kind, [&](const std::string& staging)
                                                   -> std::expected<void, std::string> {
    for (const auto& [file, text] :
         {std::pair{"refine.csv", table.str()}, std::pair{"refine_estimates.csv", estimates.str()}}) {
      const std::string body = text;
      if (auto ok = writeFileAtomically(staging + "/" + file, [&](std::ostream& out) { out << body; });
          !ok) {
        return ok;
      }
    }
    return writeInvocationBeside(staging + "/refine.csv");
  });
  if (!written) {
    std::cerr << "error: " << written.error() << '\n';
    return kFailure;
  }
  std::cout << "results in " << o.out << " (refine.csv, refine_estimates.csv)\n";
  return failures > 0 ? kBlowUp : kOk;
}

}  // namespace

void addRefineCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<RefineOptions>();
  CLI::App* cmd = app.add_subcommand(
      "refine",
      "Run material scenes at several resolutions in each engine: each quantity's observed order "
      "of convergence and Richardson limit (docs/materials.md)");
  cmd->add_option("scenes", options->scenes, "Material scene files (system.material)")->required();
  cmd->add_option("--resolutions", options->resolutions,
                  "Cells across the width, three or more for an order (default 8,16,32)")
      ->delimiter(',')
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--engines", options->engines, "Engines, comma-separated")->capture_default_str();
  addEnginesFileOption(cmd, options->engines_files);
  cmd->add_option("--out", options->out, "Output directory")->capture_default_str();
  addTimingOptions(cmd, options->timing, 1);
  cmd->callback([options, &exit_code] { exit_code = refine(*options); });
}

}  // namespace springcheck
