#pragma once
// A uniform grid over points, for the self-collision broad phase and its metric, hashed into a
// table of twice the points' count (Teschner et al. 2003, "Optimized spatial hashing for
// collision detection of deformable objects"): each point filed under its cell's hash by a
// counting sort, so a cell's points are one contiguous range found in constant time. Cells that
// share a hash share a range: callers test geometry exactly, so that only costs a few extra
// candidates. Rebuilt each step (linear in the points) rather than kept up to date.
#include <cstdint>
#include <span>
#include <vector>

#include "mysim/types.h"

namespace mysim {

class SpatialGrid {
 public:
  // Files point k at points[k]; `cell` > 0 is the cell's side, m.
  void build(const std::vector<Vec3>& points, double cell);
  // Every point filed in a hash bucket of a cell the box [low, high] touches, each once,
  // calling f(index).
  template <typename F>
  void forEachNear(const Vec3& low, const Vec3& high, F f) const {
    bucketsOf(low, high);
    for (std::uint32_t bucket : buckets_) {
      for (std::uint32_t k = start_[bucket]; k < start_[bucket + 1]; ++k) f(order_[k]);
    }
  }
  double cell() const { return cell_; }

 private:
  Eigen::Vector3i cellOf(const Vec3& x) const;
  std::uint32_t bucketOf(const Eigen::Vector3i& c) const;
  // The distinct buckets of the box's cells, into buckets_.
  void bucketsOf(const Vec3& low, const Vec3& high) const;

  double cell_ = 1.0;
  std::uint32_t mask_ = 0;              // table size - 1 (a power of two)
  std::vector<std::uint32_t> start_;    // bucket b's points: order_[start_[b] .. start_[b + 1])
  std::vector<int> order_;              // the points, bucket by bucket
  std::vector<std::uint32_t> bucket_of_point_;
  mutable std::vector<std::uint32_t> buckets_;  // scratch of forEachNear
};

}  // namespace mysim
