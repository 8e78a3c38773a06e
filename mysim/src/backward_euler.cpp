#include <Eigen/LU>
#include <algorithm>
#include <vector>

#include "mysim/conjugate_gradient.h"
#include "mysim/integrator.h"
#include "mysim/particle_system.h"

namespace mysim {
namespace {

// Below this many particles one thread is faster (see particle_system.cpp).
constexpr int kParallelParticles = 512;

// Backward Euler as in Baraff and Witkin, "Large steps in cloth simulation" (SIGGRAPH 1998),
// eq. 16: one Newton step of v1 = v0 + h M^-1 f(x0 + h v1, v1), linearised at (x0, v0):
//   (M - h df/dv - h^2 df/dx) dv = h (f0 + h df/dx v0),   v1 = v0 + dv,   x1 = x0 + h v1.
// df/dx uses each spring's elastic Jacobian with the compressive term clamped (SPD, see
// spring.h); df/dv holds spring damping and drag. Solved by conjugate gradient preconditioned
// with the inverses of the 3x3 diagonal blocks (block Jacobi) over the free particles only:
// pinned velocities are known, so their columns move to the right-hand side. First order; unconditionally stable on an oscillator, where the amplitude
// shrinks by 1/sqrt(1 + (h w)^2) a step.
//
// The matrix is never assembled. Each spring's block is alpha I + beta u u^T
// (implicitSpringBlock), so a step stores per incidence (alpha, beta, u) and per free particle its
// 3x3 diagonal block; the product gathers, per particle,
//   (A x)_p = D_p x_p - sum over free neighbours q of (alpha x_q + beta u (u . x_q)),
// in parallel with no write conflicts. That is 5 numbers an incidence instead of a CSR matrix's
// 9 values and 9 column indices, and nothing to scatter or zero.
class BackwardEuler final : public Integrator {
 public:
  BackwardEuler(double tolerance, int max_iterations, bool block_preconditioner)
      : tolerance_(tolerance),
        max_iterations_(max_iterations),
        block_preconditioner_(block_preconditioner) {}

  StepCounts step(OdeSystem& system, State& s, double h) override {
    ParticleSystem& ps = *system.particles();
    const Model& model = ps.model();
    const int n = ps.particleCount(), n3 = 3 * n;
    if (free_index_.empty()) numberFreeParticles(ps);

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
    fill(ps, x, v, h);

    const CgResult cg = conjugateGradient(
        [this, &ps](const Vector& in, Vector& out) { multiply(ps, in, out); },
        [this](const Vector& r, Vector& z) { precondition(r, z); }, rhs_, dv_free_, tolerance_,
        max_iterations_);
    StepCounts counts{.accepted = 1, .derivative_evaluations = 1};
    counts.linear_iterations = cg.iterations;
    if (!cg.converged) counts.solver_failures = 1;

    for (int p = 0; p < n; ++p) {
      const Vec3 dv = free_index_[p] >= 0 ? Vec3(dv_free_.segment<3>(3 * free_index_[p]))
                                          : Vec3(dv_known_.segment<3>(3 * p));
      s.y.segment<3>(n3 + 3 * p) += dv;
    }
    s.y.head(n3) += h * s.y.tail(n3);
    s.t += h;
    system.afterStep(s);
    return counts;
  }

 private:
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
    const int unknowns = 3 * static_cast<int>(free_particles_.size());
    blocks_.resize(ps.adjacency().other.size());
    diagonal_.resize(free_particles_.size());
    inverse_block_.resize(free_particles_.size());
    rhs_.setZero(unknowns);
    dv_free_.setZero(unknowns);
  }

  // Per-incidence blocks, diagonal blocks and the right-hand side for this step.
  void fill(const ParticleSystem& ps, const Eigen::Ref<const Vector>& x,
            const Eigen::Ref<const Vector>& v, double h) {
    const Model& model = ps.model();
    const SpringAdjacency& a = ps.adjacency();
    const int free_count = static_cast<int>(free_particles_.size());
#pragma omp parallel for schedule(static) if (free_count >= kParallelParticles)
    for (int i = 0; i < free_count; ++i) {
      const int p = free_particles_[i];
      const Vec3 xp = x.segment<3>(3 * p), vp = v.segment<3>(3 * p);
      Mat3 diagonal = (model.mass[p] + h * model.drag) * Mat3::Identity();
      // h f0, plus h^2 (df/dx v0)_p = h^2 sum J (v_q - v_p) over p's springs.
      Vec3 rhs = h * f_.segment<3>(3 * p);
      for (int e = a.offsets[p]; e < a.offsets[p + 1]; ++e) {
        const int q = a.other[e];
        const Spring& sp = model.springs[a.spring[e]];
        // implicitSpringBlock() (tested against the Mat3 Jacobians), inlined here.
        const Vec3 d = x.segment<3>(3 * q) - xp;
        const double inv_l = 1.0 / d.norm();
        const Vec3 u = d * inv_l;
        const double clamp = std::max(0.0, 1.0 - sp.rest_length * inv_l);
        ImplicitSpringBlock& b = blocks_[e];
        b.alpha = h * h * sp.stiffness * clamp;
        b.beta = h * sp.damping + h * h * sp.stiffness * (1.0 - clamp);
        b.ja = sp.stiffness * clamp;
        b.jb = sp.stiffness * (1.0 - clamp);
        b.u = u;
        const Vec3 w = v.segment<3>(3 * q) - vp;
        rhs += (h * h) * (b.ja * w + (b.jb * u.dot(w)) * u);
        diagonal.diagonal().array() += b.alpha;
        diagonal.noalias() += b.beta * (u * u.transpose());
        // A pinned neighbour's column times its known dv moves to the right: -(-block) dv_q.
        if (free_index_[q] < 0) {
          const Vec3 dq = dv_known_.segment<3>(3 * q);
          rhs += b.alpha * dq + (b.beta * u.dot(dq)) * u;
        }
      }
      diagonal_[i] = diagonal;
      rhs_.segment<3>(3 * i) = rhs;
      // Block Jacobi: each particle's 3x3 block inverted whole. It keeps the coupling between a
      // particle's own x, y and z through its springs' directions (beta u u^T), which the scalar
      // diagonal drops; the block is SPD (mass plus PSD spring terms), so it inverts.
      inverse_block_[i] = block_preconditioner_
                              ? Mat3(diagonal.inverse())
                              : Mat3(diagonal.diagonal().cwiseInverse().asDiagonal());
    }
  }

  // z = (block diagonal)^-1 r.
  void precondition(const Vector& r, Vector& z) const {
    const int free_count = static_cast<int>(free_particles_.size());
    z.resize(r.size());
#pragma omp parallel for schedule(static) if (free_count >= kParallelParticles)
    for (int i = 0; i < free_count; ++i) {
      z.segment<3>(3 * i).noalias() = inverse_block_[i] * r.segment<3>(3 * i);
    }
  }

  // out = A in, over the free particles.
  void multiply(const ParticleSystem& ps, const Vector& in, Vector& out) const {
    const SpringAdjacency& a = ps.adjacency();
    const int free_count = static_cast<int>(free_particles_.size());
    out.resize(in.size());
#pragma omp parallel for schedule(static) if (free_count >= kParallelParticles)
    for (int i = 0; i < free_count; ++i) {
      const int p = free_particles_[i];
      Vec3 sum = diagonal_[i] * in.segment<3>(3 * i);
      for (int e = a.offsets[p]; e < a.offsets[p + 1]; ++e) {
        const int j = free_index_[a.other[e]];
        if (j < 0) continue;
        const ImplicitSpringBlock& b = blocks_[e];
        const Vec3 xq = in.segment<3>(3 * j);
        sum -= b.alpha * xq + (b.beta * b.u.dot(xq)) * b.u;
      }
      out.segment<3>(3 * i) = sum;
    }
  }

  std::vector<int> free_index_;              // (N) row block of each free particle, -1 if pinned
  std::vector<int> free_particles_;          // (F) particle of each row block
  std::vector<ImplicitSpringBlock> blocks_;  // (2S) this step's block of each incidence
  std::vector<Mat3> diagonal_;               // (F) diagonal blocks
  std::vector<Mat3> inverse_block_;          // (F) their inverses: the preconditioner
  Vector f_, dv_known_, rhs_, dv_free_;
  double tolerance_;
  int max_iterations_;
  bool block_preconditioner_;
};

}  // namespace

std::unique_ptr<Integrator> makeBackwardEuler(double cg_tolerance, int cg_max_iterations,
                                              bool block_preconditioner) {
  return std::make_unique<BackwardEuler>(cg_tolerance, cg_max_iterations, block_preconditioner);
}

}  // namespace mysim
