#include "mysim/mesh_cloth.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace mysim {

std::expected<double, std::string> buildMeshCloth(const TriangleMesh& mesh,
                                                  const ClothMaterial& material, const Vec3& origin,
                                                  Model& model) {
  const int n = static_cast<int>(mesh.vertices.size());
  model.mass.setZero(n);
  model.pinned.assign(n, 0);
  model.start_position.resize(3 * n);
  model.start_velocity = Vector::Zero(3 * n);
  for (int p = 0; p < n; ++p) at3(model.start_position, p) = origin + mesh.vertices[p];
  // Each edge's adjacent area, and each vertex's third of its triangles.
  std::map<std::pair<int, int>, double> edge_area;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    if (!(area > 0.0)) {
      return std::unexpected("triangle (" + std::to_string(t[0]) + ", " + std::to_string(t[1]) +
                             ", " + std::to_string(t[2]) + ") has no area");
    }
    for (int k = 0; k < 3; ++k) {
      model.mass[t[k]] += material.density * area / 3.0;
      const int i = t[k], j = t[(k + 1) % 3];
      edge_area[{std::min(i, j), std::max(i, j)}] += area;
    }
  }
  for (int p = 0; p < n; ++p) {
    if (!(model.mass[p] > 0.0)) {
      return std::unexpected("vertex " + std::to_string(p) + " is in no triangle");
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
        return std::unexpected("the mesh is not flat at edge " + std::to_string(h.particle[0]) +
                               "-" + std::to_string(h.particle[1]) +
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
