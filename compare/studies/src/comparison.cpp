#include "compare/studies/comparison.h"

#include <algorithm>
#include <cstdio>

#include "compare/io/text_format.h"

namespace springcheck {

std::expected<Comparison, std::string> compareScene(const EngineRegistry& registry,
                                                    const mysim::Scene& scene,
                                                    const std::vector<std::string>& engines,
                                                    const Timing& timing) {
  // The scene stops here: the engines run its model with its run settings.
  Comparison c;
  c.model = mysim::buildModel(scene);
  c.config = runConfig(scene);
  applyTiming(timing, c.config);
  for (std::size_t k = 0; k < engines.size(); ++k) {
    if (auto known = registry.check(engines[k]); !known) return std::unexpected(known.error());
    if (std::find(engines.begin(), engines.begin() + k, engines[k]) != engines.begin() + k) {
      return std::unexpected("engine " + engines[k] + " is listed twice");
    }
  }
  for (const std::string& engine : engines) {
    auto record = registry.run(engine, c.model, c.config);
    if (!record) {
      if (record.error().kind == EngineError::Kind::Invalid) {
        return std::unexpected(record.error().message);  // the run itself, not the engine
      }
      (record.error().kind == EngineError::Kind::Failed ? c.failed : c.refused)
          .push_back({engine, record.error().message});
      continue;
    }
    c.runs.push_back({engine, std::move(*record)});
  }
  for (const EngineRun& run : c.runs) c.engines.push_back(engineMetrics(c.model, run));
  int best_order = 0;
  for (std::size_t r = 0; r < c.runs.size(); ++r) {
    const mysim::IntegratorInfo* info = mysim::findIntegrator(c.runs[r].record.integrator);
    if (info && !info->adaptive() && info->order > best_order && !c.runs[r].record.blowup) {
      best_order = info->order;
      c.energy_reference = r;
    }
  }
  for (std::size_t i = 0; i < c.runs.size(); ++i) {
    for (std::size_t j = i + 1; j < c.runs.size(); ++j) {
      if (c.runs[i].record.blowup || c.runs[j].record.blowup) continue;
      c.pairs.push_back(pairMetrics(c.model, c.runs[i], c.runs[j], c.engines[i], c.engines[j]));
    }
  }
  return c;
}

namespace {

std::string format(const std::optional<double>& v) { return formatNumber(v, 4, "-"); }

// Why closed_form_error is blank: once when every engine has the same reason, else per engine
// (a blow-up is said below with its time).
void printNoClosedForm(std::ostream& out, const std::vector<EngineMetrics>& engines) {
  std::vector<const EngineMetrics*> without;
  for (const EngineMetrics& m : engines) {
    if (!m.closed_form && !m.blew_up) without.push_back(&m);
  }
  if (without.empty()) return;
  bool same = true;
  for (const EngineMetrics* m : without) same &= m->no_closed_form == without.front()->no_closed_form;
  if (same && without.size() == engines.size()) {
    out << "  no closed form: " << without.front()->no_closed_form << '\n';
    return;
  }
  for (const EngineMetrics* m : without) {
    out << "  " << m->engine << ": no closed form: " << m->no_closed_form << '\n';
  }
}

// Under the per-engine table: why closed_form_error is blank, and the runs that did not end well.
void printRunNotes(std::ostream& out, const std::vector<EngineMetrics>& engines) {
  printNoClosedForm(out, engines);
  for (const EngineMetrics& m : engines) {
    if (m.blew_up) {
      out << "  " << m.engine << ": "
          << (m.status == "blowup" ? "BLOW-UP" : "STOPPED (" + m.status + ")")
          << " at t = " << m.blowup_time << " s\n";
    } else if (m.status != "ok") {
      out << "  " << m.engine << ": " << m.status << "\n";
    }
  }
}

}  // namespace

void printComparison(std::ostream& out, const Comparison& c) {
  out << "scene " << c.config.scene_name << " (" << c.config.source << "), dt " << c.config.run.dt
      << " s, " << c.config.run.duration << " s\n";
  for (const Comparison::Refusal& r : c.refused) out << "  refused: " << r.reason << '\n';
  for (const Comparison::Refusal& r : c.failed) out << "  FAILED: " << r.reason << '\n';
  // Columns as wide as their headers: a name is never cut (sag_difference, mysim:symplectic-euler).
  auto cell = [](const std::string& text, std::size_t width) {
    return std::string(width > text.size() ? width - text.size() : 0, ' ') + text;
  };
  auto left = [](const std::string& text, std::size_t width) {
    return text + std::string(width > text.size() ? width - text.size() : 0, ' ');
  };
  std::vector<std::size_t> engine_width;
  out << "  " << left("per engine", 34);
  for (const EngineMetrics& m : c.engines) {
    engine_width.push_back(std::max<std::size_t>(12, m.engine.size()) + 1);
    out << cell(m.engine, engine_width.back());
  }
  out << '\n';
  for (const MetricInfo& info : metricCatalog()) {
    if (info.pair) continue;
    // A shape measurement only some scenes have (a cantilever's, a drape test's): only where one is.
    bool any = !info.refined;
    for (const EngineMetrics& m : c.engines) any |= metricValue(m, info.name).has_value();
    if (!any) continue;
    out << "  " << left(info.name + " [" + info.unit + "]", 34);
    for (std::size_t e = 0; e < c.engines.size(); ++e) {
      out << cell(format(metricValue(c.engines[e], info.name)), engine_width[e]);
    }
    out << '\n';
  }
  printRunNotes(out, c.engines);
  if (c.pairs.empty()) return;
  std::size_t pair_width = 8;
  for (const PairMetrics& p : c.pairs) pair_width = std::max(pair_width, p.a.size() + p.b.size() + 3);
  std::vector<std::size_t> metric_width;
  out << "  " << left("per pair", pair_width);
  for (const MetricInfo& info : metricCatalog()) {
    if (!info.pair) continue;
    const std::string header = info.name + " [" + info.unit + "]";
    metric_width.push_back(std::max<std::size_t>(10, header.size()) + 2);
    out << cell(header, metric_width.back());
  }
  out << '\n';
  for (const PairMetrics& p : c.pairs) {
    out << "  " << left(p.a + " ~ " + p.b, pair_width);
    std::size_t k = 0;
    for (const MetricInfo& info : metricCatalog()) {
      if (!info.pair) continue;
      out << cell(format(metricValue(p, info.name)), metric_width[k++]);
    }
    out << '\n';
  }
}

}  // namespace springcheck
