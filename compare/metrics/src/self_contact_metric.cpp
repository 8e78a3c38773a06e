#include "compare/metrics/self_contact_metric.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "mysim/cloth_surface.h"
#include "mysim/proximity.h"
#include "mysim/self_collision.h"
#include "mysim/spatial_grid.h"

namespace springcheck {
namespace {

using mysim::Vec3;

// The mesh's pieces and who is adjacent to whom, built once per run.
struct Mesh {
  std::vector<Eigen::Vector3i> triangles;
  std::vector<std::array<int, 2>> edges;
  std::vector<std::vector<int>> neighbours;     // per node, sorted: itself and its edge neighbours
  std::vector<std::vector<int>> node_pieces;    // per node: its triangles (cloth) or edges (chain)
};

Mesh meshOf(const mysim::Model& model) {
  Mesh m{mysim::clothTriangles(model), mysim::selfCollisionEdges(model), {}, {}};
  const int n = model.particleCount();
  m.neighbours.resize(n);
  m.node_pieces.resize(n);
  for (int p = 0; p < n; ++p) m.neighbours[p].push_back(p);
  for (const auto& e : m.edges) m.neighbours[e[0]].push_back(e[1]), m.neighbours[e[1]].push_back(e[0]);
  for (auto& list : m.neighbours) std::sort(list.begin(), list.end());
  if (!m.triangles.empty()) {
    for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) {
      for (int k = 0; k < 3; ++k) m.node_pieces[m.triangles[t][k]].push_back(t);
    }
  } else {
    for (int e = 0; e < static_cast<int>(m.edges.size()); ++e) {
      for (int k = 0; k < 2; ++k) m.node_pieces[m.edges[e][k]].push_back(e);
    }
  }
  return m;
}

bool nearTriangle(const Mesh& m, int p, const Eigen::Vector3i& t) {
  for (int k = 0; k < 3; ++k) {
    if (std::binary_search(m.neighbours[p].begin(), m.neighbours[p].end(), t[k])) return true;
  }
  return false;
}

bool shareVertex(const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (a[i] == b[j]) return true;
    }
  }
  return false;
}

struct FrameContact {
  int intersections = 0;
  std::optional<double> distance;
};

void keepCloser(std::optional<double>& best, double d) {
  if (!best || d < *best) best = d;
}

// A triangle's bounding box, padded by a hair (1e-9 of the cell) so that rounding in the crossing
// test can never count a pair whose boxes the test below kept apart.
struct Box {
  Vec3 low, high;
  bool overlaps(const Box& o) const {
    return (low.array() <= o.high.array()).all() && (o.low.array() <= high.array()).all();
  }
};

std::vector<Box> triangleBoxes(const Mesh& m, const std::vector<Vec3>& x, double pad) {
  std::vector<Box> boxes(m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Vec3 &a = x[m.triangles[t][0]], &b = x[m.triangles[t][1]], &c = x[m.triangles[t][2]];
    boxes[t] = {a.cwiseMin(b).cwiseMin(c).array() - pad, a.cwiseMax(b).cwiseMax(c).array() + pad};
  }
  return boxes;
}

// One cloth frame: every triangle against the nodes and triangles within a cell of it. Two
// triangles that cross have overlapping boxes, so only those go to the crossing test (most
// candidates of a cell's neighbourhood do not: the metric's cost was most of a cloth sweep's).
FrameContact clothFrame(const Mesh& m, const std::vector<Vec3>& x, mysim::SpatialGrid& grid,
                        std::vector<int>& seen) {
  double longest = 0.0;
  for (const auto& e : m.edges) longest = std::max(longest, (x[e[0]] - x[e[1]]).norm());
  const double cell = std::max(longest, 1e-9);
  grid.build(x, cell);
  const std::vector<Box> boxes = triangleBoxes(m, x, 1e-9 * cell);
  seen.assign(m.triangles.size(), -1);  // the last triangle that took each as a candidate
  FrameContact f;
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) {
    const Eigen::Vector3i& tri = m.triangles[t];
    const Vec3 a = x[tri[0]], b = x[tri[1]], c = x[tri[2]];
    const Vec3 first[3] = {a, b, c};
    const Vec3 reach = Vec3::Constant(cell);
    grid.forEachNear(a.cwiseMin(b).cwiseMin(c) - reach, a.cwiseMax(b).cwiseMax(c) + reach, [&](int p) {
      if (!nearTriangle(m, p, tri)) {
        const Vec3 w = mysim::closestOnTriangle(x[p], a, b, c);
        keepCloser(f.distance, (x[p] - (w[0] * a + w[1] * b + w[2] * c)).norm());
      }
      for (int other : m.node_pieces[p]) {
        if (other <= t || seen[other] == t) continue;
        seen[other] = t;
        const Eigen::Vector3i& o = m.triangles[other];
        if (shareVertex(tri, o) || !boxes[t].overlaps(boxes[other])) continue;
        const Vec3 second[3] = {x[o[0]], x[o[1]], x[o[2]]};
        if (mysim::trianglesIntersect(first, second)) ++f.intersections;
      }
    });
  }
  return f;
}

// One chain frame: every link against the links within a cell of it.
FrameContact chainFrame(const Mesh& m, const std::vector<Vec3>& x, mysim::SpatialGrid& grid) {
  double longest = 0.0;
  for (const auto& e : m.edges) longest = std::max(longest, (x[e[0]] - x[e[1]]).norm());
  grid.build(x, std::max(longest, 1e-9));
  FrameContact f;
  for (int e = 0; e < static_cast<int>(m.edges.size()); ++e) {
    const auto& link = m.edges[e];
    const Vec3 reach = Vec3::Constant(longest);
    grid.forEachNear(x[link[0]].cwiseMin(x[link[1]]) - reach, x[link[0]].cwiseMax(x[link[1]]) + reach, [&](int p) {
      for (int other : m.node_pieces[p]) {
        const auto& o = m.edges[other];
        if (other <= e || o[0] == link[0] || o[0] == link[1] || o[1] == link[0] || o[1] == link[1]) continue;
        const mysim::SegmentParameters st = mysim::closestOnSegments(x[link[0]], x[link[1]], x[o[0]], x[o[1]]);
        const Vec3 gap = (x[link[0]] + st.s * (x[link[1]] - x[link[0]])) - (x[o[0]] + st.t * (x[o[1]] - x[o[0]]));
        keepCloser(f.distance, gap.norm());
      }
    });
  }
  return f;
}

}  // namespace

std::optional<SelfContact> selfContactOverRun(const mysim::Model& model, const mysim::RunRecord& run) {
  if (model.isCircle()) return std::nullopt;
  const Mesh mesh = meshOf(model);
  if (mesh.edges.empty()) return std::nullopt;
  const bool cloth = !mesh.triangles.empty();
  SelfContact result;
  if (cloth) result.intersections = 0;
  mysim::SpatialGrid grid;
  std::vector<int> seen;
  std::vector<Vec3> x(model.particleCount());
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    for (int p = 0; p < model.particleCount(); ++p) x[p] = mysim::rowPosition(run.frames[f], p);
    const FrameContact frame = cloth ? clothFrame(mesh, x, grid, seen) : chainFrame(mesh, x, grid);
    if (cloth && frame.intersections > *result.intersections) {
      result.intersections = frame.intersections;
      result.intersections_time = run.times[f];
    }
    if (frame.distance && (!result.distance_min || *frame.distance < *result.distance_min)) {
      result.distance_min = frame.distance;
      result.distance_time = run.times[f];
    }
  }
  return result;
}

}  // namespace springcheck
