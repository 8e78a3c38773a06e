#include "compare/studies/refine_study.h"

#include <algorithm>
#include <memory>
#include <mutex>
#include <numeric>
#include <sstream>

#include "compare/io/csv.h"
#include "compare/io/text_format.h"
#include "compare/metrics/cantilever_metric.h"
#include "compare/metrics/run_metrics.h"
#include "compare/studies/parallel_jobs.h"
#include "compare/studies/physical_reference.h"
#include "compare/studies/trade_grid.h"
#include "mysim/scene_file.h"
#include "mysim/thread_budget.h"

namespace springcheck {
namespace {

// The catalogue's refined metrics, in its order.
std::vector<const MetricInfo*> refinedMetrics() {
  std::vector<const MetricInfo*> list;
  for (const MetricInfo& info : metricCatalog()) {
    if (info.refined && !info.pair) list.push_back(&info);
  }
  return list;
}

// One scene file at one resolution, read as any scene file is, and its model: shared by the
// engines that run it.
struct ResolvedScene {
  mysim::Scene scene;
  mysim::Model model;
};

std::expected<std::unique_ptr<ResolvedScene>, std::string> sceneAt(const EngineRegistry& registry,
                                                                   const std::string& path,
                                                                   int resolution) {
  auto text = sceneTextAtResolution(path, resolution);
  if (!text) return std::unexpected(text.error());
  auto scene = mysim::parseScene(*text, path, registry.sceneSections());
  if (!scene) return std::unexpected(scene.error());
  auto resolved = std::make_unique<ResolvedScene>();
  resolved->model = mysim::buildModel(*scene);
  resolved->scene = std::move(*scene);
  return resolved;
}

// The order at which a material scene's smooth quantities converge under refinement. Hinge
// bending with the clamp's edge midway between its two columns: second order (derived in
// cloth_material.cpp; measured 2.10 on the cantilever's tip drop at 4-8-16 cells, the triples
// 4-8-16 and 8-16-32 within 0.2); a material chain's sag against the continuous catenary:
// second order (the discrete catenary's O(h^2), measured 2.06 on the cable). Flex springs
// converge to no bending at all (their stiffness is per spring, not the material's) and a
// membrane has no bending to converge: no order to hold them to.
// The cloth's material, if the scene is a material cloth.
const mysim::ClothMaterial* clothMaterial(const mysim::Scene& scene) {
  const auto* cloth = std::get_if<mysim::ClothScene>(&scene.system);
  return cloth && cloth->material ? &*cloth->material : nullptr;
}

std::optional<double> expectedOrder(const mysim::Scene& scene) {
  const mysim::ClothMaterial* material = clothMaterial(scene);
  if (!material) return 2.0;  // a material chain (refine takes material scenes only)
  if (material->bending == mysim::BendingModel::Hinge) return 2.0;
  return std::nullopt;
}

// What a completed run settled to, and the closed form it is held to (or why there is none).
void measure(RefineRow& row, const ResolvedScene& at, const mysim::RunRecord& record) {
  const EngineMetrics m = engineMetrics(at.model, {row.engine, record});
  for (const MetricInfo* info : refinedMetrics()) {
    if (auto v = metricValue(m, info->name)) row.values[info->name] = *v;
  }
  if (m.closed_form && cantileverReference(at.model)) {
    row.reference = m.closed_form->exact;
    row.reference_quantity = "tip_drop";
  }
  if (auto cable = closedFormReference(at.scene, at.model, "sag_lowest")) {
    row.reference = *cable->value;
    row.reference_quantity = "sag_lowest";
  }
  if (row.reference_quantity.empty()) row.note = "no closed form: " + m.no_closed_form;
}

void runOne(const EngineRegistry& registry, const RefineSettings& settings, int jobs,
            const ResolvedScene& at, RefineRow& row) {
  RunConfig config = runConfig(at.scene);
  applyTiming(settings.timing, config);
  if (config.run.threads == 0) config.run.threads = std::max(1, mysim::availableCores() / jobs);
  row.jobs = jobs;
  auto record = registry.run(row.engine, at.model, config);
  if (!record) {
    row.status = "refused";
    row.note = record.error().message;
    return;
  }
  row.status = record->status();
  row.wall_seconds = record->wall_seconds;
  if (record->blowup) {
    std::ostringstream why;
    why << record->status() << " at t = " << record->blowup->time << " s ("
        << record->blowup->check << ")";
    row.note = why.str();
  } else if (!record->frames.empty()) {
    measure(row, at, *record);
  }
}

}  // namespace

std::expected<std::vector<RefineRow>, std::string> runRefinement(const EngineRegistry& registry,
                                                                 const RefineSettings& settings) {
  std::vector<std::unique_ptr<ResolvedScene>> scenes;
  std::vector<RefineRow> rows;
  std::vector<const ResolvedScene*> scene_of;  // per row
  for (const std::string& path : settings.scenes) {
    for (int resolution : settings.resolutions) {
      auto at = sceneAt(registry, path, resolution);
      if (!at) return std::unexpected(at.error());
      const mysim::Scene& s = (*at)->scene;
      const mysim::ClothMaterial* material = clothMaterial(s);
      const std::string bending = material ? mysim::bendingModelName(material->bending) : "none (chain)";
      for (const std::string& engine : settings.engines) {
        RefineRow row;
        row.scene = s.name;
        row.bending = bending;
        row.engine = engine;
        row.resolution = resolution;
        row.particles = (*at)->model.particleCount();
        row.expected_order = expectedOrder(s);
        rows.push_back(std::move(row));
        scene_of.push_back(at->get());
      }
      scenes.push_back(std::move(*at));
    }
  }
  // The largest runs first, so the last one to start is a small one (the rows keep their order).
  std::vector<std::size_t> order(rows.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return rows[a].particles > rows[b].particles;
  });
  const int jobs = jobCount(settings.jobs, rows.size());
  std::mutex mutex;
  int done = 0;
  forEachInParallel(rows.size(), jobs, [&](std::size_t k) {
    runOne(registry, settings, jobs, *scene_of[order[k]], rows[order[k]]);
    std::lock_guard<std::mutex> lock(mutex);
    if (settings.progress) settings.progress(++done, static_cast<int>(rows.size()));
  });
  return rows;
}

double RefineEstimateRow::finestVsLimit() const {
  return verdict.converged && estimate.limit && *estimate.limit != 0.0
             ? (values.back() - *estimate.limit) / *estimate.limit
             : NAN;
}

double RefineEstimateRow::finestVsReference() const {
  return std::isfinite(reference) ? (values.back() - reference) / reference : NAN;
}

std::vector<RefineEstimateRow> refinementEstimates(const std::vector<RefineRow>& rows) {
  std::map<std::pair<std::string, std::string>, std::vector<const RefineRow*>> series;
  for (const RefineRow& r : rows) {
    if (r.status == "ok") series[{r.scene, r.engine}].push_back(&r);
  }
  std::vector<RefineEstimateRow> estimates;
  for (const auto& [key, runs] : series) {
    for (const MetricInfo* info : refinedMetrics()) {
      RefineEstimateRow e;
      e.scene = key.first;
      e.bending = runs.back()->bending;
      e.engine = key.second;
      e.quantity = info->name;
      e.unit = info->unit;
      for (const RefineRow* r : runs) {
        if (auto v = r->values.find(info->name); v != r->values.end()) {
          e.resolutions.push_back(r->resolution);
          e.values.push_back(v->second);
        }
      }
      if (e.values.empty()) continue;
      e.estimate = estimateRefinement(e.resolutions, e.values);
      if (info->count) {  // whole numbers settle on a value; no order, no limit to draw
        std::ostringstream seen;
        for (double v : e.values) seen << (seen.tellp() > 0 ? ", " : "") << v;
        e.verdict = {false, "a count, which settles rather than converging at an order: " + seen.str()};
      } else {
        e.expected_order = runs.back()->expected_order;
        e.verdict = refinementVerdict(e.resolutions, e.values, e.expected_order);
      }
      if (runs.back()->reference_quantity == info->name) e.reference = runs.back()->reference;
      estimates.push_back(std::move(e));
    }
  }
  return estimates;
}

namespace {
// Tables' number format (text_format.h); empty for a quantity the run does not have.
std::string number(double v) { return std::isfinite(v) ? formatNumber(v) : ""; }
}  // namespace

std::string refineTableCsv(const std::vector<RefineRow>& rows) {
  std::ostringstream table;
  std::vector<std::string> header{"scene", "bending", "engine", "resolution", "particles",
                                  "status", "wall_seconds", "jobs"};
  for (const MetricInfo* info : refinedMetrics()) header.push_back(info->name);
  header.push_back("closed_form_value");
  header.push_back("note");
  table << csvLine(header) << '\n';
  for (const RefineRow& r : rows) {
    std::vector<std::string> fields{r.scene,         r.bending,
                                    r.engine,        std::to_string(r.resolution),
                                    std::to_string(r.particles), r.status,
                                    number(r.wall_seconds),      std::to_string(r.jobs)};
    for (const MetricInfo* info : refinedMetrics()) {
      auto v = r.values.find(info->name);
      fields.push_back(v == r.values.end() ? "" : number(v->second));
    }
    fields.push_back(number(r.reference));
    fields.push_back(r.note);
    table << csvLine(fields) << '\n';
  }
  return table.str();
}

std::string refineEstimatesCsv(const std::vector<RefineEstimateRow>& estimates) {
  std::ostringstream out;
  // The order and the limit only where the verdict allows them (the evidence rule); the verdict
  // says what was seen either way.
  out << csvLine({"scene", "bending", "engine", "quantity", "unit", "finest_resolution", "finest",
                  "observed_order", "extrapolated_limit", "finest_vs_limit_rel", "reference",
                  "finest_vs_reference_rel", "note", "resolutions", "expected_order", "verdict"})
      << '\n';
  for (const RefineEstimateRow& e : estimates) {
    const bool quote = e.verdict.converged;
    std::string resolutions;
    for (int n : e.resolutions) resolutions += (resolutions.empty() ? "" : " ") + std::to_string(n);
    out << csvLine({e.scene, e.bending, e.engine, e.quantity, e.unit,
                    std::to_string(e.resolutions.back()), number(e.values.back()),
                    quote && e.estimate.order ? number(*e.estimate.order) : "",
                    quote && e.estimate.limit ? number(*e.estimate.limit) : "",
                    number(e.finestVsLimit()), number(e.reference), number(e.finestVsReference()),
                    e.estimate.reason, resolutions,
                    e.expected_order ? number(*e.expected_order) : "", e.verdict.text})
        << '\n';
  }
  return out.str();
}

}  // namespace springcheck
