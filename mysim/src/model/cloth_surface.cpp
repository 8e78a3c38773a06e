#include "mysim/cloth_surface.h"

namespace mysim {

std::vector<Eigen::Vector3i> gridTriangles(const GridShape& grid, bool other_cut) {
  std::vector<Eigen::Vector3i> triangles;
  triangles.reserve(2 * (grid.rows - 1) * (grid.cols - 1));
  for (int r = 0; r + 1 < grid.rows; ++r) {
    for (int c = 0; c + 1 < grid.cols; ++c) {
      const int a = r * grid.cols + c, b = a + 1, d = a + grid.cols, e = d + 1;
      if (other_cut) {
        triangles.emplace_back(a, b, e);
        triangles.emplace_back(a, e, d);
      } else {
        triangles.emplace_back(a, b, d);
        triangles.emplace_back(b, e, d);
      }
    }
  }
  return triangles;
}

namespace {

std::vector<Vec3> normalsOf(const std::vector<Eigen::Vector3i>& triangles, const Vector& x) {
  std::vector<Vec3> normals(x.size() / 3, Vec3::Zero());
  for (const Eigen::Vector3i& t : triangles) {
    const Vec3 face = (at3(x, t[1]) - at3(x, t[0])).cross(at3(x, t[2]) - at3(x, t[0]));
    const double length = face.norm();
    if (length == 0.0) continue;  // a collapsed triangle has no direction to add
    for (int k = 0; k < 3; ++k) normals[t[k]] += face / length;
  }
  for (Vec3& n : normals) {
    const double length = n.norm();
    if (length > 0.0) n /= length;
  }
  return normals;
}

void writeObjBody(std::ostream& out, const std::vector<Eigen::Vector3i>& triangles, const Vector& x) {
  const std::vector<Vec3> normals = normalsOf(triangles, x);
  out.precision(9);
  for (std::size_t p = 0; p < normals.size(); ++p) {
    out << "v " << x[3 * p] << ' ' << x[3 * p + 1] << ' ' << x[3 * p + 2] << '\n';
  }
  for (const Vec3& n : normals) out << "vn " << n.x() << ' ' << n.y() << ' ' << n.z() << '\n';
  for (const Eigen::Vector3i& t : triangles) {
    out << "f";
    for (int k = 0; k < 3; ++k) out << ' ' << t[k] + 1 << "//" << t[k] + 1;
    out << '\n';
  }
}

}  // namespace

std::vector<Vec3> vertexNormals(const GridShape& grid, const Vector& x) {
  return normalsOf(gridTriangles(grid), x.head(3 * grid.rows * grid.cols));
}

void writeObj(std::ostream& out, const std::vector<Eigen::Vector3i>& triangles, const Vector& x) {
  out << "# springcheck cloth, " << x.size() / 3 << " vertices\n";
  writeObjBody(out, triangles, x);
}

void writeObj(std::ostream& out, const GridShape& grid, const Vector& x) {
  out << "# springcheck cloth " << grid.rows << " x " << grid.cols << "\n";
  writeObjBody(out, gridTriangles(grid), x.head(3 * grid.rows * grid.cols));
}

std::vector<Eigen::Vector3i> clothTriangles(const Model& model) {
  if (model.grid) return gridTriangles(*model.grid);
  return model.mesh_triangles;
}

}  // namespace mysim
