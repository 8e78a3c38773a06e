#include "collider_drawing.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

#include "mysim/cloth_surface.h"

namespace viewer {
namespace {

const float kColliderColour[3] = {0.55f, 0.6f, 0.7f};

// The cloth is drawn as flat triangles between nodes that rest on the sphere (at radius +
// margin), so a triangle's middle dips below that surface by up to R - sqrt(R^2 - rho^2), rho
// the triangle's circumradius. Drawing the true sphere would show it through the cloth as dark
// holes where no node is inside; the sphere is drawn smaller by the largest such dip among the
// triangles near it (docs/viewer.md). Nodes really inside still show it.
double drawnSphereRadius(const mysim::Sphere& s, const mysim::Model& model,
                         const Eigen::Matrix<double, Eigen::Dynamic, 6>& rows) {
  const mysim::Sphere& sphere = s;
  const double surface = sphere.radius + sphere.margin;
  if (!model.grid) return sphere.radius;
  double dip = 0.0;
  for (const Eigen::Vector3i& t : mysim::gridTriangles(*model.grid)) {
    const Eigen::Vector3d a = rows.row(t[0]).head<3>(), b = rows.row(t[1]).head<3>(),
                          c = rows.row(t[2]).head<3>();
    if ((a - sphere.center).norm() > 1.5 * surface) continue;  // far from the sphere
    const double area2 = (b - a).cross(c - a).norm();
    if (area2 <= 0) continue;
    const double rho = (b - a).norm() * (c - b).norm() * (a - c).norm() / (2 * area2);
    dip =
        std::max(dip, rho < surface ? surface - std::sqrt(surface * surface - rho * rho) : surface);
  }
  return std::max(0.5 * sphere.radius, std::min(sphere.radius, surface - dip));
}

void drawSphere(const mysim::Sphere& true_sphere, double radius) {
  mysim::Sphere sphere = true_sphere;
  sphere.radius = radius;
  const int slices = 32, stacks = 16;
  for (int i = 0; i < stacks; ++i) {
    const double a0 = M_PI * i / stacks, a1 = M_PI * (i + 1) / stacks;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= slices; ++j) {
      const double b = 2 * M_PI * j / slices;
      for (double a : {a0, a1}) {
        const Eigen::Vector3d n(std::sin(a) * std::cos(b), std::cos(a), std::sin(a) * std::sin(b));
        glNormal3d(n.x(), n.y(), n.z());
        const Eigen::Vector3d p = sphere.center + sphere.radius * n;
        glVertex3d(p.x(), p.y(), p.z());
      }
    }
    glEnd();
  }
}

// A square of half-side `half` around `centre` in the plane with normal n.
void drawSquare(const Eigen::Vector3d& centre, const Eigen::Vector3d& n, double half) {
  const Eigen::Vector3d u = n.unitOrthogonal(), w = n.cross(u);
  glNormal3d(n.x(), n.y(), n.z());
  glBegin(GL_QUADS);
  for (const auto& [a, b] :
       {std::pair{-1, -1}, std::pair{1, -1}, std::pair{1, 1}, std::pair{-1, 1}}) {
    const Eigen::Vector3d p = centre + half * (a * u + b * w);
    glVertex3d(p.x(), p.y(), p.z());
  }
  glEnd();
}

void draw(const mysim::Sphere& s, const mysim::Model& model,
          const Eigen::Matrix<double, Eigen::Dynamic, 6>& rows) {
  drawSphere(s, drawnSphereRadius(s, model, rows));
}

// The infinite plane as a square under the particles: centred below their middle, twice as
// wide as they spread (at least 1 m).
void draw(const mysim::Plane& plane, const mysim::Model&,
          const Eigen::Matrix<double, Eigen::Dynamic, 6>& rows) {
  Eigen::Vector3d low = rows.leftCols<3>().colwise().minCoeff().transpose();
  Eigen::Vector3d high = rows.leftCols<3>().colwise().maxCoeff().transpose();
  const Eigen::Vector3d middle = 0.5 * (low + high);
  const Eigen::Vector3d foot = middle - plane.normal.dot(middle - plane.point) * plane.normal;
  drawSquare(foot, plane.normal, std::max(1.0, (high - low).norm()));
}

// How far the cloth's flat triangles cut into a box where they fold over its edges: the deepest
// triangle centroid or edge midpoint inside it. The box is drawn inset by that much, so its
// edges do not show through a cloth whose nodes all lie outside (as the sphere is drawn smaller).
double boxInset(const mysim::Box& box, const mysim::Model& model,
                const Eigen::Matrix<double, Eigen::Dynamic, 6>& rows) {
  if (!model.grid) return 0.0;
  double inset = 0.0;
  for (const Eigen::Vector3i& t : mysim::gridTriangles(*model.grid)) {
    const Eigen::Vector3d a = rows.row(t[0]).head<3>(), b = rows.row(t[1]).head<3>(),
                          c = rows.row(t[2]).head<3>();
    for (const Eigen::Vector3d& p : {Eigen::Vector3d((a + b + c) / 3), Eigen::Vector3d((a + b) / 2),
                                     Eigen::Vector3d((b + c) / 2), Eigen::Vector3d((c + a) / 2)}) {
      inset = std::max(inset, -mysim::signedDistance(box, p));
    }
  }
  return std::min(inset, 0.5 * box.half_extents.minCoeff());
}

void draw(const mysim::Box& true_box, const mysim::Model& model,
          const Eigen::Matrix<double, Eigen::Dynamic, 6>& rows) {
  mysim::Box box = true_box;
  box.half_extents.array() -= boxInset(true_box, model, rows);
  // Each face as a square scaled along its two in-plane axes.
  for (int axis = 0; axis < 3; ++axis) {
    for (double side : {-1.0, 1.0}) {
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      n[axis] = side;
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      glNormal3d(n.x(), n.y(), n.z());
      glBegin(GL_QUADS);
      for (const auto& [a, b] :
           {std::pair{-1, -1}, std::pair{1, -1}, std::pair{1, 1}, std::pair{-1, 1}}) {
        Eigen::Vector3d p = box.center + box.half_extents[axis] * n;
        p[u] += a * box.half_extents[u];
        p[w] += b * box.half_extents[w];
        glVertex3d(p.x(), p.y(), p.z());
      }
      glEnd();
    }
  }
}

}  // namespace

void drawCollider(const mysim::Collider& collider, const mysim::Model& model,
                  const Eigen::Matrix<double, Eigen::Dynamic, 6>& rows) {
  glColor3f(kColliderColour[0], kColliderColour[1], kColliderColour[2]);
  std::visit([&](const auto& shape) { draw(shape, model, rows); }, collider);
}

}  // namespace viewer
