#include "compare/metrics/mirror_symmetry.h"

#include <cmath>
#include <map>

#include "mysim/collider.h"

namespace springcheck {
namespace {

using mysim::Vec3;

Vec3 reflectPoint(const MirrorSymmetry& m, const Vec3& x) {
  return x - 2.0 * (x - m.point).dot(m.normal) * m.normal;
}
Vec3 reflectVector(const MirrorSymmetry& m, const Vec3& v) {
  return v - 2.0 * v.dot(m.normal) * m.normal;
}

bool same(const Vec3& a, const Vec3& b, double tolerance) { return (a - b).norm() <= tolerance; }

// Whether every part of the model maps onto itself under the candidate.
bool isSymmetric(const mysim::Model& model, const MirrorSymmetry& m, double tolerance) {
  if (model.wind) return false;
  const int n = model.particleCount();
  for (int p = 0; p < n; ++p) {
    const int q = m.image[p];
    if (!same(reflectPoint(m, mysim::at3(model.start_position, p)), mysim::at3(model.start_position, q),
              tolerance) ||
        !same(reflectVector(m, mysim::at3(model.start_velocity, p)), mysim::at3(model.start_velocity, q),
              tolerance) ||
        model.mass[p] != model.mass[q] || model.pinned[p] != model.pinned[q]) {
      return false;
    }
  }
  // Springs: each one's image is a spring with the same constants.
  std::map<std::pair<int, int>, const mysim::Spring*> by_ends;
  for (const mysim::Spring& s : model.springs) by_ends[{std::min(s.i, s.j), std::max(s.i, s.j)}] = &s;
  for (const mysim::Spring& s : model.springs) {
    const int i = m.image[s.i], j = m.image[s.j];
    const auto it = by_ends.find({std::min(i, j), std::max(i, j)});
    // Rest lengths are measured from the start positions: a mirrored pair's differ by round-off.
    if (it == by_ends.end() || std::abs(it->second->rest_length - s.rest_length) > tolerance ||
        it->second->stiffness != s.stiffness || it->second->damping != s.damping) {
      return false;
    }
  }
  const double g = std::max(1.0, model.gravity.norm());
  if (!same(reflectVector(m, model.gravity), model.gravity, 1e-12 * g)) return false;
  if (model.pin_motion && !same(reflectVector(m, model.pin_motion->axis), model.pin_motion->axis, 1e-12)) {
    return false;
  }
  // Each collider's surface maps onto itself: sampled at points around it (its signed distance
  // field must be the same at a point and at its mirror image).
  for (const mysim::Collider& c : model.colliders) {
    for (int p = 0; p < n; ++p) {
      const Vec3 x = mysim::at3(model.start_position, p);
      if (std::abs(mysim::signedDistance(c, x) - mysim::signedDistance(c, reflectPoint(m, x))) > tolerance) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace

std::optional<MirrorSymmetry> mirrorSymmetry(const mysim::Model& model) {
  if (!model.grid || model.particleCount() < 2) return std::nullopt;
  const int rows = model.grid->rows, cols = model.grid->cols;
  if (rows * cols != model.particleCount()) return std::nullopt;
  const mysim::Vector& x = model.start_position;
  Vec3 low = mysim::at3(x, 0), high = low, centre = Vec3::Zero();
  for (int p = 0; p < model.particleCount(); ++p) {
    low = low.cwiseMin(mysim::at3(x, p));
    high = high.cwiseMax(mysim::at3(x, p));
    centre += mysim::at3(x, p);
  }
  centre /= model.particleCount();
  const double tolerance = 1e-9 * std::max(1e-3, (high - low).norm());
  auto at = [&](int r, int c) { return mysim::at3(x, r * cols + c); };
  struct Candidate {
    const char* across;
    Vec3 axis;
    int (*image)(int r, int c, int rows, int cols);
  };
  const Candidate candidates[] = {
      {"columns", at(0, cols - 1) - at(0, 0),
       [](int r, int c, int, int cols) { return r * cols + (cols - 1 - c); }},
      {"rows", at(rows - 1, 0) - at(0, 0),
       [](int r, int c, int rows, int cols) { return (rows - 1 - r) * cols + c; }},
  };
  for (const Candidate& candidate : candidates) {
    if (candidate.axis.norm() == 0.0) continue;
    MirrorSymmetry m{centre, candidate.axis.normalized(), {}, candidate.across};
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) m.image.push_back(candidate.image(r, c, rows, cols));
    }
    if (isSymmetric(model, m, tolerance)) return m;
  }
  return std::nullopt;
}

Positions mirrored(const MirrorSymmetry& mirror, const Positions& b) {
  Positions out(b.rows(), 3);
  for (int p = 0; p < b.rows(); ++p) {
    out.row(mirror.image[p]) = reflectPoint(mirror, b.row(p).transpose()).transpose();
  }
  return out;
}

}  // namespace springcheck
