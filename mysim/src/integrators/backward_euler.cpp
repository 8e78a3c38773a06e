#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "solvers/conjugate_gradient.h"
#include "integrators/contact_holds.h"
#include "mysim/integrator.h"
#include "mysim/particle_system.h"
#include "solvers/spring_block_matrix.h"
#include "solvers/ssor_conjugate_gradient.h"
#include "solvers/step_factor.h"
#include "core/parallel_threshold.h"

namespace mysim {
namespace {


// Backward Euler as in Baraff and Witkin, "Large steps in cloth simulation" (SIGGRAPH 1998),
// eq. 16: one Newton step of v1 = v0 + h M^-1 f(x0 + h v1, v1), linearised at (x0, v0):
//   (M - h df/dv - h^2 df/dx) dv = h (f0 + h df/dx v0),   v1 = v0 + dv,   x1 = x0 + h v1.
// df/dx uses each spring's elastic Jacobian with the compressive term clamped (SPD, see
// spring.h); df/dv holds spring damping and drag. Solved by preconditioned conjugate gradient
// over the free particles only (SpringBlockMatrix): pinned velocities are known, so their
// columns move to the right-hand side. Particles the step puts inside a collider are held on it
// and the step solved again (integrators/contact_holds.h, holdContacts below). First order;
// unconditionally stable on an oscillator, where the amplitude shrinks by 1/sqrt(1 + (h w)^2) a
// step.
class BackwardEuler final : public Integrator {
 public:
  BackwardEuler(double tolerance, int max_iterations, CgPreconditioner preconditioner)
      : tolerance_(tolerance), max_iterations_(max_iterations), preconditioner_(preconditioner) {}

  StepCounts step(OdeSystem& system, State& s, double h) override {
    ParticleSystem& ps = *system.particles();
    const Model& model = ps.model();
    const int n = ps.particleCount(), n3 = 3 * n;
    if (!matrix_) numberFreeParticles(ps);

    v0_ = s.y.tail(n3);
    const auto x = s.y.head(n3);
    const auto v = s.y.tail(n3);
    f_.resize(n3);
    ps.force(s.t, x, v, f_);

    // Known velocity change of pinned particles.
    dv_known_.setZero(n3);
    const Vec3 pin_velocity_end = ps.pinVelocity(s.t + h);
    for (int p = 0; p < n; ++p) {
      if (model.pinned[p]) dv_known_.segment<3>(3 * p) = pin_velocity_end - v.segment<3>(3 * p);
    }
    fillSprings(ps, x, v, h);
    fillRows(ps, h);
    if (!model.hinges.empty()) addHinges(ps, v, h);
    const CgResult cg = solve(ps, h);
    StepCounts counts{.accepted = 1, .derivative_evaluations = 1};
    counts.linear_iterations = cg.iterations;
    if (!cg.converged) counts.solver_failures = 1;
    endVelocities(ps, s);
    if (holdContacts(ps, h, s, counts)) endVelocities(ps, s);
    s.y.head(n3) += h * s.y.tail(n3);
    s.t += h;
    system.afterStep(s);
    return counts;
  }

 private:
  // The step's linear system A dv = b, solved for dv_free_ (warm-started from the last step's).
  CgResult solve(const ParticleSystem& ps, double h) {
    const SpringBlockMatrix& A = *matrix_;
    // The factor, where chosen and positive definite (else block Jacobi, below); refactored only
    // when the last solve with it took more than kStaleIterations.
    const bool factoring = preconditionerFor(h) == CgPreconditioner::Cholesky;
    if (factoring && (!factored_ || refactor_)) factored_ = factorStep(ps, h);
    exact_ = factoring && factored_;
    if (exact_) {
      const CgResult cg = conjugateGradient(
          [this, &ps, h](const Vector& in, Vector& out) { multiply(ps, h, in, out); },
          [this](const Vector& r, Vector& z) { factor_.solve(r, z); }, rhs_, dv_free_, tolerance_,
          max_iterations_);
      refactor_ = cg.iterations > kStaleIterations;
      return cg;
    }
    if (!ps.model().hinges.empty()) {
      // The hinges' constant blocks beside the springs' (addHinges); SSOR sweeps the spring
      // matrix's own storage, so hinge scenes take block Jacobi (the scene reader refuses ssor).
      matrix_->factorDiagonal(true);
      return conjugateGradient([this, &ps, h](const Vector& in, Vector& out) { multiply(ps, h, in, out); },
                               [&A](const Vector& r, Vector& z) { A.applyDiagonalInverse(r, z); },
                               rhs_, dv_free_, tolerance_, max_iterations_);
    }
    if (preconditionerFor(h) == CgPreconditioner::Ssor) {
      matrix_->prepareSsor(kSsorOmega);
      return ssorConjugateGradient(A, rhs_, dv_free_, tolerance_, max_iterations_);
    }
    matrix_->factorDiagonal(preconditionerFor(h) == CgPreconditioner::BlockJacobi);
    return conjugateGradient([&A](const Vector& in, Vector& out) { A.multiply(in, out); },
                             [&A](const Vector& r, Vector& z) { A.applyDiagonalInverse(r, z); },
                             rhs_, dv_free_, tolerance_, max_iterations_);
  }

  // out = A in: the springs' blocks and, with hinges, theirs.
  void multiply(const ParticleSystem& ps, double h, const Vector& in, Vector& out) const {
    matrix_->multiply(in, out);
    if (!ps.model().hinges.empty()) multiplyHinges(ps, h, in, out);
  }

  // v1 = v0 + dv: the solved dv of free particles, the known one of pinned.
  void endVelocities(const ParticleSystem& ps, State& s) const {
    const int n = ps.particleCount(), n3 = 3 * n;
    for (int p = 0; p < n; ++p) {
      const Vec3 dv = free_index_[p] >= 0 ? Vec3(dv_free_.segment<3>(3 * free_index_[p]))
                                          : Vec3(dv_known_.segment<3>(3 * p));
      s.y.segment<3>(n3 + 3 * p) = v0_.segment<3>(3 * p) + dv;
    }
  }

  // Contacts inside the step (integrators/contact_holds.h): rounds of holds on x1 = x0 + h v1, each
  // re-solving the system with the held particles' velocity constrained (solveHeld); whether
  // any particle was held (s then holds the first solve's v1).
  bool holdContacts(const ParticleSystem& ps, double h, const State& s, StepCounts& counts) {
    if (ps.model().colliders.empty() && !ps.hasSelfCollision()) return false;
    const int n = ps.particleCount();
    x0_ = s.y.head(3 * n);
    const Vector& x0 = x0_;
    x1_ = x0 + h * s.y.tail(3 * n);
    holds_.clear(n);
    bool held = false;
    // A hold's reaction: the linear system's residual at its row, A dv - b (an impulse), over h.
    bool measured = false;  // product_ = A dv for this round's dv
    const HoldReaction reaction = [&](int p) -> Vec3 {
      const int i = free_index_[p];
      if (!measured) multiply(ps, h, dv_free_, product_), measured = true;
      return (product_.segment<3>(3 * i) - rhs_.segment<3>(3 * i) - h * holds_.all()[holds_.of(p)].force) / h;
    };
    for (int round = 0; round < kContactRounds && holds_.hold(ps, x0, h, x1_, reaction) > 0; ++round) {
      held = true;
      const CgResult cg = solveHeld(ps, h, x0);
      measured = false;
      counts.linear_iterations += cg.iterations;
      counts.solver_failures = cg.converged ? 0 : 1;  // the last solve's
      for (int p = 0; p < n; ++p) {
        if (free_index_[p] < 0) continue;
        x1_.segment<3>(3 * p) = x0.segment<3>(3 * p) +
                                h * (v0_.segment<3>(3 * p) + dv_free_.segment<3>(3 * free_index_[p]));
      }
    }
    return held;
  }

  // A dv = b with each held particle's dv constrained to land it on its hold (its normal part,
  // or all of it when held whole): dv = S y + z, z the constrained part, S the filter onto what
  // is left free, and S A S y = S (b - A z) by conjugate gradient with the filtered block
  // Jacobi preconditioner (Baraff and Witkin 1998, sec. 5.3, "modified PCG").
  CgResult solveHeld(const ParticleSystem& ps, double h, const Vector& x0) {
    filters_.clear();
    constrained_.setZero(rhs_.size());
    for (const ContactHold& hold : holds_.all()) {
      const int p = hold.particle, i = free_index_[p];
      const Vec3 landing = (hold.point - x0.segment<3>(3 * p)) / h - v0_.segment<3>(3 * p);
      const Mat3 free_part = hold.whole ? Mat3(Mat3::Zero())
                                        : Mat3(Mat3::Identity() - hold.normal * hold.normal.transpose());
      filters_.push_back({i, free_part});
      constrained_.segment<3>(3 * i) = landing - free_part * landing;
    }
    const auto filter = [this](Vector& u) {
      for (const auto& [row, free_part] : filters_) u.segment<3>(3 * row) = free_part * u.segment<3>(3 * row);
    };
    multiply(ps, h, constrained_, filtered_rhs_);
    filtered_rhs_ = rhs_ - filtered_rhs_;
    for (const ContactHold& hold : holds_.all()) {  // kinetic friction's impulse
      filtered_rhs_.segment<3>(3 * free_index_[hold.particle]) += h * hold.force;
    }
    filter(filtered_rhs_);
    Vector y = dv_free_ - constrained_;
    filter(y);
    const SpringBlockMatrix& A = *matrix_;
    matrix_->factorDiagonal(true);
    // The tolerance against the whole system's right-hand side, as the first solve's: b - A z
    // cancels to almost nothing on a cloth at rest, and a residual relative to that would sit
    // below round-off (measured: CG then ran to its limit and kicked the resting cloth).
    const double filtered_norm = filtered_rhs_.norm();
    const double tolerance =
        filtered_norm > 0.0 ? tolerance_ * std::max(1.0, rhs_.norm() / filtered_norm) : tolerance_;
    const CgResult cg = conjugateGradient(
        [&](const Vector& in, Vector& out) { multiply(ps, h, in, out), filter(out); },
        [&](const Vector& r, Vector& z) {
          exact_ ? factor_.solve(r, z) : A.applyDiagonalInverse(r, z);
          filter(z);
        },
        filtered_rhs_, y, tolerance, max_iterations_);
    dv_free_ = y + constrained_;
    return cg;
  }

  // SSOR's relaxation factor, measured on the hanging cloth at h = 1/60 s: iterations fall from
  // w = 1 (symmetric Gauss-Seidel) to their fewest between 1.4 and 1.7 at 128 x 128, where 1.7
  // is already worse at 32 x 32 (docs/performance.md).
  static constexpr double kSsorOmega = 1.5;

  // Auto: the whole factor where hinges bend a system of at most kFactorParticles (their
  // stiffness grows as the fourth power of the cells, and block Jacobi's CG took 500 iterations a
  // step on the 32-cell cantilever, 1000 unsolved at 64); else SSOR where the springs' blocks
  // outweigh the masses, (h c + h^2 k)/m > 1 for the stiffest and most damped springs on a free
  // particle (integrator.h).
  CgPreconditioner preconditionerFor(double h) const {
    if (preconditioner_ != CgPreconditioner::Auto) return preconditioner_;
    if (hinged_ && std::ssize(free_particles_) <= kFactorParticles) return CgPreconditioner::Cholesky;
    return h * most_damping_over_m_ + h * h * stiffest_k_over_m_ > 1.0
               ? CgPreconditioner::Ssor
               : CgPreconditioner::BlockJacobi;
  }

  void numberFreeParticles(const ParticleSystem& ps) {
    const int n = ps.particleCount();
    free_index_.assign(n, -1);
    free_particles_.clear();
    for (int p = 0; p < n; ++p) {
      if (!ps.model().pinned[p]) {
        free_index_[p] = static_cast<int>(free_particles_.size());
        free_particles_.push_back(p);
      }
    }
    const Model& model = ps.model();
    hinged_ = !model.hinges.empty();
    stiffest_k_over_m_ = most_damping_over_m_ = 0.0;
    for (const Spring& sp : model.springs) {
      for (int end : {sp.i, sp.j}) {
        if (model.pinned[end]) continue;
        stiffest_k_over_m_ = std::max(stiffest_k_over_m_, sp.stiffness / model.mass[end]);
        most_damping_over_m_ = std::max(most_damping_over_m_, sp.damping / model.mass[end]);
      }
    }
    const int springs = static_cast<int>(model.springs.size());
    matrix_.emplace(ps.adjacency(), free_index_, springs);
    stiffness_term_.resize(springs);
    const int unknowns = 3 * static_cast<int>(free_particles_.size());
    rhs_.setZero(unknowns);
    dv_free_.setZero(unknowns);
  }

  // Each spring's block alpha I + s s^T (implicitSpringBlock, tested against the Mat3
  // Jacobians, written out here) and its right-hand-side term h^2 J (v_j - v_i), once a spring.
  void fillSprings(const ParticleSystem& ps, const Eigen::Ref<const Vector>& x,
                   const Eigen::Ref<const Vector>& v, double h) {
    const std::vector<Spring>& springs = ps.model().springs;
    std::vector<SpringBlockMatrix::Block>& blocks = matrix_->blocks();
    const int count = static_cast<int>(springs.size());
#pragma omp parallel for schedule(static) if (count >= kParallelParticles)
    for (int k = 0; k < count; ++k) {
      const Spring& sp = springs[k];
      const Vec3 d = x.segment<3>(3 * sp.j) - x.segment<3>(3 * sp.i);
      const double l = d.norm();
      const Vec3 u = d / l;
      const double clamp = std::max(0.0, 1.0 - sp.rest_length / l);
      const double alpha = h * h * sp.stiffness * clamp;
      const double beta = h * sp.damping + h * h * sp.stiffness * (1.0 - clamp);  // >= 0
      blocks[k] = {alpha, std::sqrt(beta) * u};
      const Vec3 w = v.segment<3>(3 * sp.j) - v.segment<3>(3 * sp.i);
      // h^2 J w, J = k (clamp I + (1 - clamp) u u^T).
      stiffness_term_[k] = alpha * w + (h * h * sp.stiffness * (1.0 - clamp) * u.dot(w)) * u;
    }
  }

  // Each free particle's diagonal block and right-hand side, gathered from its springs:
  //   D_p = (m + h drag) I + sum (alpha I + s s^T),
  //   b_p = h f0_p + sum +-h^2 J (v_q - v_p) + sum over pinned q of (alpha I + s s^T) dv_q.
  void fillRows(const ParticleSystem& ps, double h) {
    const Model& model = ps.model();
    const SpringAdjacency& a = ps.adjacency();
    const std::vector<SpringBlockMatrix::Block>& blocks = matrix_->blocks();
    std::vector<Mat3>& diagonal = matrix_->diagonal();
    const int free_count = static_cast<int>(free_particles_.size());
#pragma omp parallel for schedule(static) if (free_count >= kParallelParticles)
    for (int i = 0; i < free_count; ++i) {
      const int p = free_particles_[i];
      Mat3 block = (model.mass[p] + h * model.drag) * Mat3::Identity();
      Vec3 rhs = h * f_.segment<3>(3 * p);
      for (int e = a.offsets[p]; e < a.offsets[p + 1]; ++e) {
        const int k = a.spring[e];
        const SpringBlockMatrix::Block& b = blocks[k];
        block.diagonal().array() += b.alpha;
        block.noalias() += b.s * b.s.transpose();
        // The spring's w is v_j - v_i: seen from p it is v_q - v_p when p is the spring's i.
        if (model.springs[k].i == p) {
          rhs += stiffness_term_[k];
        } else {
          rhs -= stiffness_term_[k];
        }
        // A pinned neighbour's column times its known dv moves to the right: -(-block) dv_q.
        const int q = a.other[e];
        if (free_index_[q] < 0) {
          const Vec3 dq = dv_known_.segment<3>(3 * q);
          rhs += b.alpha * dq + b.s.dot(dq) * b.s;
        }
      }
      diagonal[i] = block;
      rhs_.segment<3>(3 * i) = rhs;
    }
  }

  // Hinges (hinge.h) have df/dx = -k w w^T (x) I, constant, so the step's matrix gains
  // h^2 k w_p w_q I between their particles: on the diagonal blocks here, off it in
  // multiplyHinges. The right-hand side gains h^2 J v0 = -h^2 w_p k b(v0) and, for a pinned
  // hinge particle q, -h^2 k w_p w_q dv_q.
  void addHinges(const ParticleSystem& ps, const Eigen::Ref<const Vector>& v, double h) {
    const Model& model = ps.model();
    std::vector<Mat3>& diagonal = matrix_->diagonal();
    for (const Hinge& hinge : model.hinges) {
      const Vec3 kb_v = hinge.stiffness * hingeVector(hinge, v.data());
      Vec3 kb_pinned = Vec3::Zero();
      for (int c = 0; c < 4; ++c) {
        const int q = hinge.particle[c];
        if (free_index_[q] < 0) kb_pinned += hinge.stiffness * hinge.weight[c] * dv_known_.segment<3>(3 * q);
      }
      for (int a = 0; a < 4; ++a) {
        const int i = free_index_[hinge.particle[a]];
        if (i < 0) continue;
        const double w = hinge.weight[a];
        diagonal[i].diagonal().array() += h * h * hinge.stiffness * w * w;
        rhs_.segment<3>(3 * i) -= (h * h * w) * (kb_v + kb_pinned);
      }
    }
  }

  // The step's matrix, springs' and hinges' blocks, factored whole (StepFactor).
  bool factorStep(const ParticleSystem& ps, double h) {
    triplets_.clear();
    matrix_->appendLowerTriangle(triplets_);
    for (const Hinge& hinge : ps.model().hinges) {  // h^2 k w_p w_q I below the diagonal
      for (int a = 0; a < 4; ++a) {
        for (int b = 0; b < 4; ++b) {
          const int i = free_index_[hinge.particle[a]], j = free_index_[hinge.particle[b]];
          if (i < 0 || j < 0 || j >= i) continue;
          const double value = h * h * hinge.stiffness * hinge.weight[a] * hinge.weight[b];
          for (int c = 0; c < 3; ++c) triplets_.emplace_back(3 * i + c, 3 * j + c, value);
        }
      }
    }
    return factor_.factor(3 * matrix_->rows(), triplets_);
  }

  // out += the hinges' off-diagonal blocks times `in` (free unknowns): per hinge
  // h^2 k w_p sum_{q free, q != p} w_q in_q on each free particle p.
  void multiplyHinges(const ParticleSystem& ps, double h, const Vector& in, Vector& out) const {
    for (const Hinge& hinge : ps.model().hinges) {
      Vec3 sum = Vec3::Zero();
      for (int c = 0; c < 4; ++c) {
        const int q = free_index_[hinge.particle[c]];
        if (q >= 0) sum += hinge.weight[c] * in.segment<3>(3 * q);
      }
      for (int a = 0; a < 4; ++a) {
        const int p = free_index_[hinge.particle[a]];
        if (p < 0) continue;
        const double w = hinge.weight[a];
        out.segment<3>(3 * p) += (h * h * hinge.stiffness * w) * (sum - w * in.segment<3>(3 * p));
      }
    }
  }

  std::vector<int> free_index_;      // (N) row block of each free particle, -1 if pinned
  std::vector<int> free_particles_;  // (F) particle of each row block
  std::optional<SpringBlockMatrix> matrix_;
  StepFactor factor_;  // the "cholesky" preconditioner's
  std::vector<StepFactor::Triplet> triplets_;
  bool exact_ = false;     // this step's solve used factor_
  bool factored_ = false;  // factor_ holds a positive definite factor of an earlier step's matrix
  bool refactor_ = false;  // the last solve with it took more than kStaleIterations
  // The matrix changes little from one step to the next (springs turning a few degrees), so an
  // earlier step's factor still brings CG to its tolerance in a few iterations, each far cheaper
  // than factoring again (docs/performance.md "A direct solve for backward Euler").
  static constexpr int kStaleIterations = 4;
  // Measured faster than block Jacobi on every hinge system up to the 64-ring Cusick disc's 12481
  // particles (26.6 s to 22.0 s for its first 0.25 s, 2.3x the memory); larger ones are not
  // measured, so they keep CG.
  static constexpr int kFactorParticles = 12500;
  bool hinged_ = false;  // the model bends by hinges
  std::vector<Vec3> stiffness_term_;  // (S) h^2 J (v_j - v_i) of each spring, this step
  Vector f_, dv_known_, rhs_, dv_free_;
  Vector v0_;  // (3N) the step's start velocities
  // Contact holds (integrators/contact_holds.h): the holds, x0 and x1 of the last solve, each held
  // row's filter onto its free part, and the held part of dv.
  ContactHolds holds_;
  Vector x0_, x1_, constrained_, filtered_rhs_, product_;
  std::vector<std::pair<int, Mat3>> filters_;
  double tolerance_;
  int max_iterations_;
  CgPreconditioner preconditioner_;
  double stiffest_k_over_m_ = 0.0;    // max k / m over springs and their free ends, 1/s^2
  double most_damping_over_m_ = 0.0;  // max c / m over the same, 1/s
};

}  // namespace

std::unique_ptr<Integrator> makeBackwardEuler(double cg_tolerance, int cg_max_iterations,
                                              CgPreconditioner preconditioner) {
  return std::make_unique<BackwardEuler>(cg_tolerance, cg_max_iterations, preconditioner);
}

}  // namespace mysim
