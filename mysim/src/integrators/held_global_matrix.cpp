#include "integrators/held_global_matrix.h"

#include <algorithm>

namespace mysim {

bool HeldGlobalMatrix::factor(const Eigen::SparseMatrix<double>& lower,
                              const std::vector<int>& free_index, const ContactHolds& holds) {
  std::vector<Term> terms;
  for (const ContactHold& hold : holds.all()) {
    const int f = free_index[hold.particle];
    terms.push_back({f, kHoldWeight * lower.coeff(f, f), hold.whole, hold.normal, hold.point});
  }
  terms_ = std::move(terms);
  // The same holds as a recently factored set (a cloth resting on a plane, step after step, its
  // rounds alternating between plane and friction holds): only their points, which enter the
  // right-hand side alone, may differ.
  const auto same_matrix = [this](const Factored& f) {
    return std::ranges::equal(terms_, f.terms, [](const Term& a, const Term& b) {
      return a.unknown == b.unknown && a.weight == b.weight && a.whole == b.whole &&
             (a.whole || a.normal == b.normal);
    });
  };
  const auto found = std::ranges::find_if(recent_, same_matrix);
  if (found != recent_.end()) {
    current_ = found->factor.get();
    return true;
  }
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(3 * lower.nonZeros() + 9 * terms_.size());
  for (int column = 0; column < lower.outerSize(); ++column) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, column); it; ++it) {
      for (int c = 0; c < 3; ++c) entries.emplace_back(3 * it.row() + c, 3 * it.col() + c, it.value());
    }
  }
  for (const Term& t : terms_) {
    const Mat3 block = t.whole ? Mat3(t.weight * Mat3::Identity()) : Mat3(t.weight * t.normal * t.normal.transpose());
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b <= a; ++b) entries.emplace_back(3 * t.unknown + a, 3 * t.unknown + b, block(a, b));
    }
  }
  Eigen::SparseMatrix<double> matrix(3 * lower.rows(), 3 * lower.cols());
  matrix.setFromTriplets(entries.begin(), entries.end());
  auto factor = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower>>(matrix);
  if (factor->info() != Eigen::Success) return false;
  if (recent_.size() == kRecent) recent_.erase(recent_.begin());
  recent_.push_back({terms_, std::move(factor)});
  current_ = recent_.back().factor.get();
  return true;
}

void HeldGlobalMatrix::forget() {
  recent_.clear();
  current_ = nullptr;
}

void HeldGlobalMatrix::addHoldTerms(Vector& rhs) const {
  for (const Term& t : terms_) {
    rhs.segment<3>(3 * t.unknown) +=
        t.whole ? Vec3(t.weight * t.point) : Vec3((t.weight * t.normal.dot(t.point)) * t.normal);
  }
}

void HeldGlobalMatrix::solve(Vector& rhs) const { rhs = current_->solve(rhs); }

}  // namespace mysim
