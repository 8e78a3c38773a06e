#include "compare/studies/comparison.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "compare/io/atomic_file.h"
#include "compare/io/csv.h"
#include "compare/io/run_output.h"
#include "compare/metrics/penetration_metric.h"
#include "compare/metrics/sag_metric.h"

namespace springcheck {

std::expected<Comparison, std::string> compareScene(const EngineRegistry& registry,
                                                    const mysim::Scene& scene,
                                                    const std::vector<std::string>& engines,
                                                    const Timing& timing) {
  Comparison c;
  c.scene = scene;
  c.model = mysim::buildModel(scene);
  for (const std::string& engine : engines) {
    if (auto known = registry.check(engine); !known) return std::unexpected(known.error());
  }
  RunConfig config = runConfig(scene);
  applyTiming(timing, config);
  for (const std::string& engine : engines) {
    auto record = registry.run(engine, c.model, config);
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
  for (const EngineRun& run : c.runs) c.engines.push_back(engineMetrics(scene, c.model, run));
  for (std::size_t i = 0; i < c.runs.size(); ++i) {
    for (std::size_t j = i + 1; j < c.runs.size(); ++j) {
      if (c.runs[i].record.blowup || c.runs[j].record.blowup) continue;
      c.pairs.push_back(pairMetrics(scene, c.model, c.runs[i], c.runs[j]));
    }
  }
  return c;
}

namespace {

std::string format(const std::optional<double>& v) {
  if (!v) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", *v);
  return text;
}

}  // namespace

void printComparison(std::ostream& out, const Comparison& c) {
  out << "scene " << c.scene.name << " (" << c.scene.source << "), dt " << c.scene.dt << " s, "
      << c.scene.duration << " s\n";
  for (const Comparison::Refusal& r : c.refused) out << "  refused: " << r.reason << '\n';
  for (const Comparison::Refusal& r : c.failed) out << "  FAILED: " << r.reason << '\n';
  char line[512];
  std::snprintf(line, sizeof line, "  %-30s", "per engine");
  out << line;
  for (const EngineMetrics& m : c.engines) {
    std::snprintf(line, sizeof line, " %18s", m.engine.c_str());
    out << line;
  }
  out << '\n';
  for (const MetricInfo& info : metricCatalog()) {
    if (info.pair) continue;
    std::snprintf(line, sizeof line, "  %-30s", (info.name + " [" + info.unit + "]").c_str());
    out << line;
    for (const EngineMetrics& m : c.engines) {
      std::snprintf(line, sizeof line, " %18s", format(metricValue(m, info.name)).c_str());
      out << line;
    }
    out << '\n';
  }
  for (const EngineMetrics& m : c.engines) {
    if (m.blew_up) {
      out << "  " << m.engine << ": "
          << (m.status == "blowup" ? "BLOW-UP" : "STOPPED (" + m.status + ")")
          << " at t = " << m.blowup_time << " s\n";
    } else if (m.status != "ok") {
      out << "  " << m.engine << ": " << m.status << "\n";
    }
  }
  if (c.pairs.empty()) return;
  std::snprintf(line, sizeof line, "  %-40s", "per pair");
  out << line;
  for (const MetricInfo& info : metricCatalog()) {
    if (!info.pair) continue;
    std::snprintf(line, sizeof line, " %12s", info.name.substr(0, 12).c_str());
    out << line;
  }
  out << '\n';
  for (const PairMetrics& p : c.pairs) {
    std::snprintf(line, sizeof line, "  %-40s", (p.a + " ~ " + p.b).c_str());
    out << line;
    for (const MetricInfo& info : metricCatalog()) {
      if (!info.pair) continue;
      std::snprintf(line, sizeof line, " %12s", format(metricValue(p, info.name)).c_str());
      out << line;
    }
    out << '\n';
  }
}

namespace {

using nlohmann::json;

json metricsJson(const EngineMetrics& m) {
  json j = {{"engine", m.engine},
            {"steps", m.steps},
            {"wall_seconds", m.wall_seconds},
            {"wall_median_seconds", m.wall_median_seconds},
            {"realtime_factor", m.realtime_factor},
            {"repeats", m.repeats},
            {"threads", m.threads},
            {"external_work", m.external_work},
            {"energy_reference", m.drift.reference}};
  for (const MetricInfo& info : metricCatalog()) {
    if (info.pair) continue;
    const auto v = metricValue(m, info.name);
    j[info.name] = v ? json(*v) : json();
  }
  if (m.closed_form) {
    j["closed_form"] = {{"quantity", m.closed_form->quantity}, {"exact", m.closed_form->exact}};
  }
  j["blowup_time"] = m.blew_up ? json(m.blowup_time) : json();
  j["status"] = m.status;
  return j;
}

json pairJson(const PairMetrics& p) {
  json j = {{"a", p.a}, {"b", p.b}, {"drape_argmax_node", p.drape.argmax}};
  for (const MetricInfo& info : metricCatalog()) {
    if (!info.pair) continue;
    const auto v = metricValue(p, info.name);
    j[info.name] = v ? json(*v) : json();
  }
  return j;
}

std::string safeDirName(std::string engine) {
  for (char& ch : engine) {
    if (ch == ':') ch = '_';
  }
  return engine;
}

// What a reader of the tables needs to know of the model (the report draws the colliders, picks the
// energy view for undamped or damped scenes, and draws cloths as meshes).
json modelJson(const mysim::Model& model) {
  bool spring_damping = false;
  for (const mysim::Spring& s : model.springs) spring_damping |= s.damping > 0.0;
  json j = {{"kind", mysim::systemKindName(model.kind)},
            {"particles", model.particleCount()},
            {"damped", model.drag > 0.0 || spring_damping},
            {"driven", model.wind.has_value() || model.pin_motion.has_value()},
            {"colliders", json::array()},
            {"grid", json()}};
  for (const mysim::Collider& c : model.colliders) j["colliders"].push_back(describeCollider(c));
  if (model.grid) j["grid"] = {{"rows", model.grid->rows}, {"cols", model.grid->cols}};
  return j;
}

}  // namespace

std::expected<void, std::string> writeComparison(const std::string& dir, const Comparison& c) {
  namespace fs = std::filesystem;
  for (const EngineRun& run : c.runs) {
    if (auto w = writeRunOutputs((fs::path(dir) / safeDirName(run.engine)).string(), c.scene,
                                 run.record);
        !w) {
      return w;
    }
  }
  auto in = [&](const char* name) { return (fs::path(dir) / name).string(); };
  // Each file whole or not at all; comparison.json last, so it is never newer than the tables.

  auto done = writeFileAtomically(in("engine_metrics.csv"), [&](std::ostream& engines) {
    engines.precision(10);
    engines << "engine";
    for (const MetricInfo& info : metricCatalog()) {
      if (!info.pair) engines << ',' << info.name;
    }
    engines << ",wall_seconds,wall_median_seconds,realtime_factor,repeats,threads,steps,status\n";
    for (const EngineMetrics& m : c.engines) {
      engines << csvField(m.engine);
      for (const MetricInfo& info : metricCatalog()) {
        if (info.pair) continue;
        const auto v = metricValue(m, info.name);
        engines << ',';
        if (v) engines << *v;
      }
      engines << ',' << m.wall_seconds << ',' << m.wall_median_seconds << ',' << m.realtime_factor
              << ',' << m.repeats << ',' << m.threads << ',' << m.steps << ',' << m.status << '\n';
    }
  });
  if (!done) return done;

  done = writeFileAtomically(in("pair_metrics.csv"), [&](std::ostream& pairs) {
    pairs.precision(10);
    pairs << "a,b";
    for (const MetricInfo& info : metricCatalog()) {
      if (info.pair) pairs << ',' << info.name;
    }
    pairs << '\n';
    for (const PairMetrics& p : c.pairs) {
      pairs << csvField(p.a) << ',' << csvField(p.b);
      for (const MetricInfo& info : metricCatalog()) {
        if (!info.pair) continue;
        const auto v = metricValue(p, info.name);
        pairs << ',';
        if (v) pairs << *v;
      }
      pairs << '\n';
    }
  });
  if (!done) return done;

  // Per-node distance of every run's final shape to the first run's (for drape colour maps).
  done = writeFileAtomically(in("node_distance.csv"), [&](std::ostream& nodes) {
    nodes.precision(10);
    nodes << "engine,reference_engine,node,distance\n";
    for (std::size_t r = 1; r < c.runs.size() && !c.runs.empty(); ++r) {
      if (c.runs[0].record.blowup || c.runs[r].record.blowup) continue;
      const mysim::ParticleRows& a = c.runs[0].record.frames.back();
      const mysim::ParticleRows& b = c.runs[r].record.frames.back();
      for (int i = 0; i < a.rows(); ++i) {
        nodes << csvField(c.runs[r].engine) << ',' << csvField(c.runs[0].engine) << ',' << i << ','
              << (a.row(i).head<3>() - b.row(i).head<3>()).norm() << '\n';
      }
    }
  });
  if (!done) return done;

  done = writeFileAtomically(in("series.csv"), [&](std::ostream& series) {
    series.precision(10);
    series << "engine,t,sag_lowest,sag_free_middle,penetration_deepest,energy_drift_total\n";
    for (std::size_t r = 0; r < c.runs.size(); ++r) {
      const mysim::RunRecord& rec = c.runs[r].record;
      if (c.model.isCircle()) continue;
      const SagSeries sag = sagOverTime(c.model, rec);
      const EnergyDrift& drift = c.engines[r].drift;
      for (std::size_t f = 0; f < rec.frames.size(); ++f) {
        series << csvField(c.runs[r].engine) << ',' << rec.times[f] << ',' << sag.lowest[f] << ',';
        if (!sag.free_middle.empty()) series << sag.free_middle[f];
        series << ',';
        if (!c.model.colliders.empty()) series << penetration(c.model.colliders, rec.frames[f]).deepest;
        series << ',';
        if (f < drift.total.size()) series << drift.total[f];
        series << '\n';
      }
    }
  });
  if (!done) return done;

  json j = {{"scene", c.scene.name},    {"scene_file", c.scene.source},
            {"dt", c.scene.dt},         {"duration", c.scene.duration},
            {"refused", json::array()}, {"failed", json::array()},
            {"engines", json::array()}, {"pairs", json::array()}};
  for (const Comparison::Refusal& r : c.failed) {
    j["failed"].push_back({{"engine", r.engine}, {"reason", r.reason}});
  }
  for (const Comparison::Refusal& r : c.refused) {
    j["refused"].push_back({{"engine", r.engine}, {"reason", r.reason}});
  }
  j["model"] = modelJson(c.model);
  for (std::size_t r = 0; r < c.engines.size(); ++r) {
    json e = metricsJson(c.engines[r]);
    // Where its run files are, and what stepped it (the scene's integrator for plain "mysim").
    e["folder"] = safeDirName(c.engines[r].engine);
    if (r < c.runs.size()) e["integrator"] = c.runs[r].record.integrator;
    j["engines"].push_back(e);
  }
  for (const PairMetrics& p : c.pairs) j["pairs"].push_back(pairJson(p));
  return writeFileAtomically(in("comparison.json"),
                             [&](std::ostream& out) { out << j.dump(2) << '\n'; });
}

}  // namespace springcheck
