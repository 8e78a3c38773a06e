#include "mysim/hinge.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace mysim {

Hinge makeHinge(const std::array<int, 4>& particles, const Vec3& x0, const Vec3& x1,
                const Vec3& x2, const Vec3& x3, double rigidity) {
  const Vec3 edge = x1 - x0;
  const double length = edge.norm();
  const Vec3 along = edge / length;
  // Each opposite vertex: where the foot of its height falls along the edge (0 at x0, 1 at x1)
  // and the height. Unfolding keeps both.
  auto foot = [&](const Vec3& x) {
    const double s = (x - x0).dot(along);
    return std::pair{s / length, (x - x0 - s * along).norm()};
  };
  const auto [s2, h2] = foot(x2);
  const auto [s3, h3] = foot(x3);
  Hinge hinge;
  hinge.particle = particles;
  hinge.weight[2] = length / h2;
  hinge.weight[3] = length / h3;
  hinge.weight[0] = -(hinge.weight[2] * (1.0 - s2) + hinge.weight[3] * (1.0 - s3));
  hinge.weight[1] = -(hinge.weight[2] * s2 + hinge.weight[3] * s3);
  const double area = 0.5 * length * (h2 + h3);
  hinge.stiffness = rigidity / area;
  return hinge;
}

std::vector<Hinge> meshHinges(const std::vector<Eigen::Vector3i>& triangles,
                              Eigen::Ref<const Vector> x, double rigidity) {
  // Each undirected edge: the triangles' vertices opposite it, in triangle order.
  struct EdgeUse {
    int a, b;  // the edge as the first triangle ran it
    std::vector<int> opposite;
    int order;
  };
  std::map<std::pair<int, int>, EdgeUse> edges;
  int order = 0;
  for (const Eigen::Vector3i& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      auto [it, inserted] = edges.try_emplace({std::min(a, b), std::max(a, b)},
                                              EdgeUse{a, b, {}, order});
      if (inserted) ++order;
      it->second.opposite.push_back(c);
    }
  }
  std::vector<const EdgeUse*> interior;
  for (const auto& [key, use] : edges) {
    if (use.opposite.size() == 2) interior.push_back(&use);
  }
  std::sort(interior.begin(), interior.end(),
            [](const EdgeUse* l, const EdgeUse* r) { return l->order < r->order; });
  std::vector<Hinge> hinges;
  hinges.reserve(interior.size());
  for (const EdgeUse* use : interior) {
    const std::array<int, 4> p{use->a, use->b, use->opposite[0], use->opposite[1]};
    auto at = [&x](int q) { return Vec3(x.segment<3>(3 * q)); };
    hinges.push_back(makeHinge(p, at(p[0]), at(p[1]), at(p[2]), at(p[3]), rigidity));
  }
  return hinges;
}

Vec3 hingeVector(const Hinge& hinge, const double* x) {
  Vec3 b = Vec3::Zero();
  for (int a = 0; a < 4; ++a) b += hinge.weight[a] * Eigen::Map<const Vec3>(x + 3 * hinge.particle[a]);
  return b;
}

double hingeEnergy(const std::vector<Hinge>& hinges, Eigen::Ref<const Vector> x) {
  double e = 0.0;
  for (const Hinge& h : hinges) e += 0.5 * h.stiffness * hingeVector(h, x.data()).squaredNorm();
  return e;
}

HingeAdjacency HingeAdjacency::build(int particle_count, const std::vector<Hinge>& hinges) {
  HingeAdjacency a;
  a.offsets.assign(particle_count + 1, 0);
  for (const Hinge& h : hinges) {
    for (int p : h.particle) ++a.offsets[p + 1];
  }
  for (int p = 0; p < particle_count; ++p) a.offsets[p + 1] += a.offsets[p];
  a.hinge.resize(4 * hinges.size());
  a.slot.resize(4 * hinges.size());
  std::vector<int> next(a.offsets.begin(), a.offsets.end() - 1);
  for (int k = 0; k < static_cast<int>(hinges.size()); ++k) {
    for (int s = 0; s < 4; ++s) {
      const int e = next[hinges[k].particle[s]]++;
      a.hinge[e] = k;
      a.slot[e] = s;
    }
  }
  return a;
}

}  // namespace mysim
