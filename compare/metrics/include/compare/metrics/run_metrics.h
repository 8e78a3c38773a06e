#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compare/metrics/cantilever_metric.h"
#include "compare/metrics/closed_form.h"
#include "compare/metrics/drape_test_metric.h"
#include "compare/metrics/drape_metric.h"
#include "compare/metrics/energy_metric.h"
#include "compare/metrics/momentum_metric.h"
#include "compare/metrics/sag_metric.h"
#include "compare/metrics/self_contact_metric.h"
#include "compare/metrics/surface_distance.h"
#include "mysim/scene.h"
#include "mysim/simulation.h"

namespace springcheck {

// One engine's run of a scene. `engine` is the spec it was run as: "mysim" (the scene's
// integrator), "mysim:INTEGRATOR", or a Bullet engine name.
struct EngineRun {
  std::string engine;
  mysim::RunRecord record;
};

// Every single-run metric of one engine on one scene.
struct EngineMetrics {
  std::string engine;
  bool blew_up = false;  // the run stopped early (a blow-up or an adaptive step limit)
  std::string status;    // RunRecord::status()
  double blowup_time = 0.0;
  double wall_seconds = 0.0;  // the fastest of `repeats` runs; threads: the most it used
  double wall_median_seconds = 0.0;
  double realtime_factor = 0.0;  // simulated s per wall s
  int repeats = 1;
  int threads = 1;
  long steps = 0;
  double sag_lowest = 0.0;                  // m below the pins, last frame
  std::optional<double> sag_free_middle;    // m, last frame
  // A clamped material strip (cantilever_metric.h), last frame: the free end's drop below the
  // clamp's edge, the chord's angle, the bending length that chord reads.
  std::optional<double> tip_drop, chord_angle, bending_length;
  // A mesh cloth pinned in its middle (drape_test_metric.h), last frame.
  std::optional<double> drape_coefficient, drape_folds;
  SagSeries sag;                            // per frame (empty for the circle)
  std::vector<double> penetration_deepest;  // m, per frame (empty without colliders)
  std::optional<ClosedFormError> closed_form;
  std::string no_closed_form;  // without closed_form: why the run has none
  double penetration_max = 0.0;         // m, deepest over all frames (0 without colliders)
  double penetration_mean_max = 0.0;    // m, largest per-frame mean depth
  int penetration_count_max = 0;        // most nodes inside in any frame
  EnergyDrift drift;                    // per frame
  bool external_work = false;           // wind or driven pins: energy may rise on purpose
  std::optional<double> settling_time;  // s
  double max_strain = 0.0;
  std::optional<MomentumDrift> momentum;  // where the model conserves momentum
  std::optional<SelfContact> self_contact;  // cloths and chains (self_contact_metric.h)
};

// How far two engines' runs of the same scene are apart.
struct PairMetrics {
  std::string a, b;
  NodeDistance drape;           // last frames, node i against node i
  // Where the scene has a plane of mirror symmetry (mirror_symmetry.h): the last frames, a
  // against b's mirror image. A fold that buckled the other way is round-off apart here.
  std::optional<NodeDistance> drape_mirrored;
  // Whether the shapes are mirror images: the mirrored distance under half the direct one (a fold
  // that flipped). On a shape that is itself nearly symmetric the two differ only by its small
  // asymmetries, and the direct distance stays the answer.
  bool mirrorCloser() const { return drape_mirrored && drape_mirrored->max < 0.5 * drape.max; }
  // The direct max distance, or the mirrored one where the shapes are mirror images.
  double drapeMirrorAware() const { return mirrorCloser() ? drape_mirrored->max : drape.max; }
  SurfaceDistance surface;      // last frames, topology-free
  double sag_difference = 0.0;  // |sag_lowest(a) - sag_lowest(b)|, m
  // Max over the frames both sampled of the per-frame RMS node distance.
  std::optional<double> trajectory_rms_max;
};

// Max over frames and last frame of the RMS node distance between two runs, over the times both
// sampled (nothing when they share none).
struct TrajectoryDistance {
  double max_rms = 0.0;
  double last_rms = 0.0;
};
std::optional<TrajectoryDistance> trajectoryDistance(const mysim::RunRecord& a,
                                                     const mysim::RunRecord& b);

// Every metric of one run, or of a pair, each computed once (from the model the runs were made
// of; the scene stops at the model builder).
EngineMetrics engineMetrics(const mysim::Model& model, const EngineRun& run);
// `ma`, `mb`: the runs' own metrics, so nothing of a single run is computed again.
PairMetrics pairMetrics(const mysim::Model& model, const EngineRun& a, const EngineRun& b,
                        const EngineMetrics& ma, const EngineMetrics& mb);

// The surface of a model's shape in a frame: grid triangles for a cloth, one degenerate
// triangle per spring otherwise.
Surface surfaceOf(const mysim::Model& model, const mysim::ParticleRows& frame);

// Metrics by name, for tolerance files and tables.
// One row per metric: its name (what tolerance files and tables call it), unit, meaning, and
// where its value is read from what engineMetrics / pairMetrics computed (one of the two).
struct MetricInfo {
  std::string name;
  bool pair;  // a metric between two engines, else of one
  std::string unit;
  std::string description;
  std::function<std::optional<double>(const EngineMetrics&)> of_run = nullptr;
  std::function<std::optional<double>(const PairMetrics&)> of_pair = nullptr;
  // A measurement of the settled shape that `springcheck refine` follows across resolutions.
  bool refined = false;
  // A count (a drape's folds): a whole number, which converges by settling on a value, never
  // at an order.
  bool count = false;
};
const std::vector<MetricInfo>& metricCatalog();
const MetricInfo* findMetric(std::string_view name);
std::optional<double> metricValue(const EngineMetrics& m, std::string_view name);
std::optional<double> metricValue(const PairMetrics& m, std::string_view name);

}  // namespace springcheck
