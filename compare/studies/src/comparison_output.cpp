// The files of a comparison: each run's own files, one table per concern and comparison.json,
// each written whole or not at all, from metrics computed once (compareScene).
#include <map>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "compare/io/atomic_file.h"
#include "compare/io/invocation.h"
#include "compare/io/whole_folder.h"
#include "compare/io/csv.h"
#include "compare/io/run_output.h"
#include "compare/studies/comparison.h"

namespace springcheck {
namespace {

using nlohmann::json;

json metricsJson(const EngineMetrics& m) {
  json j = {{"engine", m.engine},
            {"steps", m.steps},
            {"wall_seconds", m.wall_seconds},
            {"wall_median_seconds", m.wall_median_seconds},
            {"realtime_factor", m.realtime_factor},
            {"repeats", m.repeats},
            {"threads", m.threads > 0 ? json(m.threads) : json()},  // 0: unknown (external)
            {"external_work", m.external_work},
            {"energy_reference", m.drift.reference}};
  for (const MetricInfo& info : metricCatalog()) {
    if (info.pair) continue;
    const auto v = metricValue(m, info.name);
    j[info.name] = v ? json(*v) : json();
  }
  if (m.closed_form) {
    j["closed_form"] = {{"quantity", m.closed_form->quantity},
                        {"exact", m.closed_form->exact},
                        {"unit", m.closed_form->unit}};
    if (m.closed_form->motion_left) {
      j["closed_form"]["motion_left"] = *m.closed_form->motion_left;
      j["closed_form"]["at_motion_floor"] = m.closed_form->atMotionFloor();
    }
  } else {
    j["no_closed_form"] = m.no_closed_form;
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

// A collider as the report draws it: its description and its surface's quads (an endless shape
// under the cloth's start: `drawing`), so the report names no shape.
json colliderJson(const mysim::Collider& c, const mysim::SurfaceDrawing& drawing) {
  const mysim::SurfaceMesh mesh = mysim::surfaceMesh(c, drawing);
  json j = describeCollider(c);
  j["surface"] = {{"points", json::array()}, {"quads", mesh.quads}};
  for (const mysim::Vec3& p : mesh.points) j["surface"]["points"].push_back({p.x(), p.y(), p.z()});
  return j;
}

// What a reader of the tables needs to know of the model (the report draws the colliders, picks the
// energy view for undamped or damped scenes, and draws cloths as meshes).
json modelJson(const mysim::Model& model) {
  bool spring_damping = false;
  for (const mysim::Spring& s : model.springs) spring_damping |= s.damping > 0.0;
  // Damped: something takes energy out by physics, so its drift is not a conservation check.
  // Contact does: every collider and self-collision remove the approaching normal velocity
  // (inelastic), and friction more.
  const bool contact = !model.colliders.empty() || model.self_collision_thickness.has_value();
  json j = {{"kind", model.kind},
            {"particles", model.particleCount()},
            {"damped", model.drag > 0.0 || spring_damping || contact},
            {"driven", model.wind.has_value() || model.pin_motion.has_value()},
            {"colliders", json::array()},
            {"grid", json()}};
  const mysim::SurfaceDrawing drawing = mysim::drawingAround(
      Eigen::Map<const Eigen::Matrix3Xd>(model.start_position.data(), 3, model.start_position.size() / 3), 0.0);
  for (const mysim::Collider& c : model.colliders) j["colliders"].push_back(colliderJson(c, drawing));
  if (model.grid) j["grid"] = {{"rows", model.grid->rows}, {"cols", model.grid->cols}};
  if (model.self_collision_thickness) j["self_collision"] = {{"thickness", *model.self_collision_thickness}};
  return j;
}

using Write = std::expected<void, std::string>;

// engine_metrics.csv: every single-run metric of the catalogue, then the timing columns.
Write writeEngineTable(const std::string& path, const Comparison& c) {
  return writeFileAtomically(path, [&](std::ostream& engines) {
    engines.precision(10);
    engines << "engine";
    for (const MetricInfo& info : metricCatalog()) {
      if (!info.pair) engines << ',' << info.name;
    }
    engines << ",wall_seconds,wall_median_seconds,realtime_factor,repeats,threads,steps,status,"
               "no_closed_form\n";
    for (const EngineMetrics& m : c.engines) {
      engines << csvField(m.engine);
      for (const MetricInfo& info : metricCatalog()) {
        if (info.pair) continue;
        const auto v = metricValue(m, info.name);
        engines << ',';
        if (v) engines << *v;
      }
      engines << ',' << m.wall_seconds << ',' << m.wall_median_seconds << ',' << m.realtime_factor
              << ',' << m.repeats << ',' << (m.threads > 0 ? std::to_string(m.threads) : "") << ','
              << m.steps << ',' << m.status << ',' << csvField(m.no_closed_form) << '\n';
    }
  });
}

// pair_metrics.csv: every pair metric of the catalogue.
Write writePairTable(const std::string& path, const Comparison& c) {
  return writeFileAtomically(path, [&](std::ostream& pairs) {
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
}

// node_distance.csv: per-node distance of every run's final shape to the first run's (for the
// drape colour maps), as the pair metrics measured it.
Write writeNodeDistances(const std::string& path, const Comparison& c) {
  return writeFileAtomically(path, [&](std::ostream& nodes) {
    nodes.precision(10);
    nodes << "engine,reference_engine,node,distance\n";
    if (c.runs.empty()) return;
    for (const PairMetrics& p : c.pairs) {
      if (p.a != c.runs[0].engine) continue;
      for (std::size_t i = 0; i < p.drape.per_node.size(); ++i) {
        nodes << csvField(p.b) << ',' << csvField(p.a) << ',' << i << ',' << p.drape.per_node[i]
              << '\n';
      }
    }
  });
}

// series.csv: per frame and engine, sag of the lowest point and the free edge, deepest
// penetration and total energy drift.
Write writeSeries(const std::string& path, const Comparison& c) {
  return writeFileAtomically(path, [&](std::ostream& series) {
    series.precision(10);
    series << "engine,t,sag_lowest,sag_free_middle,penetration_deepest,energy_drift_total,"
              "energy_drift_vs_reference\n";
    if (c.model.isCircle()) return;
    const mysim::RunRecord* ref =
        c.energy_reference ? &c.runs[*c.energy_reference].record : nullptr;
    const EnergyDrift* ref_drift =
        c.energy_reference ? &c.engines[*c.energy_reference].drift : nullptr;
    for (std::size_t r = 0; r < c.runs.size(); ++r) {
      const mysim::RunRecord& rec = c.runs[r].record;
      const EngineMetrics& m = c.engines[r];
      for (std::size_t f = 0, g = 0; f < rec.frames.size(); ++f) {
        series << csvField(c.runs[r].engine) << ',' << rec.times[f] << ',' << m.sag.lowest[f]
               << ',';
        if (!m.sag.free_middle.empty()) series << m.sag.free_middle[f];
        series << ',';
        if (!m.penetration_deepest.empty()) series << m.penetration_deepest[f];
        series << ',';
        if (f < m.drift.total.size()) series << m.drift.total[f];
        series << ',';
        // |drift - the reference's drift| at the times both sampled (not for the reference).
        while (ref && g < ref->times.size() && ref->times[g] < rec.times[f]) ++g;
        if (ref && r != *c.energy_reference && g < ref->times.size() &&
            ref->times[g] == rec.times[f] && f < m.drift.total.size() &&
            g < ref_drift->total.size()) {
          series << std::abs(m.drift.total[f] - ref_drift->total[g]);
        }
        series << '\n';
      }
    }
  });
}

json comparisonJson(const Comparison& c) {
  json j = {{"scene", c.config.scene_name}, {"scene_file", c.config.source},
            {"dt", c.config.run.dt},        {"duration", c.config.run.duration},
            {"refused", json::array()},     {"failed", json::array()},
            {"engines", json::array()},     {"pairs", json::array()}};
  for (const Comparison::Refusal& r : c.failed) {
    j["failed"].push_back({{"engine", r.engine}, {"reason", r.reason}});
  }
  for (const Comparison::Refusal& r : c.refused) {
    j["refused"].push_back({{"engine", r.engine}, {"reason", r.reason}});
  }
  j["model"] = modelJson(c.model);
  // The command that made it (the report prints it under its figures); null from the library.
  j["command"] = invocation().empty() ? json() : json(invocation());
  j["energy_reference"] = c.energy_reference ? json(c.runs[*c.energy_reference].engine) : json();
  j["jobs"] = c.jobs;
  for (std::size_t r = 0; r < c.engines.size(); ++r) {
    json e = metricsJson(c.engines[r]);
    // Where its run files are, and what stepped it (the scene's integrator for plain "mysim").
    e["folder"] = safeDirName(c.engines[r].engine);
    if (r < c.runs.size()) e["integrator"] = c.runs[r].record.integrator;
    j["engines"].push_back(e);
  }
  for (const PairMetrics& p : c.pairs) j["pairs"].push_back(pairJson(p));
  return j;
}

}  // namespace

std::expected<void, std::string> writeComparison(const std::string& out, const Comparison& c,
                                                 const RunFileOptions& files) {
  namespace fs = std::filesystem;
  // Two engines whose names map to one folder (mysim:backward-euler, mysim_backward-euler) would
  // write one over the other.
  std::map<std::string, std::string> folders;
  for (const EngineRun& run : c.runs) {
    auto [at, fresh] = folders.emplace(safeDirName(run.engine), run.engine);
    if (!fresh) {
      return std::unexpected("engines '" + at->second + "' and '" + run.engine +
                             "' would share the folder " + at->first + " in " + out +
                             ": compare them in two runs");
    }
  }
  // The whole folder at once: an engine that failed this time leaves no folder of an earlier run.
  return writeFolderWhole(out, comparisonFolderKind(), [&](const std::string& dir) {
    return writeComparisonFiles(dir, c, files);
  });
}

std::expected<void, std::string> writeComparisonFiles(const std::string& dir, const Comparison& c,
                                                      const RunFileOptions& files) {
  namespace fs = std::filesystem;
  for (const EngineRun& run : c.runs) {
    const std::string folder = (fs::path(dir) / safeDirName(run.engine)).string();
    if (auto w = writeRunFiles(folder, c.model, c.config.scene_name, c.config.source, run.record,
                               files);
        !w) {
      return w;
    }
  }
  auto in = [&](const char* name) { return (fs::path(dir) / name).string(); };
  // comparison.json last, so it is never newer than the tables.
  for (auto [name, write] : {std::pair{"engine_metrics.csv", &writeEngineTable},
                             std::pair{"pair_metrics.csv", &writePairTable},
                             std::pair{"node_distance.csv", &writeNodeDistances},
                             std::pair{"series.csv", &writeSeries}}) {
    if (auto done = write(in(name), c); !done) return done;
  }
  const json j = comparisonJson(c);
  return writeFileAtomically(in("comparison.json"),
                             [&](std::ostream& out) { out << jsonText(j, 2) << '\n'; });
}

}  // namespace springcheck
