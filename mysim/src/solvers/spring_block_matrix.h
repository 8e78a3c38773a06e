#pragma once
#include <Eigen/SparseCore>
#include <utility>
#include <vector>

#include "mysim/spring_adjacency.h"
#include "mysim/types.h"

namespace mysim {

// Backward Euler's matrix over the free particles, never assembled:
//   A = D - sum over springs between free particles of their blocks,
// a spring's block alpha I + s s^T (s = sqrt(beta) u, the ImplicitSpringBlock written with 4
// numbers instead of 7) stored once per spring, D_p the 3x3 diagonal block of free particle p.
// Each free row lists its free neighbours (column, spring) once, lower columns first, so the
// product gathers per row (parallel, no write conflicts, fixed order: the same bits at any
// thread count) and the Gauss-Seidel sweeps find the two triangles without a test.
//
// Per step a row moves its entries (8 B each), its two 3x3 blocks and each spring's 32 B, about
// 400 B a cloth particle where a block per incidence (alpha, beta, ja, jb, u) moved 750.
class SpringBlockMatrix {
 public:
  struct Block {
    double alpha = 0.0;
    Vec3 s = Vec3::Zero();
  };

  // Topology, once: free_index (N) is each particle's row, -1 if pinned.
  SpringBlockMatrix(const SpringAdjacency& adjacency, const std::vector<int>& free_index,
                    int spring_count);

  int rows() const { return static_cast<int>(diagonal_.size()); }
  std::vector<Block>& blocks() { return blocks_; }  // (S) filled by the integrator each step
  std::vector<Mat3>& diagonal() { return diagonal_; }

  // After blocks and diagonal are filled: the inverses of the diagonal blocks (or of their
  // diagonals) for the Jacobi preconditioners.
  void factorDiagonal(bool whole_blocks);
  // Or, for block SSOR with relaxation w: the block inverses and the sweeps' links (below).
  void prepareSsor(double w);
  double ssorOmega() const { return omega_; }

  // out = A in.
  void multiply(const Vector& in, Vector& out) const;
  // Appends A's lower triangle, scalar entries with the diagonal blocks' (for StepFactor): every
  // spring's block, zero or not, so the pattern is the same each step.
  void appendLowerTriangle(std::vector<Eigen::Triplet<double>>& out) const;
  // z = P^-1 r for P the (block) diagonal.
  void applyDiagonalInverse(const Vector& r, Vector& z) const;

  // Block SSOR's factors, after prepareSsor(w): F = D/w + L and F^T = D/w + U, L and U the strict
  // block triangles of A, so P = F (D/w)^-1 F^T is the SSOR preconditioner and
  // A = F + F^T + (1 - 2/w) D (ssor_conjugate_gradient.h uses both). The solves are sequential
  // sweeps in row order.
  void solveLower(const Vector& r, Vector& y) const;                      // y = F^-1 r
  void solveUpper(const Vector& r, Vector& y) const;                      // y = F^-T r
  void multiplyLower(const Vector& x, Vector& y) const;                   // y = F x
  void multiplyUpper(const Vector& x, Vector& y) const;                   // y = F^T x
  void multiplyDiagonal(const Vector& x, Vector& y, double scale) const;  // y = scale D x

 private:
  enum class Part { Both, Lower, Upper };  // a row's neighbours: all, columns below, above
  std::pair<int, int> entries(int row, Part part) const;       // [begin, end) into entries_
  Vec3 neighbours(int row, Part part, const double* x) const;  // sum of N_ij x_j over the part
  void multiplyPart(const Vector& x, Vector& y, double diagonal_scale, Part part) const;
  void sweep(const Vector& r, Vector& y, Part part) const;  // y = F^-1 r or F^-T r

  struct Entry {
    int column;
    int spring;
  };
  std::vector<int> row_offsets_;  // (F + 1) entries of row i: [row_offsets_[i], row_offsets_[i+1])
  std::vector<int> upper_begin_;  // (F) first entry with column > i
  std::vector<Entry> entries_;    // free neighbours only
  std::vector<Block> blocks_;     // (S)
  std::vector<Mat3> diagonal_;    // (F)
  std::vector<Mat3> inverse_;     // (F) inverse of each diagonal block (or of its diagonal)
  double omega_ = 1.0;
};

}  // namespace mysim
