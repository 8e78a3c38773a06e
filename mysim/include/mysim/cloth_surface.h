#pragma once
// The surface of a cloth model: its triangles (a grid's or a mesh's), vertex normals and OBJ
// output. (Building a cloth from a triangle mesh is mesh_cloth.h.)
#include <Eigen/Core>
#include <ostream>
#include <vector>

#include "mysim/model.h"

namespace mysim {

// Triangles of a grid cloth: two per cell, as (a, b, c) particle indices, counter-clockwise seen
// from the side the normals point to, each cell cut from (r, c + 1) to (r + 1, c), or with
// `other_cut` from (r, c) to (r + 1, c + 1) (hinge bending uses both, cloth_material.cpp).
std::vector<Eigen::Vector3i> gridTriangles(const GridShape& grid, bool other_cut = false);

// Per-vertex normals: the normalised sum of the normalised normals of the faces around each
// vertex (the seed's smooth shading). Every face counts equally, whatever its area.
std::vector<Vec3> vertexNormals(const GridShape& grid, const Vector& x);

// Writes the cloth as a Wavefront OBJ mesh: v, vn and f lines (1-based, v//vn).
void writeObj(std::ostream& out, const GridShape& grid, const Vector& x);
// The same for any triangle list (a mesh cloth), normals as vertexNormals computes them.
void writeObj(std::ostream& out, const std::vector<Eigen::Vector3i>& triangles, const Vector& x);

// A cloth model's triangles: its grid's, or its mesh's (empty for chains and particles).
std::vector<Eigen::Vector3i> clothTriangles(const Model& model);

}  // namespace mysim
