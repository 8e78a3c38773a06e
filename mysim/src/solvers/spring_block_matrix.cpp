#include "solvers/spring_block_matrix.h"

#include <Eigen/LU>
#include <algorithm>

namespace mysim {
namespace {

// Below this many rows one thread is faster (see particle_system.cpp).
constexpr int kParallelRows = 512;

// One neighbour's alpha x_j + s (s . x_j), added to (sx, sy, sz).
inline void addNeighbour(const SpringBlockMatrix::Block& b, const double* xj, double& sx,
                         double& sy, double& sz) {
  const double along = b.s.x() * xj[0] + b.s.y() * xj[1] + b.s.z() * xj[2];
  sx += b.alpha * xj[0] + along * b.s.x();
  sy += b.alpha * xj[1] + along * b.s.y();
  sz += b.alpha * xj[2] + along * b.s.z();
}

// sum over entries [begin, end) of the row's neighbours' (alpha x_j + s (s . x_j)).
inline Vec3 neighbourSum(const std::vector<SpringBlockMatrix::Block>& blocks, const auto* entries,
                         int begin, int end, const double* x) {
  double sx = 0, sy = 0, sz = 0;
  for (int e = begin; e < end; ++e) {
    addNeighbour(blocks[entries[e].spring], x + 3 * entries[e].column, sx, sy, sz);
  }
  return Vec3(sx, sy, sz);
}

}  // namespace

SpringBlockMatrix::SpringBlockMatrix(const SpringAdjacency& adjacency,
                                     const std::vector<int>& free_index, int spring_count)
    : blocks_(spring_count) {
  const int n = static_cast<int>(free_index.size());
  // At most these sizes (pinned rows and columns are left out): grown by doubling they held up
  // to twice that at a large cloth's peak memory.
  row_offsets_.reserve(n + 1);
  upper_begin_.reserve(n);
  entries_.reserve(adjacency.other.size());
  row_offsets_.push_back(0);
  for (int p = 0; p < n; ++p) {
    const int row = free_index[p];
    if (row < 0) continue;
    const std::size_t first = entries_.size();
    for (int e = adjacency.offsets[p]; e < adjacency.offsets[p + 1]; ++e) {
      const int column = free_index[adjacency.other[e]];
      if (column >= 0) entries_.push_back({column, adjacency.spring[e]});
    }
    // Columns in order: lower triangle first, and neighbours' x read in memory order.
    std::sort(entries_.begin() + first, entries_.end(), [](const Entry& a, const Entry& b) {
      return a.column != b.column ? a.column < b.column : a.spring < b.spring;
    });
    const auto upper = std::find_if(entries_.begin() + first, entries_.end(),
                                    [row](const Entry& e) { return e.column > row; });
    upper_begin_.push_back(static_cast<int>(upper - entries_.begin()));
    row_offsets_.push_back(static_cast<int>(entries_.size()));
  }
  diagonal_.resize(upper_begin_.size());
  inverse_.resize(upper_begin_.size());
}

void SpringBlockMatrix::factorDiagonal(bool whole_blocks) {
  const int n = rows();
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
  for (int i = 0; i < n; ++i) {
    // Whole blocks keep the coupling of a particle's x, y and z through its springs' directions
    // (the s s^T terms) that the scalar diagonal drops; each block is SPD (mass plus PSD spring
    // terms), so it inverts.
    inverse_[i] = whole_blocks ? Mat3(diagonal_[i].inverse())
                               : Mat3(diagonal_[i].diagonal().cwiseInverse().asDiagonal());
  }
}

std::pair<int, int> SpringBlockMatrix::entries(int row, Part part) const {
  switch (part) {
    case Part::Lower:
      return {row_offsets_[row], upper_begin_[row]};
    case Part::Upper:
      return {upper_begin_[row], row_offsets_[row + 1]};
    case Part::Both:
      break;
  }
  return {row_offsets_[row], row_offsets_[row + 1]};
}

Vec3 SpringBlockMatrix::neighbours(int row, Part part, const double* x) const {
  const auto [begin, end] = entries(row, part);
  return neighbourSum(blocks_, entries_.data(), begin, end, x);
}

void SpringBlockMatrix::multiplyPart(const Vector& x, Vector& y, double diagonal_scale,
                                     Part part) const {
  const int n = rows();
  y.resize(x.size());
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
  for (int i = 0; i < n; ++i) {
    y.segment<3>(3 * i) =
        (diagonal_[i] * x.segment<3>(3 * i)) * diagonal_scale - neighbours(i, part, x.data());
  }
}

// A_ij = -N_ij, so "minus sum A_ij y_j" adds the neighbour sums. Lower: rows in order, each
// reading the rows before it; upper: in reverse.
void SpringBlockMatrix::sweep(const Vector& r, Vector& y, Part part) const {
  const int n = rows();
  y.resize(r.size());
  for (int k = 0; k < n; ++k) {
    const int i = part == Part::Lower ? k : n - 1 - k;
    const Vec3 sum = r.segment<3>(3 * i) + neighbours(i, part, y.data());
    y.segment<3>(3 * i) = omega_ * (inverse_[i] * sum);
  }
}

void SpringBlockMatrix::multiply(const Vector& in, Vector& out) const {
  multiplyPart(in, out, 1.0, Part::Both);
}

void SpringBlockMatrix::appendLowerTriangle(std::vector<Eigen::Triplet<double>>& out) const {
  for (int i = 0; i < rows(); ++i) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c <= r; ++c) out.emplace_back(3 * i + r, 3 * i + c, diagonal_[i](r, c));
    }
    for (int e = row_offsets_[i]; e < upper_begin_[i]; ++e) {  // columns below the row
      const Block& b = blocks_[entries_[e].spring];
      const Mat3 block = b.alpha * Mat3::Identity() + b.s * b.s.transpose();
      const int j = entries_[e].column;
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) out.emplace_back(3 * i + r, 3 * j + c, -block(r, c));
      }
    }
  }
}

void SpringBlockMatrix::applyDiagonalInverse(const Vector& r, Vector& z) const {
  const int n = rows();
  z.resize(r.size());
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
  for (int i = 0; i < n; ++i) z.segment<3>(3 * i).noalias() = inverse_[i] * r.segment<3>(3 * i);
}

void SpringBlockMatrix::prepareSsor(double w) {
  factorDiagonal(true);
  omega_ = w;
}

void SpringBlockMatrix::solveLower(const Vector& r, Vector& y) const { sweep(r, y, Part::Lower); }
void SpringBlockMatrix::solveUpper(const Vector& r, Vector& y) const { sweep(r, y, Part::Upper); }
void SpringBlockMatrix::multiplyLower(const Vector& x, Vector& y) const {
  multiplyPart(x, y, 1.0 / omega_, Part::Lower);
}
void SpringBlockMatrix::multiplyUpper(const Vector& x, Vector& y) const {
  multiplyPart(x, y, 1.0 / omega_, Part::Upper);
}

void SpringBlockMatrix::multiplyDiagonal(const Vector& x, Vector& y, double scale) const {
  const int n = rows();
  y.resize(x.size());
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
  for (int i = 0; i < n; ++i) y.segment<3>(3 * i) = scale * (diagonal_[i] * x.segment<3>(3 * i));
}

}  // namespace mysim
