#pragma once
#include <expected>
#include <string>
#include <vector>

#include "mysim/types.h"

namespace mysim {

// A cloth that is not a grid: vertices and triangles (0-based, counter-clockwise seen from the
// side the normals point to).
struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<Eigen::Vector3i> triangles;
};

// A disc of `radius` in the x-z plane (normals +y) centred at the origin: the centre and `rings`
// concentric rings at k radius / rings, ring k of 6k vertices, neighbouring rings zipped into
// triangles by angle. Edges are radius / rings long within a few tens of per cent.
TriangleMesh discMesh(double radius, int rings);

// A Wavefront OBJ file's vertices (v) and faces (f, triangles or polygons fanned from their first
// vertex; v, v/vt, v//vn and v/vt/vn, negative indices relative); other lines are ignored. Errors
// name the file and line.
std::expected<TriangleMesh, std::string> readObjMesh(const std::string& path);

}  // namespace mysim
