#include "compare/metrics/drape_test_metric.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace springcheck {
namespace {

using mysim::Vec3;
using Point = Eigen::Vector2d;

// Area covered by the union of triangles (2-D), by counting pixel centres inside any of them.
double unionArea(const std::vector<std::array<Point, 3>>& triangles) {
  constexpr int kPixels = 4096;
  Point low(INFINITY, INFINITY), high(-INFINITY, -INFINITY);
  for (const auto& t : triangles) {
    for (const Point& p : t) low = low.cwiseMin(p), high = high.cwiseMax(p);
  }
  const double size = std::max(high.x() - low.x(), high.y() - low.y()) * (1.0 + 1e-9);
  const double pixel = size / kPixels;
  std::vector<bool> covered(static_cast<std::size_t>(kPixels) * kPixels, false);
  for (const auto& t : triangles) {
    Point a = t[0], b = t[1], c = t[2];
    if ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x() < 0.0) std::swap(b, c);
    auto edge = [](const Point& p, const Point& q, const Point& x) {
      return (q - p).x() * (x - p).y() - (q - p).y() * (x - p).x();
    };
    const Point lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    const int i0 = std::max(0, static_cast<int>((lo.x() - low.x()) / pixel));
    const int i1 = std::min(kPixels - 1, static_cast<int>((hi.x() - low.x()) / pixel));
    const int j0 = std::max(0, static_cast<int>((lo.y() - low.y()) / pixel));
    const int j1 = std::min(kPixels - 1, static_cast<int>((hi.y() - low.y()) / pixel));
    for (int i = i0; i <= i1; ++i) {
      for (int j = j0; j <= j1; ++j) {
        const Point x = low + Point((i + 0.5) * pixel, (j + 0.5) * pixel);
        if (edge(a, b, x) >= 0 && edge(b, c, x) >= 0 && edge(c, a, x) >= 0) {
          covered[static_cast<std::size_t>(i) * kPixels + j] = true;
        }
      }
    }
  }
  return std::count(covered.begin(), covered.end(), true) * pixel * pixel;
}

// Lobes of a closed curve's radius: excursions above the mean by a fifth of its largest
// deviation, each counted once it comes back below the mean by as much.
int lobes(const std::vector<double>& radius) {
  if (radius.empty()) return 0;
  double mean = 0.0;
  for (double r : radius) mean += r / radius.size();
  double deviation = 0.0;
  for (double r : radius) deviation = std::max(deviation, std::abs(r - mean));
  if (deviation < 1e-3 * mean) return 0;
  const double band = 0.2 * deviation;
  // Start where the curve is lowest, so a lobe is never split by the start.
  const std::size_t start = std::min_element(radius.begin(), radius.end()) - radius.begin();
  int count = 0;
  bool high = false;
  for (std::size_t k = 0; k <= radius.size(); ++k) {
    const double r = radius[(start + k) % radius.size()] - mean;
    if (!high && r > band) high = true;
    if (high && r < -band) high = false, ++count;
  }
  return count;
}

}  // namespace

std::optional<DrapeTestReading> readDrapeTest(const mysim::Model& model,
                                              const mysim::ParticleRows& frame) {
  if (model.mesh_triangles.empty() || !model.material || model.gravity.norm() == 0.0) {
    return std::nullopt;
  }
  const int n = model.particleCount();
  Vec3 centre = Vec3::Zero();
  int pins = 0;
  for (int p = 0; p < n; ++p) {
    if (model.pinned[p]) centre += mysim::at3(model.start_position, p), ++pins;
  }
  if (pins == 0) return std::nullopt;
  centre /= pins;
  // The plane of the shadow: two directions across gravity.
  const Vec3 down = model.gravity.normalized();
  const Vec3 u = (std::abs(down.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(down).normalized();
  const Vec3 v = down.cross(u);
  auto project = [&](const Vec3& x) { return Point((x - centre).dot(u), (x - centre).dot(v)); };

  DrapeTestReading r;
  double support = 0.0;
  for (int p = 0; p < n; ++p) {
    if (model.pinned[p]) support = std::max(support, project(mysim::at3(model.start_position, p)).norm());
  }
  r.support_area = std::numbers::pi * support * support;
  std::vector<std::array<Point, 3>> shadow;
  std::map<std::pair<int, int>, int> edge_uses;
  for (const Eigen::Vector3i& t : model.mesh_triangles) {
    const Vec3 a = mysim::at3(model.start_position, t[0]), b = mysim::at3(model.start_position, t[1]),
               c = mysim::at3(model.start_position, t[2]);
    r.specimen_area += 0.5 * (b - a).cross(c - a).norm();
    shadow.push_back({project(frame.row(t[0]).head<3>().transpose()),
                      project(frame.row(t[1]).head<3>().transpose()),
                      project(frame.row(t[2]).head<3>().transpose())});
    for (int k = 0; k < 3; ++k) ++edge_uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  }
  r.shadow_area = unionArea(shadow);
  r.drape_coefficient = (r.shadow_area - r.support_area) / (r.specimen_area - r.support_area);
  // The rim: vertices of edges used once, in order of their angle at rest.
  std::vector<std::pair<double, int>> rim;
  for (const auto& [edge, uses] : edge_uses) {
    if (uses != 1) continue;
    for (int p : {edge.first, edge.second}) {
      const Point rest = project(mysim::at3(model.start_position, p));
      rim.emplace_back(std::atan2(rest.y(), rest.x()), p);
    }
  }
  std::sort(rim.begin(), rim.end());
  rim.erase(std::unique(rim.begin(), rim.end()), rim.end());
  for (const auto& [angle, p] : rim) r.rim_radius.push_back(project(mysim::rowPosition(frame, p)).norm());
  r.folds = lobes(r.rim_radius);
  return r;
}

}  // namespace springcheck
