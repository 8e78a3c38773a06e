#include "integrators/held_global_matrix.h"

namespace mysim {

bool HeldGlobalMatrix::factor(const Eigen::SparseMatrix<double>& lower,
                              const std::vector<int>& free_index, const ContactHolds& holds) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(3 * lower.nonZeros() + 9 * holds.all().size());
  Vector diagonal = Vector::Zero(lower.rows());
  for (int column = 0; column < lower.outerSize(); ++column) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, column); it; ++it) {
      for (int c = 0; c < 3; ++c) entries.emplace_back(3 * it.row() + c, 3 * it.col() + c, it.value());
      if (it.row() == it.col()) diagonal[it.row()] = it.value();
    }
  }
  terms_.clear();
  for (const ContactHold& hold : holds.all()) {
    const int f = free_index[hold.particle];
    const double k = kHoldWeight * diagonal[f];
    terms_.push_back({f, k, hold.whole, hold.normal, hold.point});
    const Mat3 block = hold.whole ? Mat3(k * Mat3::Identity()) : Mat3(k * hold.normal * hold.normal.transpose());
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b <= a; ++b) entries.emplace_back(3 * f + a, 3 * f + b, block(a, b));
    }
  }
  Eigen::SparseMatrix<double> matrix(3 * lower.rows(), 3 * lower.cols());
  matrix.setFromTriplets(entries.begin(), entries.end());
  factor_.compute(matrix);
  return factor_.info() == Eigen::Success;
}

void HeldGlobalMatrix::addHoldTerms(Vector& rhs) const {
  for (const Term& t : terms_) {
    rhs.segment<3>(3 * t.unknown) +=
        t.whole ? Vec3(t.weight * t.point) : Vec3((t.weight * t.normal.dot(t.point)) * t.normal);
  }
}

void HeldGlobalMatrix::solve(Vector& rhs) const { rhs = factor_.solve(rhs); }

}  // namespace mysim
