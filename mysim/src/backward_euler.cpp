#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <vector>

#include "mysim/integrator.h"
#include "mysim/particle_system.h"

namespace mysim {
namespace {

// Backward Euler as in Baraff and Witkin, "Large steps in cloth simulation" (SIGGRAPH 1998),
// eq. 16: one Newton step of v1 = v0 + h M^-1 f(x0 + h v1, v1), linearised at (x0, v0):
//   (M - h df/dv - h^2 df/dx) dv = h (f0 + h df/dx v0),   v1 = v0 + dv,   x1 = x0 + h v1.
// df/dx uses each spring's elastic Jacobian with the compressive term clamped (SPD, see
// spring.h); df/dv holds spring damping and drag. Solved by Jacobi-preconditioned conjugate
// gradient over the free particles only: pinned velocities are known, so their columns move to
// the right-hand side. First order; unconditionally stable on an oscillator, where the amplitude
// shrinks by 1/sqrt(1 + (h w)^2) a step.
class BackwardEuler final : public Integrator {
 public:
  BackwardEuler(double tolerance, int max_iterations) {
    cg_.setTolerance(tolerance);
    cg_.setMaxIterations(max_iterations);
  }
  bool needsParticles() const override { return true; }

  StepCounts step(OdeSystem& system, State& s, double h) override {
    ParticleSystem& ps = *system.particles();
    const Model& model = ps.model();
    const int n = ps.particleCount(), n3 = 3 * n;
    if (free_index_.empty()) numberFreeParticles(model);

    x_ = s.y.head(n3);
    v_ = s.y.tail(n3);
    f_.resize(n3);
    ps.force(s.t, x_, v_, f_);

    // Known velocity change of pinned particles.
    dv_known_ = Vector::Zero(n3);
    const Vec3 pin_velocity_end = ps.pinVelocity(s.t + h);
    for (int p = 0; p < n; ++p) {
      if (model.pinned[p]) at3(dv_known_, p) = pin_velocity_end - at3(v_, p);
    }

    // Right-hand side h f0 over free particles (the h^2 df/dx v0 term is added per spring).
    rhs_.resize(3 * free_count_);
    for (int p = 0; p < n; ++p) {
      if (free_index_[p] >= 0) rhs_.segment<3>(3 * free_index_[p]) = h * at3(f_, p);
    }
    triplets_.clear();
    for (int p = 0; p < n; ++p) {
      const double diagonal = model.mass[p] + h * model.drag;
      addBlock(p, p, diagonal * Mat3::Identity());
    }
    for (const Spring& sp : model.springs) {
      const Vec3 xi = at3(x_, sp.i), xj = at3(x_, sp.j);
      const Mat3 J = springElasticJacobianDefinite(xi, xj, sp.rest_length, sp.stiffness);
      const Mat3 C = springVelocityJacobian(xi, xj, sp.damping);
      // df/dx v0: particle i gets J (vj - vi), j the opposite.
      const Vec3 Jv = J * (at3(v_, sp.j) - at3(v_, sp.i));
      addToRhs(sp.i, h * h * Jv);
      addToRhs(sp.j, -h * h * Jv);
      const Mat3 block = h * C + h * h * J;
      addBlock(sp.i, sp.i, block);
      addBlock(sp.j, sp.j, block);
      addBlock(sp.i, sp.j, -block);
      addBlock(sp.j, sp.i, -block);
    }
    matrix_.resize(3 * free_count_, 3 * free_count_);
    matrix_.setFromTriplets(triplets_.begin(), triplets_.end());

    cg_.compute(matrix_);
    dv_free_ = cg_.solve(rhs_);
    StepCounts counts{.accepted = 1, .derivative_evaluations = 1};
    counts.linear_iterations = cg_.iterations();
    if (cg_.info() != Eigen::Success) counts.solver_failures = 1;

    for (int p = 0; p < n; ++p) {
      const Vec3 dv = free_index_[p] >= 0 ? Vec3(dv_free_.segment<3>(3 * free_index_[p]))
                                          : Vec3(at3(dv_known_, p));
      at3(v_, p) += dv;
    }
    x_ += h * v_;
    s.y.head(n3) = x_;
    s.y.tail(n3) = v_;
    s.t += h;
    system.afterStep(s);
    return counts;
  }

 private:
  void numberFreeParticles(const Model& model) {
    free_index_.assign(model.particleCount(), -1);
    free_count_ = 0;
    for (int p = 0; p < model.particleCount(); ++p) {
      if (!model.pinned[p]) free_index_[p] = free_count_++;
    }
  }

  void addToRhs(int p, const Vec3& value) {
    if (free_index_[p] >= 0) rhs_.segment<3>(3 * free_index_[p]) += value;
  }

  // Adds a 3x3 block of the system matrix at particles (row, col); a block in a pinned column
  // multiplies a known dv and moves to the right-hand side; a pinned row has no equation.
  void addBlock(int row, int col, const Mat3& block) {
    const int r = free_index_[row], c = free_index_[col];
    if (r < 0) return;
    if (c < 0) {
      rhs_.segment<3>(3 * r) -= block * at3(dv_known_, col);
      return;
    }
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        if (block(a, b) != 0.0) triplets_.emplace_back(3 * r + a, 3 * c + b, block(a, b));
      }
    }
  }

  std::vector<int> free_index_;  // (N) row of each free particle in the solve, -1 if pinned
  int free_count_ = 0;
  Vector x_, v_, f_, dv_known_, rhs_, dv_free_;
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SparseMatrix<double> matrix_;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg_;
};

}  // namespace

std::unique_ptr<Integrator> makeBackwardEuler(double cg_tolerance, int cg_max_iterations) {
  return std::make_unique<BackwardEuler>(cg_tolerance, cg_max_iterations);
}

}  // namespace mysim
