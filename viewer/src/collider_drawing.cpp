#include "collider_drawing.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>

#include "mysim/cloth_surface.h"

namespace viewer {
namespace {

const float kColliderColour[3] = {0.55f, 0.6f, 0.7f};

// The points of a flat triangle that dip deepest into a surface its corners rest on: its
// centroid, its edges' midpoints, and its circumcentre when that lies inside it (an acute
// triangle's corners on a sphere: the circumcentre is the point nearest the centre).
struct Candidates {
  std::array<Eigen::Vector3d, 5> points;
  int count = 4;
  const Eigen::Vector3d* begin() const { return points.data(); }
  const Eigen::Vector3d* end() const { return points.data() + count; }
};
Candidates deepestCandidates(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  Candidates found;
  found.points = {(a + b + c) / 3, (a + b) / 2, (b + c) / 2, (c + a) / 2, Eigen::Vector3d::Zero()};
  const Eigen::Vector3d ab = b - a, ac = c - a, normal = ab.cross(ac);
  const bool acute = ab.dot(ac) > 0 && (a - b).dot(c - b) > 0 && (a - c).dot(b - c) > 0;
  if (acute && normal.squaredNorm() > 0) {
    found.points[found.count++] =
        a + (ac.squaredNorm() * normal.cross(ab) + ab.squaredNorm() * ac.cross(normal)) /
                (2 * normal.squaredNorm());
  }
  return found;
}

// How deep the cloth's flat triangles cut into the collider's true surface beyond their corners
// (0 when they do not, or the model has no grid): the collider is drawn inset by that much
// (docs/viewer.md). A node really inside is as deep as its triangles, so it still shows it.
double clothInset(const mysim::Collider& collider, const mysim::Model& model,
                  const Eigen::Matrix<double, Eigen::Dynamic, 6>& rows) {
  if (!model.grid) return 0.0;
  double inset = 0.0;
  for (const Eigen::Vector3i& t : mysim::gridTriangles(*model.grid)) {
    const Eigen::Vector3d a = rows.row(t[0]).head<3>(), b = rows.row(t[1]).head<3>(),
                          c = rows.row(t[2]).head<3>();
    const double corner_depth = std::max({0.0, -mysim::signedDistance(collider, a),
                                          -mysim::signedDistance(collider, b),
                                          -mysim::signedDistance(collider, c)});
    for (const Eigen::Vector3d& p : deepestCandidates(a, b, c)) {
      inset = std::max(inset, -mysim::signedDistance(collider, p) - corner_depth);
    }
  }
  return inset;
}

}  // namespace

void drawCollider(const mysim::Collider& collider, const mysim::Model& model,
                  const Eigen::Matrix<double, Eigen::Dynamic, 6>& rows) {
  const Eigen::Matrix3Xd positions = rows.leftCols<3>().transpose();
  const mysim::SurfaceMesh mesh = mysim::surfaceMesh(
      collider, mysim::drawingAround(positions, clothInset(collider, model, rows)));
  glColor3f(kColliderColour[0], kColliderColour[1], kColliderColour[2]);
  glBegin(GL_QUADS);
  for (const std::array<int, 4>& quad : mesh.quads) {
    for (int k : quad) {
      const Eigen::Vector3d& n = mesh.normals[k];
      const Eigen::Vector3d& p = mesh.points[k];
      glNormal3d(n.x(), n.y(), n.z());
      glVertex3d(p.x(), p.y(), p.z());
    }
  }
  glEnd();
}

}  // namespace viewer
