#pragma once
#include <optional>

#include "mysim/model.h"
#include "mysim/simulation.h"

namespace springcheck {

// How close a mesh came to itself over a run, the same for every engine (computed from the
// frames): a cloth's intersecting triangle pairs and its nearest node-triangle approach; a
// chain's nearest approach of two links. "Adjacent" pieces are excluded: a triangle sharing a
// vertex with another, a node on a triangle or joined by an edge to one of its corners, links
// sharing a node.
struct SelfContact {
  // Cloth only: the most pairs of triangles (sharing no vertex) that cross, in any frame.
  std::optional<int> intersections;
  double intersections_time = 0.0;  // s, the first frame with that many
  // The smallest distance between a node and a non-adjacent triangle (a chain: two links that
  // share no node) in any frame, m; nothing when no such pair ever came within a cell.
  std::optional<double> distance_min;
  double distance_time = 0.0;  // s
};

// Nothing for a system without triangles or links (the circle, free particles).
std::optional<SelfContact> selfContactOverRun(const mysim::Model& model, const mysim::RunRecord& run);

}  // namespace springcheck
