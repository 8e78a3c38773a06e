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
  // Read from an OBJ file: its path and each triangle's line, so errors point into the file.
  std::string source;
  std::vector<int> lines;
  std::vector<std::string> warnings;  // what the reader skipped, with line numbers
  // "FILE:LINE: " of triangle t for a mesh read from a file, "" for a generated one.
  std::string where(int t) const;
  // A vertex as the user numbers it: the file's 1-based number, or the 0-based index.
  std::string vertexName(int v) const;
};

// A disc of `radius` in the x-z plane (normals +y) centred at the origin: the centre and `rings`
// concentric rings at k radius / rings, ring k of 6k vertices, neighbouring rings zipped into
// triangles by angle. Edges are radius / rings long within a few tens of per cent.
TriangleMesh discMesh(double radius, int rings);

// A Wavefront OBJ file's vertices (v) and faces (f, triangles or polygons fanned from their first
// vertex; v, v/vt, v//vn and v/vt/vn, negative indices relative). A UTF-8 byte-order mark is read
// past; the statements that do not shape a cloth (vt, vn, vp, o, g, s, mtllib, usemtl, comments)
// are skipped, and any other is skipped with a warning naming its lines. Errors name the file and
// line; a path that is not a regular file (a folder, a FIFO) is refused before it is opened.
std::expected<TriangleMesh, std::string> readObjMesh(const std::string& path);

}  // namespace mysim
