#include "compare/metrics/run_metrics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "compare/metrics/mirror_symmetry.h"
#include "compare/metrics/penetration_metric.h"
#include "compare/metrics/sag_metric.h"
#include "compare/metrics/settling_metric.h"
#include "mysim/cloth_surface.h"

namespace springcheck {

EngineMetrics engineMetrics(const mysim::Model& model, const EngineRun& run) {
  const mysim::RunRecord& r = run.record;
  EngineMetrics m;
  m.engine = run.engine;
  m.blew_up = r.blowup.has_value();
  m.status = r.status();
  m.blowup_time = r.blowup ? r.blowup->time : 0.0;
  m.wall_seconds = r.wall_seconds;
  m.wall_median_seconds = r.wall_median_seconds;
  m.realtime_factor = r.realtimeFactor();
  m.repeats = r.repeats;
  m.threads = r.threads;
  m.steps = r.steps;
  if (ClosedFormResult closed = closedFormError(model, r)) {
    m.closed_form = *closed;
  } else {
    m.no_closed_form = closed.error();
  }
  m.drift = energyDrift(r.energies);
  m.external_work = model.wind.has_value() || model.pin_motion.has_value();
  if (model.isCircle()) return m;

  m.sag = sagOverTime(model, r);
  m.sag_lowest = m.sag.lowest.back();
  if (!m.sag.free_middle.empty()) m.sag_free_middle = m.sag.free_middle.back();
  if (!model.colliders.empty()) {
    for (const Penetration& p : penetrationOverTime(model.colliders, r)) {
      m.penetration_deepest.push_back(p.deepest);
      m.penetration_max = std::max(m.penetration_max, p.deepest);
      m.penetration_mean_max = std::max(m.penetration_mean_max, p.mean_depth);
      m.penetration_count_max = std::max(m.penetration_count_max, p.count);
    }
  }
  // Shape measurements of the settled state: none for a run that stopped early (its last frame
  // is only the last healthy one).
  if (!r.frames.empty() && !r.blowup) {
    if (auto reading = readCantilever(model, r.frames.back())) {
      m.tip_drop = reading->drop;
      m.chord_angle = reading->chord_angle * 180.0 / std::numbers::pi;
      if (reading->chord_bending_length > 0.0) m.bending_length = reading->chord_bending_length;
    }
    if (auto drape = readDrapeTest(model, r.frames.back())) {
      m.drape_coefficient = drape->drape_coefficient;
      m.drape_folds = drape->folds;
    }
  }
  m.settling_time = settlingTime(r);
  m.max_strain = maxStrainOverRun(model, r);
  m.momentum = momentumDrift(model, r);
  m.self_contact = selfContactOverRun(model, r);
  return m;
}

Surface surfaceOf(const mysim::Model& model, const mysim::ParticleRows& frame) {
  Surface s{frame.leftCols<3>(), {}};
  if (model.grid || !model.mesh_triangles.empty()) {
    s.triangles = mysim::clothTriangles(model);
  } else {
    for (const mysim::Spring& sp : model.springs) s.triangles.emplace_back(sp.i, sp.j, sp.j);
    if (s.triangles.empty()) {
      for (int p = 0; p < frame.rows(); ++p) s.triangles.emplace_back(p, p, p);
    }
  }
  return s;
}

PairMetrics pairMetrics(const mysim::Model& model, const EngineRun& a, const EngineRun& b,
                        const EngineMetrics& ma, const EngineMetrics& mb) {
  PairMetrics m;
  m.a = a.engine;
  m.b = b.engine;
  const mysim::ParticleRows& fa = a.record.frames.back();
  const mysim::ParticleRows& fb = b.record.frames.back();
  m.drape = nodeDistance(fa.leftCols<3>(), fb.leftCols<3>());
  if (const auto mirror = mirrorSymmetry(model)) {
    m.drape_mirrored = nodeDistance(fa.leftCols<3>(), mirrored(*mirror, fb.leftCols<3>()));
  }
  if (!model.isCircle()) {
    m.surface = surfaceDistance(surfaceOf(model, fa), surfaceOf(model, fb));
    m.sag_difference = std::abs(ma.sag_lowest - mb.sag_lowest);
  }
  if (auto d = trajectoryDistance(a.record, b.record)) m.trajectory_rms_max = d->max_rms;
  return m;
}

std::optional<TrajectoryDistance> trajectoryDistance(const mysim::RunRecord& a,
                                                     const mysim::RunRecord& b) {
  // Frames at the times both runs sampled (runs whose durations are not whole multiples of their
  // steps end at different times and add a last frame of their own: those are skipped).
  const auto& ta = a.times;
  const auto& tb = b.times;
  auto same = [](double x, double y) {
    return std::abs(x - y) <= 1e-9 * std::max(1.0, std::abs(x));
  };
  TrajectoryDistance d;
  bool any = false;
  for (std::size_t i = 0, j = 0; i < ta.size() && j < tb.size();) {
    if (same(ta[i], tb[j])) {
      d.last_rms = nodeDistance(a.frames[i].leftCols<3>(), b.frames[j].leftCols<3>()).rms;
      d.max_rms = std::max(d.max_rms, d.last_rms);
      any = true;
      ++i;
      ++j;
    } else if (ta[i] < tb[j]) {
      ++i;
    } else {
      ++j;
    }
  }
  if (!any) return std::nullopt;
  return d;
}

namespace {

using E = const EngineMetrics&;
using V = std::optional<double>;

// Contact: penetration of colliders, and the mesh against itself.
std::vector<MetricInfo> contactMetrics() {
  return {
      // Undefined without a collider: 0 there would pass any bound for nothing measured.
      {"penetration_max", false, "m", "deepest node inside a collider, any frame",
       [](E m) { return m.penetration_deepest.empty() ? V() : V(m.penetration_max); }},
      {"penetration_mean_max", false, "m", "largest per-frame mean depth of penetrating nodes",
       [](E m) { return m.penetration_deepest.empty() ? V() : V(m.penetration_mean_max); }},
      {"self_intersections", false, "1",
       "most pairs of a cloth's triangles (sharing no vertex) that cross, in any frame",
       [](E m) { return m.self_contact && m.self_contact->intersections ? V(*m.self_contact->intersections) : V(); },
       nullptr, false, true},
      {"self_intersections_time", false, "s", "the first frame with that many",
       [](E m) { return m.self_contact && m.self_contact->intersections ? V(m.self_contact->intersections_time) : V(); }},
      {"self_distance_min", false, "m",
       "smallest distance of a node to a triangle not around it (a chain: of two links sharing no "
       "node), any frame",
       [](E m) { return m.self_contact ? m.self_contact->distance_min : V(); }},
      {"self_distance_min_time", false, "s", "when it was smallest",
       [](E m) { return m.self_contact && m.self_contact->distance_min ? V(m.self_contact->distance_time) : V(); }},
  };
}

// What a run's final shape reads: sag, a clamped strip's bend, a drape.
std::vector<MetricInfo> shapeMetrics() {
  return {
    {"blowup", false, "1/0", "1 if the run blew up",
     [](E m) { return V(m.blew_up ? 1.0 : 0.0); }},
    {"closed_form_error", false, "m or rel", "error against the scene's closed form",
     [](E m) { return m.closed_form ? V(m.closed_form->error) : V(); }},
    {"sag_lowest", false, "m", "lowest point below the pins at the end",
     [](E m) { return V(m.sag_lowest); }, nullptr, true},
    {"tip_drop", false, "m", "a clamped strip's free end below the clamp's edge at the end",
     [](E m) { return m.tip_drop; }, nullptr, true},
    {"chord_angle", false, "deg", "a clamped strip's chord from clamp edge to tip, below level",
     [](E m) { return m.chord_angle; }, nullptr, true},
    {"bending_length", false, "m",
     "the bending length a clamped strip's chord reads (the standard's l/2 at 41.5 deg)",
     [](E m) { return m.bending_length; }, nullptr, true},
    {"drape_coefficient", false, "1",
     "Cusick drape coefficient (A_shadow - A_support) / (A_specimen - A_support) at the end",
     [](E m) { return m.drape_coefficient; }, nullptr, true},
    {"drape_folds", false, "1", "folds (lobes) of a draped disc's outline at the end",
     [](E m) { return m.drape_folds; }, nullptr, true, true},
    {"sag_free_middle", false, "m", "middle of the free edge below the pins at the end",
     [](E m) { return m.sag_free_middle; }}};
}

// Energy, strain and momentum over the run.
std::vector<MetricInfo> driftMetrics() {
  return {
    {"energy_drift_max", false, "rel", "max |E(t) - E(0)| / E_ref",
     [](E m) { return m.drift.total.empty() ? V() : V(m.drift.max_abs_total); }},
    {"energy_rise", false, "J", "largest rise of total energy above an earlier low",
     [](E m) { return m.drift.total.empty() ? V() : V(m.drift.max_rise); }},
    {"settling_time", false, "s", "time after which KE stays below 1e-4 of its peak",
     [](E m) { return m.settling_time; }},
    {"max_strain", false, "rel", "largest |l / rest - 1| of any spring, any frame",
     [](E m) { return V(m.max_strain); }},
    {"linear_momentum_drift", false, "rel",
     "max |P(t) - P(0) - M g t| / max sum m|v| (free bodies only)",
     [](E m) { return m.momentum ? V(m.momentum->linear) : V(); }},
    {"angular_momentum_drift", false, "rel",
     "max |L(t) - L(0)| about the centre of mass / its scale (free bodies only)",
     [](E m) { return m.momentum ? V(m.momentum->angular) : V(); }}};
}

// Of a pair of runs: how far apart their shapes and trajectories are.
std::vector<MetricInfo> pairMetrics() {
  using P = const PairMetrics&;
  return {
    {"drape_rms", true, "m", "RMS per-node distance of the final shapes", nullptr,
     [](P m) { return V(m.drape.rms); }},
    {"drape_max", true, "m", "max per-node distance of the final shapes", nullptr,
     [](P m) { return V(m.drape.max); }},
    {"drape_max_mirror_aware", true, "m",
     "drape_max, or the distance to the other's mirror image across the scene's plane of "
     "symmetry where that is under half of it (a fold buckled the other way)",
     nullptr, [](P m) { return V(m.drapeMirrorAware()); }},
    {"drape_mirrored", true, "1/0",
     "1 if drape_max_mirror_aware is the mirrored distance; empty without a symmetry plane",
     nullptr, [](P m) { return m.drape_mirrored ? V(m.mirrorCloser() ? 1.0 : 0.0) : V(); }},
    {"chamfer", true, "m", "symmetric Chamfer distance of the final surfaces", nullptr,
     [](P m) { return V(m.surface.chamfer); }},
    {"hausdorff", true, "m", "Hausdorff distance of the final surfaces", nullptr,
     [](P m) { return V(m.surface.hausdorff); }},
    {"sag_difference", true, "m", "difference of the final lowest-point sag", nullptr,
     [](P m) { return V(m.sag_difference); }},
    {"trajectory_rms_max", true, "m", "max over frames of the RMS node distance", nullptr,
     [](P m) { return m.trajectory_rms_max; }}};
}

}  // namespace

const std::vector<MetricInfo>& metricCatalog() {
  static const std::vector<MetricInfo> catalog = [] {
    std::vector<MetricInfo> rows;
    for (auto part : {shapeMetrics, contactMetrics, driftMetrics, pairMetrics}) {
      const std::vector<MetricInfo> more = part();
      rows.insert(rows.end(), more.begin(), more.end());
    }
    return rows;
  }();
  return catalog;
}

const MetricInfo* findMetric(std::string_view name) {
  for (const MetricInfo& info : metricCatalog()) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

std::optional<double> metricValue(const EngineMetrics& m, std::string_view name) {
  const MetricInfo* info = findMetric(name);
  return info && info->of_run ? info->of_run(m) : std::nullopt;
}

std::optional<double> metricValue(const PairMetrics& m, std::string_view name) {
  const MetricInfo* info = findMetric(name);
  return info && info->of_pair ? info->of_pair(m) : std::nullopt;
}

}  // namespace springcheck
