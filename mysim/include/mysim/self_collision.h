#pragma once
// Self-collision: a cloth's nodes kept a thickness away from its own triangles (node-triangle)
// and its edges from one another (edge-edge); a chain's links from one another (edge-edge). The
// scene asks for it with "system": {"self_collision": {"thickness": METRES}} (docs/contact.md).
// Applied after each step, with the colliders, in every integrator: candidates gathered once
// through a uniform grid (spatial_grid.h), then kPasses Gauss-Seidel passes of mass-weighted
// pushes, each removing the approaching normal velocity (inelastic, frictionless). Which side a
// pair is on comes from where the step began, so a node that passed through a triangle within
// the step is put back on its own side rather than pushed on through.
#include <array>
#include <optional>
#include <vector>

#include "mysim/model.h"
#include "mysim/limit_error.h"

namespace mysim {

class SpatialGrid;

// The segments self-collision keeps apart: a cloth's triangle edges (each once), else the
// model's springs (a chain's links).
std::vector<std::array<int, 2>> selfCollisionEdges(const Model& model);

// The scene's thickness against its mesh: refused when it is larger than the shortest triangle
// edge or link at the start (a cell), or when a system without triangles or links asks for it.
// Pairs closer than the thickness at the start are the mesh's own neighbours (a flat cloth's
// diagonal lies 0.71 of a cell from the next cell's edge) and are never pushed.
std::optional<LimitError> checkSelfCollision(const Model& model);

class SelfCollision {
 public:
  explicit SelfCollision(const Model& model);  // model.self_collision_thickness must be set
  ~SelfCollision();
  // A copy shares nothing: its scratch (grids, candidates) starts empty.
  SelfCollision(const SelfCollision& other);
  SelfCollision& operator=(const SelfCollision&) = delete;
  // After a step from `start` (3N): pushes x and v apart where pairs are closer than the
  // thickness or crossed; returns how many pairs were pushed in the first pass.
  int resolve(Eigen::Ref<const Vector> start, Eigen::Ref<Vector> x, Eigen::Ref<Vector> v);

 private:
  struct Candidate {
    int a, b;  // node, triangle (node-triangle) or edge, edge (edge-edge)
  };
  void gather(Eigen::Ref<const Vector> start, Eigen::Ref<const Vector> x);
  bool pushNodeFromTriangle(const Candidate& c, Eigen::Ref<const Vector> start, Eigen::Ref<Vector> x,
                            Eigen::Ref<Vector> v) const;
  bool pushEdges(const Candidate& c, Eigen::Ref<const Vector> start, Eigen::Ref<Vector> x,
                 Eigen::Ref<Vector> v) const;
  bool apartAtRest(const Candidate& c, bool node_triangle) const;

  double thickness_;
  std::vector<Eigen::Vector3i> triangles_;
  std::vector<std::array<int, 2>> edges_;
  Vector inverse_mass_;  // (N) 0 for pinned particles
  Vector rest_;          // (3N) the model's start: pairs closer there are mesh neighbours
  std::unique_ptr<SpatialGrid> nodes_grid_, edges_grid_;
  std::vector<Candidate> node_triangle_, edge_edge_;
};

}  // namespace mysim
