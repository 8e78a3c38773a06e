#include "model/mesh_cloth.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace mysim {

namespace {

// Each edge's adjacent area, and into `mass` each vertex's third of its triangles' mass; refuses
// a triangle without area (or whose area overflows) and an edge of more than two triangles.
std::expected<std::map<std::pair<int, int>, double>, std::string> lumpTriangles(
    const TriangleMesh& mesh, double density, Vector& mass) {
  std::map<std::pair<int, int>, double> edge_area;
  std::map<std::pair<int, int>, std::vector<int>> edge_triangles;
  for (int k = 0; k < static_cast<int>(mesh.triangles.size()); ++k) {
    const Eigen::Vector3i& t = mesh.triangles[k];
    const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const std::string corners = "(" + mesh.vertexName(t[0]) + ", " + mesh.vertexName(t[1]) +
                                ", " + mesh.vertexName(t[2]) + ")";
    if (std::isinf(area) || (std::isnan(area) && (b - a).allFinite() && (c - a).allFinite())) {
      return std::unexpected(mesh.where(k) + "triangle " + corners +
                             ": its area overflows a double (coordinates too large: use metres)");
    }
    if (!(area > 0.0)) {
      return std::unexpected(mesh.where(k) + "triangle " + corners + " has no area");
    }
    for (int e = 0; e < 3; ++e) {
      mass[t[e]] += density * area / 3.0;
      const int i = t[e], j = t[(e + 1) % 3];
      edge_area[{std::min(i, j), std::max(i, j)}] += area;
      edge_triangles[{std::min(i, j), std::max(i, j)}].push_back(k);
    }
  }
  for (const auto& [edge, triangles] : edge_triangles) {
    if (triangles.size() <= 2) continue;
    std::string faces;  // the faces' lines in the file, or the triangles' indices
    for (int t : triangles) {
      faces += (faces.empty() ? "" : ", ") +
               std::to_string(mesh.source.empty() ? t : mesh.lines[t]);
    }
    return std::unexpected(mesh.where(triangles[2]) + "edge " + mesh.vertexName(edge.first) + "-" +
                           mesh.vertexName(edge.second) + " is shared by " +
                           std::to_string(triangles.size()) + " triangles (" +
                           (mesh.source.empty() ? "triangles " : "lines ") + faces +
                           "; non-manifold): a cloth's edge joins at most two");
  }
  return edge_area;
}

}  // namespace

std::expected<double, std::string> buildMeshCloth(const TriangleMesh& mesh,
                                                  const ClothMaterial& material, const Vec3& origin,
                                                  Model& model) {
  const int n = static_cast<int>(mesh.vertices.size());
  model.mass.setZero(n);
  model.pinned.assign(n, 0);
  model.start_position.resize(3 * n);
  model.start_velocity = Vector::Zero(3 * n);
  for (int p = 0; p < n; ++p) at3(model.start_position, p) = origin + mesh.vertices[p];
  auto lumped = lumpTriangles(mesh, material.density, model.mass);
  if (!lumped) return std::unexpected(lumped.error());
  const std::map<std::pair<int, int>, double>& edge_area = *lumped;
  for (int p = 0; p < n; ++p) {
    if (!(model.mass[p] > 0.0)) {
      return std::unexpected(mesh.source + (mesh.source.empty() ? "" : ": ") + "vertex " +
                             mesh.vertexName(p) + " is in no triangle");
    }
  }
  std::vector<Spring> springs;
  springs.reserve(edge_area.size());
  for (const auto& [edge, area] : edge_area) {
    const double length = (mesh.vertices[edge.second] - mesh.vertices[edge.first]).norm();
    springs.push_back({edge.first, edge.second, length,
                       material.stretch_stiffness * area / (length * length), 0.0,
                       SpringFamily::Structural});
  }
  model.springs = SpringList(std::move(springs));
  model.mesh_triangles = mesh.triangles;
  if (material.bending == BendingModel::Hinge) {
    model.hinges = meshHinges(mesh.triangles, model.start_position, material.bending_rigidity);
    for (const Hinge& h : model.hinges) {
      const Vec3 rest = hingeVector(h, model.start_position.data());
      const double edge = (at3(model.start_position, h.particle[1]) -
                           at3(model.start_position, h.particle[0])).norm();
      if (rest.norm() > 1e-9 * edge * std::abs(h.weight[2])) {
        return std::unexpected(mesh.source + (mesh.source.empty() ? "" : ": ") +
                               "the mesh is not flat at edge " + mesh.vertexName(h.particle[0]) +
                               "-" + mesh.vertexName(h.particle[1]) +
                               ": hinge bending bends about a flat rest state (rest angle 0)");
      }
    }
  }
  double mean_edge = 0.0;
  for (const Spring& s : model.springs) mean_edge += s.rest_length / model.springs.size();
  model.material = MaterialSource{material, mean_edge, mean_edge, false};
  return material.damping_rate * model.mass.sum() / n;
}

}  // namespace mysim
