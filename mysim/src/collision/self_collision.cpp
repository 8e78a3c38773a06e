#include "mysim/self_collision.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "mysim/cloth_surface.h"
#include "mysim/proximity.h"
#include "mysim/spatial_grid.h"

namespace mysim {
namespace {

// Gauss-Seidel passes over the gathered pairs: a push can bring a neighbouring pair closer, and
// two more passes settle a fold of three layers (measured on the fold-on-ground scene: 0
// intersecting pairs with 3, one in a few hundred frames with 1).
constexpr int kPasses = 3;

Vec3 at(Eigen::Ref<const Vector> y, int p) { return y.segment<3>(3 * p); }

bool shares(const Eigen::Vector3i& t, int p) { return t[0] == p || t[1] == p || t[2] == p; }
bool shares(const std::array<int, 2>& e, const std::array<int, 2>& f) {
  return e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1];
}

}  // namespace

std::vector<std::array<int, 2>> selfCollisionEdges(const Model& model) {
  const std::vector<Eigen::Vector3i> triangles = clothTriangles(model);
  std::set<std::array<int, 2>> edges;
  for (const Eigen::Vector3i& t : triangles) {
    for (int k = 0; k < 3; ++k) edges.insert({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  }
  if (triangles.empty()) {
    for (const Spring& s : model.springs) edges.insert({std::min(s.i, s.j), std::max(s.i, s.j)});
  }
  return {edges.begin(), edges.end()};
}

std::optional<LimitError> checkSelfCollision(const Model& model) {
  if (!model.self_collision_thickness) return std::nullopt;
  const std::vector<std::array<int, 2>> edges = selfCollisionEdges(model);
  if (edges.empty()) {
    return LimitError{"system.self_collision",
                      "needs a cloth's triangles or a chain's links; this system has neither"};
  }
  double shortest = INFINITY;
  for (const auto& e : edges) shortest = std::min(shortest, (at(model.start_position, e[0]) - at(model.start_position, e[1])).norm());
  if (*model.self_collision_thickness > shortest) {
    std::ostringstream m;
    m << "expected at most the shortest edge of the mesh at the start (a cell: " << shortest
      << " m), got " << *model.self_collision_thickness << " m";
    return LimitError{"system.self_collision.thickness", m.str()};
  }
  return std::nullopt;
}

SelfCollision::SelfCollision(const Model& model)
    : thickness_(model.self_collision_thickness.value()),
      triangles_(clothTriangles(model)),
      edges_(selfCollisionEdges(model)),
      inverse_mass_(model.particleCount()),
      rest_(model.start_position),
      nodes_grid_(std::make_unique<SpatialGrid>()),
      edges_grid_(std::make_unique<SpatialGrid>()) {
  for (int p = 0; p < model.particleCount(); ++p) inverse_mass_[p] = model.pinned[p] ? 0.0 : 1.0 / model.mass[p];
}

SelfCollision::~SelfCollision() = default;

SelfCollision::SelfCollision(const SelfCollision& other)
    : thickness_(other.thickness_),
      triangles_(other.triangles_),
      edges_(other.edges_),
      inverse_mass_(other.inverse_mass_),
      rest_(other.rest_),
      nodes_grid_(std::make_unique<SpatialGrid>()),
      edges_grid_(std::make_unique<SpatialGrid>()) {}

bool SelfCollision::apartAtRest(const Candidate& c, bool node_triangle) const {
  if (node_triangle) {
    const Eigen::Vector3i& t = triangles_[c.b];
    const Vec3 p = at(rest_, c.a), a = at(rest_, t[0]), b = at(rest_, t[1]), d = at(rest_, t[2]);
    const Vec3 w = closestOnTriangle(p, a, b, d);
    return (p - (w[0] * a + w[1] * b + w[2] * d)).norm() >= thickness_;
  }
  const auto& e = edges_[c.a];
  const auto& f = edges_[c.b];
  const Vec3 p0 = at(rest_, e[0]), p1 = at(rest_, e[1]), q0 = at(rest_, f[0]), q1 = at(rest_, f[1]);
  const SegmentParameters st = closestOnSegments(p0, p1, q0, q1);
  return ((p0 + st.s * (p1 - p0)) - (q0 + st.t * (q1 - q0))).norm() >= thickness_;
}

namespace {

// The weights and directions of a push between two sides of a pair: side 1 the node (or the
// first edge's two ends), side 2 the triangle's corners (or the second edge's ends).
struct PairPush {
  std::array<int, 4> particle{};
  std::array<double, 4> weight{};  // + on side 1, - on side 2 (barycentric)
  int count = 0;
};

// Moves the pair `depth` apart along n and removes its approaching velocity along n,
// mass-weighted; false when every particle of it is pinned.
bool push(const PairPush& pair, const Vec3& n, double depth, const Vector& inverse_mass,
          Eigen::Ref<Vector> x, Eigen::Ref<Vector> v) {
  double resistance = 0.0, approach = 0.0;
  for (int k = 0; k < pair.count; ++k) {
    resistance += pair.weight[k] * pair.weight[k] * inverse_mass[pair.particle[k]];
    approach += pair.weight[k] * v.segment<3>(3 * pair.particle[k]).dot(n);
  }
  if (resistance == 0.0) return false;
  const double dx = depth / resistance, dv = approach < 0.0 ? -approach / resistance : 0.0;
  for (int k = 0; k < pair.count; ++k) {
    const double share = pair.weight[k] * inverse_mass[pair.particle[k]];
    x.segment<3>(3 * pair.particle[k]) += (share * dx) * n;
    v.segment<3>(3 * pair.particle[k]) += (share * dv) * n;
  }
  return true;
}

}  // namespace

bool SelfCollision::pushNodeFromTriangle(const Candidate& c, Eigen::Ref<const Vector> start,
                                         Eigen::Ref<Vector> x, Eigen::Ref<Vector> v) const {
  const Eigen::Vector3i& t = triangles_[c.b];
  const Vec3 a = at(x, t[0]), b = at(x, t[1]), d = at(x, t[2]), p = at(x, c.a);
  Vec3 n = (b - a).cross(d - a);
  if (n.norm() == 0.0) return false;
  n.normalize();
  const Vec3 w = closestOnTriangle(p, a, b, d);
  // Nearest on an edge or a corner: the pairs of the node's edges with the triangle's take it.
  if (w.minCoeff() <= 0.0) return false;
  const Vec3 gap = p - (w[0] * a + w[1] * b + w[2] * d);
  const Vec3 a0 = at(start, t[0]), b0 = at(start, t[1]), d0 = at(start, t[2]);
  const Vec3 gap0 = at(start, c.a) - (w[0] * a0 + w[1] * b0 + w[2] * d0);
  const Vec3 n0 = (b0 - a0).cross(d0 - a0);
  const double side = (n0.norm() > 0.0 ? gap0.dot(n0) : gap.dot(n)) >= 0.0 ? 1.0 : -1.0;
  const double distance = side * gap.dot(n);
  if (distance >= thickness_) return false;
  // Behind the triangle farther than this step carried it: a layer beyond, not a crossing.
  if (distance < 0.0 && -distance > std::abs((gap - gap0).dot(n))) return false;
  const PairPush pair{{c.a, t[0], t[1], t[2]}, {1.0, -w[0], -w[1], -w[2]}, 4};
  return push(pair, side * n, thickness_ - distance, inverse_mass_, x, v);
}

bool SelfCollision::pushEdges(const Candidate& c, Eigen::Ref<const Vector> start, Eigen::Ref<Vector> x,
                              Eigen::Ref<Vector> v) const {
  const auto& e = edges_[c.a];
  const auto& f = edges_[c.b];
  const SegmentParameters st = closestOnSegments(at(x, e[0]), at(x, e[1]), at(x, f[0]), at(x, f[1]));
  auto gapIn = [&](Eigen::Ref<const Vector> y) {
    return Vec3(((1 - st.s) * at(y, e[0]) + st.s * at(y, e[1])) - ((1 - st.t) * at(y, f[0]) + st.t * at(y, f[1])));
  };
  const Vec3 gap = gapIn(x), gap0 = gapIn(start);
  double distance = gap.norm();
  Vec3 n;
  if (gap.dot(gap0) < 0.0 && gap0.norm() > 0.0) {  // passed through each other within the step
    n = gap0.normalized();
    distance = gap.dot(n);
  } else if (distance < thickness_ && distance > 0.0) {
    n = gap / distance;
  } else {
    return false;
  }
  const PairPush pair{{e[0], e[1], f[0], f[1]}, {1 - st.s, st.s, -(1 - st.t), -st.t}, 4};
  return push(pair, n, thickness_ - distance, inverse_mass_, x, v);
}

void SelfCollision::gather(Eigen::Ref<const Vector> start, Eigen::Ref<const Vector> x) {
  const int n = static_cast<int>(inverse_mass_.size());
  double longest = 0.0, motion = 0.0;
  for (const auto& e : edges_) longest = std::max(longest, (at(x, e[0]) - at(x, e[1])).norm());
  for (int p = 0; p < n; ++p) motion = std::max(motion, (at(x, p) - at(start, p)).norm());
  // A pair within twice the thickness (it may close within the passes) or the step's motion
  // (it may have crossed) is a candidate.
  const double reach = 2.0 * thickness_ + motion;
  const double cell = std::max(longest + reach, 1e-9);
  node_triangle_.clear();
  edge_edge_.clear();
  std::vector<Vec3> points(n);
  if (!triangles_.empty()) {
    for (int p = 0; p < n; ++p) points[p] = at(x, p);
    nodes_grid_->build(points, cell);
    for (int k = 0; k < static_cast<int>(triangles_.size()); ++k) {
      const Eigen::Vector3i& t = triangles_[k];
      const Vec3 low = at(x, t[0]).cwiseMin(at(x, t[1])).cwiseMin(at(x, t[2])) - Vec3::Constant(reach);
      const Vec3 high = at(x, t[0]).cwiseMax(at(x, t[1])).cwiseMax(at(x, t[2])) + Vec3::Constant(reach);
      nodes_grid_->forEachNear(low, high, [&](int p) {
        if (shares(t, p) || (at(x, p).array() < low.array()).any() || (at(x, p).array() > high.array()).any()) return;
        // Only a node over the triangle's inside can be pushed by it (pushNodeFromTriangle).
        const Vec3 w = closestOnTriangle(at(x, p), at(x, t[0]), at(x, t[1]), at(x, t[2]));
        if (w.minCoeff() <= 0.0) return;
        const Vec3 q = w[0] * at(x, t[0]) + w[1] * at(x, t[1]) + w[2] * at(x, t[2]);
        if ((at(x, p) - q).norm() > reach) return;
        if (apartAtRest({p, k}, true)) node_triangle_.push_back({p, k});
      });
    }
  }
  const int edges = static_cast<int>(edges_.size());
  points.resize(edges);
  for (int k = 0; k < edges; ++k) points[k] = 0.5 * (at(x, edges_[k][0]) + at(x, edges_[k][1]));
  edges_grid_->build(points, cell);
  for (int k = 0; k < edges; ++k) {
    const Vec3 half = Vec3::Constant(0.5 * longest + reach);
    edges_grid_->forEachNear(points[k] - half, points[k] + half, [&](int other) {
      if (other <= k || shares(edges_[k], edges_[other])) return;
      const auto& e = edges_[k];
      const auto& f = edges_[other];
      // Boxes first: most edges of the cells around are farther than reach on some axis.
      const Vec3 e_low = at(x, e[0]).cwiseMin(at(x, e[1])), e_high = at(x, e[0]).cwiseMax(at(x, e[1]));
      const Vec3 f_low = at(x, f[0]).cwiseMin(at(x, f[1])), f_high = at(x, f[0]).cwiseMax(at(x, f[1]));
      if (((f_low - e_high).array() > reach).any() || ((e_low - f_high).array() > reach).any()) return;
      const SegmentParameters st = closestOnSegments(at(x, e[0]), at(x, e[1]), at(x, f[0]), at(x, f[1]));
      const Vec3 gap = ((1 - st.s) * at(x, e[0]) + st.s * at(x, e[1])) - ((1 - st.t) * at(x, f[0]) + st.t * at(x, f[1]));
      if (gap.norm() > reach) return;
      if (apartAtRest({k, other}, false)) edge_edge_.push_back({k, other});
    });
  }
}

int SelfCollision::resolve(Eigen::Ref<const Vector> start, Eigen::Ref<Vector> x, Eigen::Ref<Vector> v) {
  gather(start, x);
  int pushed = 0;
  for (int pass = 0; pass < kPasses; ++pass) {
    int this_pass = 0;
    for (const Candidate& c : node_triangle_) this_pass += pushNodeFromTriangle(c, start, x, v);
    for (const Candidate& c : edge_edge_) this_pass += pushEdges(c, start, x, v);
    if (pass == 0) pushed = this_pass;
    if (this_pass == 0) break;
  }
  return pushed;
}

}  // namespace mysim
