#include "mysim/spatial_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace mysim {

Eigen::Vector3i SpatialGrid::cellOf(const Vec3& x) const {
  return {static_cast<int>(std::floor(x.x() / cell_)), static_cast<int>(std::floor(x.y() / cell_)),
          static_cast<int>(std::floor(x.z() / cell_))};
}

std::uint32_t SpatialGrid::bucketOf(const Eigen::Vector3i& c) const {
  // Teschner et al.'s three large primes.
  const std::uint32_t h = (static_cast<std::uint32_t>(c.x()) * 73856093u) ^
                          (static_cast<std::uint32_t>(c.y()) * 19349663u) ^
                          (static_cast<std::uint32_t>(c.z()) * 83492791u);
  return h & mask_;
}

void SpatialGrid::build(const std::vector<Vec3>& points, double cell) {
  cell_ = cell;
  const std::uint32_t size = std::bit_ceil(std::max<std::uint32_t>(2 * points.size(), 16));
  mask_ = size - 1;
  start_.assign(size + 1, 0);
  bucket_of_point_.resize(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    bucket_of_point_[k] = bucketOf(cellOf(points[k]));
    ++start_[bucket_of_point_[k] + 1];
  }
  for (std::uint32_t b = 0; b < size; ++b) start_[b + 1] += start_[b];
  order_.resize(points.size());
  std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
  for (std::size_t k = 0; k < points.size(); ++k) order_[next[bucket_of_point_[k]]++] = static_cast<int>(k);
}

void SpatialGrid::bucketsOf(const Vec3& low, const Vec3& high) const {
  const Eigen::Vector3i a = cellOf(low), b = cellOf(high);
  buckets_.clear();
  for (int i = a.x(); i <= b.x(); ++i) {
    for (int j = a.y(); j <= b.y(); ++j) {
      for (int k = a.z(); k <= b.z(); ++k) buckets_.push_back(bucketOf({i, j, k}));
    }
  }
  std::sort(buckets_.begin(), buckets_.end());
  buckets_.erase(std::unique(buckets_.begin(), buckets_.end()), buckets_.end());
}

}  // namespace mysim
