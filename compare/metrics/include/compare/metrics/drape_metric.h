#pragma once
#include <Eigen/Core>
#include <vector>

namespace springcheck {

// Rest shapes as (N x 3) node positions, m.
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3>;

// Per-node distance between two shapes of the same topology (node i against node i).
struct NodeDistance {
  double rms = 0.0;              // sqrt(mean |a_i - b_i|^2), m
  double max = 0.0;              // max |a_i - b_i|, m
  int argmax = -1;               // node where the max is
  std::vector<double> per_node;  // (N) |a_i - b_i|, m
};
NodeDistance nodeDistance(const Positions& a, const Positions& b);

}  // namespace springcheck
