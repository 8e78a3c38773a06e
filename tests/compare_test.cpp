// Every comparison metric on a hand-made case whose answer is known.
// ctest-label: unit
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "compare/engines/engine_registry.h"
#include "compare/io/report_headlines.h"
#include "compare/metrics/closed_form.h"
#include "compare/metrics/mirror_symmetry.h"
#include "compare/metrics/drape_metric.h"
#include "compare/metrics/energy_metric.h"
#include "compare/metrics/penetration_metric.h"
#include "compare/metrics/run_metrics.h"
#include "compare/metrics/sag_metric.h"
#include "compare/metrics/settling_metric.h"
#include "compare/metrics/surface_distance.h"
#include "mysim/cloth.h"
#include "mysim/cloth_surface.h"
#include "mysim/scene_file.h"
#include "source_root.h"

namespace springcheck {
namespace {

using Eigen::Vector3d;

TEST(DrapeMetric, NodeDistanceRmsMaxAndWhere) {
  Positions a(3, 3), b(3, 3);
  a << 0, 0, 0, 1, 0, 0, 2, 0, 0;
  b << 0, 0, 0, 1, 3, 0, 2, 0, 4;  // node 1 off by 3, node 2 by 4
  const NodeDistance d = nodeDistance(a, b);
  EXPECT_DOUBLE_EQ(d.max, 4.0);
  EXPECT_EQ(d.argmax, 2);
  EXPECT_DOUBLE_EQ(d.rms, std::sqrt((9.0 + 16.0) / 3));
}

TEST(SurfaceDistance, PointTriangleDistanceInsideOnEdgeAtVertexAndDegenerate) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_DOUBLE_EQ(pointTriangleDistance({0.2, 0.2, 0.5}, a, b, c), 0.5);  // above the face
  EXPECT_DOUBLE_EQ(pointTriangleDistance({0.5, -2, 0}, a, b, c), 2.0);     // beside edge ab
  EXPECT_DOUBLE_EQ(pointTriangleDistance({-3, -4, 0}, a, b, c), 5.0);      // nearest vertex a
  EXPECT_DOUBLE_EQ(pointTriangleDistance({0.5, 1, 0}, a, b, b), 1.0);      // a segment
  EXPECT_DOUBLE_EQ(pointTriangleDistance({0, 0, 2}, a, a, a), 2.0);        // a point
}

Surface flatSheet(int n, double height) {
  mysim::ClothShape shape;
  shape.rows = shape.cols = n;
  mysim::Model model;
  mysim::buildCloth(shape, model);  // 1 m square in the x-z plane
  Surface s;
  s.vertices.resize(n * n, 3);
  for (int p = 0; p < n * n; ++p)
    s.vertices.row(p) = model.start_position.segment<3>(3 * p).transpose();
  s.vertices.col(1).array() += height;
  s.triangles = mysim::gridTriangles(*model.grid);
  return s;
}

TEST(SurfaceDistance, CoarseAndFineSheetsOfOneSquareAreZeroApartAndOffsetsAreExact) {
  // 8 and 32 nodes a side (16 and 64 took 11 s under the sanitizers: every vertex against every
  // triangle; the plane is the same at any count).
  const SurfaceDistance same = surfaceDistance(flatSheet(8, 0.0), flatSheet(32, 0.0));
  EXPECT_LT(same.hausdorff, 1e-12);  // every vertex of either lies on the other's plane square
  const SurfaceDistance lifted = surfaceDistance(flatSheet(8, 0.0), flatSheet(32, 0.03));
  EXPECT_NEAR(lifted.chamfer, 0.03, 1e-12);
  EXPECT_NEAR(lifted.hausdorff, 0.03, 1e-12);
}

TEST(SagMetric, LowestPointAndFreeEdgeMiddleBelowThePins) {
  // 2 x 3 cloth, top corners pinned at y = 0; bottom row at y = -1, -1.5, -1.2.
  mysim::Model model;
  mysim::ClothShape shape;
  shape.rows = 2;
  shape.cols = 3;
  mysim::buildCloth(shape, model);
  model.pinned[0] = model.pinned[2] = 1;
  model.gravity = mysim::Vec3(0, -9.8, 0);
  mysim::RunRecord run;
  mysim::ParticleRows frame = mysim::ParticleRows::Zero(6, 6);
  frame(3, 1) = -1.0;
  frame(4, 1) = -1.5;
  frame(5, 1) = -1.2;
  run.frames = {frame};
  const SagSeries sag = sagOverTime(model, run);
  EXPECT_DOUBLE_EQ(sag.lowest[0], 1.5);
  EXPECT_DOUBLE_EQ(sag.free_middle[0], 1.5);  // odd column count: the middle node itself
}

TEST(PenetrationMetric, DeepestMeanAndCountOfNodesInside) {
  const mysim::Sphere sphere{mysim::Vec3::Zero(), 1.0, 0.0};
  mysim::ParticleRows frame = mysim::ParticleRows::Zero(3, 6);
  frame.row(0).head<3>() << 0.9, 0, 0;  // 0.1 inside
  frame.row(1).head<3>() << 0, 0.7, 0;  // 0.3 inside
  frame.row(2).head<3>() << 0, 0, 2;    // outside
  const Penetration p = penetration({sphere}, frame);
  EXPECT_EQ(p.count, 2);
  EXPECT_NEAR(p.deepest, 0.3, 1e-15);
  EXPECT_NEAR(p.mean_depth, 0.2, 1e-15);
}

TEST(EnergyMetric, DriftPerTermAndLargestRiseAboveAnEarlierLow) {
  std::vector<mysim::EnergyTerms> e = {{0, 0, 0}, {2, -3, 0}, {1, -4, 0.5}, {0.5, -3.5, 1.5}};
  // totals: 0, -1, -2.5, -1.5; peak kinetic 2 -> E_ref = 2.
  const EnergyDrift d = energyDrift(e);
  EXPECT_DOUBLE_EQ(d.reference, 2.0);
  EXPECT_DOUBLE_EQ(d.total[2], -1.25);
  EXPECT_DOUBLE_EQ(d.kinetic[1], 1.0);
  EXPECT_DOUBLE_EQ(d.max_abs_total, 1.25);
  EXPECT_DOUBLE_EQ(d.max_rise, 1.0);  // from -2.5 back up to -1.5
}

// The circle's energy is its mechanical twin's (r^2: 1/2 |v|^2 + 1/2 |x|^2 with v = (-y, x)).
// Forward Euler multiplies r^2 by 1 + h^2 a step, so after n steps E = (1 + h^2)^n and the drift
// is (E - 1) / E_ref with E_ref = max(E(0), peak kinetic E / 2): a closed form, not the zero a
// missing energy used to read as.
TEST(EnergyMetric, TheCircleDriftsByForwardEulersRadiusGrowth) {
  auto circle = mysim::loadScene(std::string(SPRINGCHECK_SOURCE_DIR) + "/scenes/seed/circle.json");
  ASSERT_TRUE(circle) << circle.error();
  circle->integrator.name = "euler";
  circle->duration = 2 * std::numbers::pi;  // 157 steps of 0.04 s
  const auto run = EngineRegistry().run("mysim", *circle);
  ASSERT_TRUE(run) << run.error().message;
  const EngineMetrics m = engineMetrics(mysim::buildModel(*circle), EngineRun{"mysim", *run});
  const double grown = std::pow(1.0 + 0.04 * 0.04, static_cast<double>(run->steps));
  ASSERT_TRUE(metricValue(m, "energy_drift_max"));
  EXPECT_NEAR(*metricValue(m, "energy_drift_max"), (grown - 1.0) / std::max(1.0, grown / 2),
              1e-12);
  // A run that recorded no energy has no drift: not applicable, not 0.
  EXPECT_FALSE(metricValue(EngineMetrics{}, "energy_drift_max"));
  EXPECT_FALSE(metricValue(EngineMetrics{}, "energy_rise"));
}

// The two-pin elastic catenary is the chain's equilibrium: at every free node of the closed form
// the two springs' forces and the weight add up to nothing (1e-12 of the weight), level pins or
// not; and the level one is symmetric about its middle.
TEST(ClosedForm, TheTwoPinCatenaryBalancesEveryNode) {
  auto scene = mysim::loadScene(std::string(SPRINGCHECK_SOURCE_DIR) + "/scenes/matched/chain_catenary.json");
  ASSERT_TRUE(scene) << scene.error();
  for (double raised : {0.0, 0.3}) {
    mysim::Model model = mysim::buildModel(*scene);
    const int last = model.particleCount() - 1;
    mysim::at3(model.start_position, last) += mysim::Vec3(-0.2, raised, 0.0);  // slack, and higher
    const auto nodes = twoPinCatenaryNodes(model);
    ASSERT_TRUE(nodes);
    ASSERT_EQ(static_cast<int>(nodes->size()), model.particleCount());
    EXPECT_LT(((*nodes)[last] - mysim::at3(model.start_position, last)).norm(), 1e-12);
    const double weight = model.mass[1] * model.gravity.norm();
    for (int j = 1; j < last; ++j) {
      mysim::Vec3 f = model.mass[j] * model.gravity;
      for (int q : {j - 1, j + 1}) {
        const mysim::Vec3 d = (*nodes)[q] - (*nodes)[j];
        const mysim::Spring& sp = model.springs[std::min(j, q)];
        f += sp.stiffness * (d.norm() - sp.rest_length) * d.normalized();
      }
      EXPECT_LT(f.norm(), 1e-12 * weight) << "node " << j << ", right pin raised " << raised;
    }
    if (raised == 0.0) {
      for (int j = 0; j <= last; ++j) {
        EXPECT_NEAR((*nodes)[j].y(), (*nodes)[last - j].y(), 1e-12);
      }
    }
  }
}

TEST(ClosedForm, EllipticKKnownValues) {
  EXPECT_NEAR(ellipticK(0.0), std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(ellipticK(std::sqrt(0.5)), 1.8540746773013719, 1e-14);  // the 90-degree pendulum
}

TEST(ClosedForm, ExactCircleFramesHaveZeroErrorAndAShiftedOneItsShift) {
  mysim::Model circle;
  circle.circle_start = Eigen::Vector2d(1.0, 0.0);
  mysim::RunRecord run;
  for (double t : {0.0, 0.5, 1.0}) {
    mysim::ParticleRows row = mysim::ParticleRows::Zero(1, 6);
    row(0, 0) = std::cos(t);
    row(0, 1) = std::sin(t);
    run.times.push_back(t);
    run.frames.push_back(row);
  }
  EXPECT_LT(closedFormError(circle, run)->error, 1e-15);
  run.frames[2](0, 0) += 0.01;
  EXPECT_NEAR(closedFormError(circle, run)->error, 0.01, 1e-15);
}

// A closed form of the state at rest says when its error is the motion left at the end: a chain
// put exactly on its closed form at the last frame has no error and no floor; one whose last
// frame is 1e-5 m off and still moving 2e-5 m over the last tenth is at the motion floor.
TEST(ClosedForm, AnAtRestErrorNearTheMotionLeftSaysSo) {
  auto scene = mysim::loadScene(std::string(SPRINGCHECK_SOURCE_DIR) + "/scenes/matched/chain_hanging.json");
  ASSERT_TRUE(scene) << scene.error();
  const mysim::Model model = mysim::buildModel(*scene);
  const int n = model.particleCount();
  const double m = model.mass[1], k = model.springs.front().stiffness;
  const double L = model.springs.front().rest_length;
  mysim::ParticleRows rest = mysim::ParticleRows::Zero(n, 6);
  for (int j = 1; j < n; ++j) {
    rest(j, 1) = -(j * L + (m * model.gravity.norm() / k) * j * (2 * (n - 1) - j + 1) / 2.0);
  }
  mysim::RunRecord run;
  for (double t : {0.0, 9.0, 10.0}) {
    run.times.push_back(t);
    run.frames.push_back(rest);
  }
  auto still = closedFormError(model, run);
  ASSERT_TRUE(still && still->motion_left);
  EXPECT_LT(still->error, 1e-12);
  EXPECT_FALSE(still->atMotionFloor());
  run.frames[1](n - 1, 1) -= 1e-5;  // at 90 % of the run: 1e-5 m below
  run.frames[2](n - 1, 1) += 1e-5;  // at the end: 1e-5 m above
  auto moving = closedFormError(model, run);
  EXPECT_NEAR(moving->error, 1e-5, 1e-12);
  EXPECT_NEAR(*moving->motion_left, 2e-5, 1e-12);
  EXPECT_TRUE(moving->atMotionFloor());
}

// A fold that buckles the other way is no disagreement: cloth_hanging (pinned at its two top
// corners) is symmetric across its columns, so one cloth bent out of plane on one side and the
// mirror image of it are 0.1 m apart node by node and round-off apart mirror-aware, which says
// it took the mirrored distance. A cloth with a third pin has no such plane.
TEST(MirrorAwareDrape, AMirroredClothIsReportedAsMirroredAtRoundOff) {
  auto scene = mysim::loadScene(std::string(SPRINGCHECK_SOURCE_DIR) + "/scenes/matched/cloth_hanging.json");
  ASSERT_TRUE(scene) << scene.error();
  const mysim::Model model = mysim::buildModel(*scene);
  const auto mirror = mirrorSymmetry(model);
  ASSERT_TRUE(mirror);
  EXPECT_STREQ(mirror->across, "columns");
  mysim::ParticleRows a = mysim::ParticleRows::Zero(model.particleCount(), 6);
  for (int p = 0; p < model.particleCount(); ++p) a.block<1, 3>(p, 0) = mysim::at3(model.start_position, p).transpose();
  for (int r = 0; r < 12; ++r) a(r * 12 + 2, 1) += 0.1;  // bent up along column 2 only
  mysim::ParticleRows b = a;
  b.leftCols<3>() = mirrored(*mirror, a.leftCols<3>());
  auto run = [](const std::string& engine, const mysim::ParticleRows& f) {
    mysim::RunRecord r;
    r.times = {0.0};
    r.frames = {f};
    return EngineRun{engine, r};
  };
  const PairMetrics m = pairMetrics(model, run("a", a), run("b", b), EngineMetrics{}, EngineMetrics{});
  EXPECT_NEAR(m.drape.max, 0.1, 1e-12);
  EXPECT_LT(m.drapeMirrorAware(), 1e-14);
  EXPECT_TRUE(m.mirrorCloser());
  EXPECT_EQ(*metricValue(m, "drape_mirrored"), 1.0);
  mysim::Model three = model;
  three.pinned[5] = 1;
  EXPECT_FALSE(mirrorSymmetry(three));
}

// Final-frame distances are rest-shape disagreements only where every engine settled: a cloth
// still moving at its last frame, 165 mm apart there, is reported by its trajectory difference
// as moving, and the rest-shape headline is the settled cloth's 1 um.
TEST(ReportHeadlines, AMovingClothsFinalFrameIsNotARestShapeDisagreement) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("springcheck_headlines_" + std::to_string(::getpid()));
  fs::create_directories(dir / "moving");
  fs::create_directories(dir / "settled");
  auto comparison = [](std::optional<double> settling, double drape, double trajectory) {
    nlohmann::json engine = {{"engine", "x"}, {"settling_time", nullptr}};
    if (settling) engine["settling_time"] = *settling;
    nlohmann::json other = engine;
    other["engine"] = "y";
    return nlohmann::json{{"duration", 5.0},  // pairs against the first engine, as a drape page draws
                          {"model", {{"kind", "cloth"}, {"driven", false}}},
                          {"engines", {engine, other}},
                          {"pairs", {{{"a", "x"}, {"b", "y"}, {"drape_max", drape},
                                      {"trajectory_rms_max", trajectory}}}}};
  };
  std::ofstream(dir / "moving" / "comparison.json") << comparison(std::nullopt, 0.165, 0.09);
  std::ofstream(dir / "settled" / "comparison.json") << comparison(3.5, 1e-6, 2e-3);
  const nlohmann::json comparisons = {
      {{"group", "suite"}, {"scene", "swinging"}, {"folder", (dir / "moving").string()}},
      {{"group", "suite"}, {"scene", "resting"}, {"folder", (dir / "settled").string()}}};
  const nlohmann::json h = reportHeadlines(comparisons, nlohmann::json::array());
  EXPECT_EQ(h["worst_cloth_drape"]["scene"], "resting");
  EXPECT_DOUBLE_EQ(h["worst_cloth_drape"]["value"].get<double>(), 1e-6);
  EXPECT_EQ(h["worst_moving_cloth"]["scene"], "swinging");
  EXPECT_DOUBLE_EQ(h["worst_moving_cloth"]["value"].get<double>(), 0.09);
  EXPECT_EQ(h["cloth_states"]["suite/swinging"]["state"], "moving");
  EXPECT_DOUBLE_EQ(h["cloth_states"]["suite/resting"]["settled_at"].get<double>(), 3.5);
  fs::remove_all(dir);
}

TEST(SettlingMetric, TimeAfterWhichKineticEnergyStaysLowAndMaxStrain) {
  mysim::RunRecord run;
  run.times = {0, 1, 2, 3, 4};
  for (double ke : {1.0, 0.5, 1e-5, 2e-4, 1e-5}) run.energies.push_back({ke, 0, 0});
  EXPECT_DOUBLE_EQ(*settlingTime(run, 1e-4), 4.0);  // the 2e-4 at t = 3 breaks the first calm
  EXPECT_DOUBLE_EQ(*settlingTime(run, 1e-3), 2.0);
  run.energies.back().kinetic = 0.1;
  EXPECT_FALSE(settlingTime(run, 1e-4));

  mysim::Model model;
  model.springs.push_back({0, 1, 2.0, 1.0, 0.0, mysim::SpringFamily::Custom});
  mysim::ParticleRows frame = mysim::ParticleRows::Zero(2, 6);
  frame(1, 0) = 2.5;
  run.frames = {frame};
  EXPECT_DOUBLE_EQ(maxStrainOverRun(model, run), 0.25);
}

}  // namespace
}  // namespace springcheck
