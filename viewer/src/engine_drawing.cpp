#include "engine_drawing.h"

#include <GLFW/glfw3.h>

#include <cmath>

#include "collider_drawing.h"
#include "mysim/cloth_surface.h"
#include "mysim/particle_system.h"

namespace viewer {
namespace {

using Rows = Eigen::Matrix<double, Eigen::Dynamic, 6>;

// The circle: the exact orbit and the point.
void drawCircle(const Rows& rows) {
  glDisable(GL_LIGHTING);
  glColor3f(0.5f, 0.5f, 0.5f);
  glBegin(GL_LINE_LOOP);
  for (int k = 0; k < 128; ++k) {
    glVertex3d(std::cos(2 * M_PI * k / 128), std::sin(2 * M_PI * k / 128), 0);
  }
  glEnd();
  glPointSize(10);
  glColor3f(1.0f, 0.8f, 0.2f);
  glBegin(GL_POINTS);
  glVertex3d(rows(0, 0), rows(0, 1), 0);
  glEnd();
}

void drawShadedCloth(const mysim::GridShape& grid, const Rows& rows) {
  mysim::Vector x(3 * rows.rows());
  for (int p = 0; p < rows.rows(); ++p) x.segment<3>(3 * p) = mysim::rowPosition(rows, p);
  const std::vector<mysim::Vec3> normals = mysim::vertexNormals(grid, x);
  glEnable(GL_LIGHTING);
  glColor3f(0.85f, 0.35f, 0.25f);
  glBegin(GL_TRIANGLES);
  for (const Eigen::Vector3i& t : mysim::gridTriangles(grid)) {
    for (int k = 0; k < 3; ++k) {
      glNormal3d(normals[t[k]].x(), normals[t[k]].y(), normals[t[k]].z());
      glVertex3d(rows(t[k], 0), rows(t[k], 1), rows(t[k], 2));
    }
  }
  glEnd();
}

// Springs as lines: structural white, shear blue, flex green.
void drawSprings(const mysim::Model& model, const Rows& rows) {
  glDisable(GL_LIGHTING);
  glBegin(GL_LINES);
  for (const mysim::Spring& s : model.springs) {
    switch (s.family) {
      case mysim::SpringFamily::Shear:
        glColor3f(0.4f, 0.7f, 1.0f);
        break;
      case mysim::SpringFamily::Flex:
        glColor3f(0.5f, 0.9f, 0.5f);
        break;
      default:
        glColor3f(0.95f, 0.95f, 0.95f);
    }
    glVertex3d(rows(s.i, 0), rows(s.i, 1), rows(s.i, 2));
    glVertex3d(rows(s.j, 0), rows(s.j, 1), rows(s.j, 2));
  }
  glEnd();
}

// Nodes as points, pinned ones red; over a shaded cloth only the pinned ones.
void drawNodes(const mysim::Model& model, const Rows& rows, bool shaded_cloth) {
  glDisable(GL_LIGHTING);
  glPointSize(model.grid ? 3 : 7);
  glBegin(GL_POINTS);
  for (int p = 0; p < rows.rows(); ++p) {
    if (shaded_cloth && !model.pinned[p]) continue;
    if (model.pinned[p]) {
      glColor3f(1.0f, 0.2f, 0.2f);
    } else {
      glColor3f(1.0f, 0.85f, 0.3f);
    }
    glVertex3d(rows(p, 0), rows(p, 1), rows(p, 2));
  }
  glEnd();
}

}  // namespace

void drawEngine(const ViewerSession& session, const EngineView& e) {
  if (!e.system) return;
  const Rows rows = e.system->particleRows(e.state);
  const mysim::ParticleSystem* ps = e.system->particles();
  if (!ps) {
    drawCircle(rows);
    return;
  }
  const mysim::Model& model = ps->model();
  glEnable(GL_LIGHTING);
  for (const mysim::Collider& c : model.colliders) drawCollider(c, model, rows);
  const bool shaded_cloth = model.grid && session.shaded();
  if (shaded_cloth) {
    drawShadedCloth(*model.grid, rows);
  } else {
    drawSprings(model, rows);
  }
  drawNodes(model, rows, shaded_cloth);
}

}  // namespace viewer
