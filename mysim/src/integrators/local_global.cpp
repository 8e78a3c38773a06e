#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "integrators/implicit_euler_step.h"
#include "mysim/integrator.h"
#include "integrators/local_global_matrix.h"
#include "mysim/particle_system.h"
#include "solvers/sparse_ldlt3.h"
#include "integrators/accelerated_passes.h"
#include "integrators/held_global_matrix.h"
#include "forces/spring_forces.h"
#include "core/parallel_threshold.h"

namespace mysim {
namespace {

// Liu, O'Brien, Liu, Kavan and Xiao, "Fast simulation of mass-spring systems" (SIGGRAPH Asia
// 2013): the implicit-Euler step (implicit_euler_step.h) solved by block coordinate descent on
//   g(x, d) = 1/(2 h^2) |x - y~|^2_M~ + sum_s k_s/2 |x_i - x_j - d_s|^2,   |d_s| = rest_s,
// alternating the local step (d_s = rest_s u_s, u_s the spring's direction at the current x;
// g's minimum over d for fixed x) and the global step (g's minimum over x for fixed d, one linear
// system with the constant matrix M~/h^2 + L, the same for x, y and z). Each pass lowers g, and
// g's minimum over d is Liu's energy: the iterate converges (linearly) to the implicit-Euler
// minimiser. x starts at y~, the inertial prediction.
//
// Spring damping (derived here; Liu adds none): the damping force at v1 = (x - x0)/h on end i,
//   -(c/h) u u^T (dx_i - dx_j) = -(c/h)(dx_i - dx_j) + (c/h)(I - u u^T)(dx_i - dx_j),
// keeps its isotropic part in the matrix (weight c/h beside k, so the matrix stays constant) and
// moves the part across the spring, with u and dx from the current iterate, to the right-hand
// side. At a fixed point the step's equation holds exactly; the lagged part is bounded above by
// the matrix part it mirrors (0 <= I - u u^T <= I), so the passes still contract.
// Drag folds into M~ and y~ exactly (implicit_euler_step.h). Pins are eliminated: only free
// particles are unknowns, a pinned neighbour's term (k + c/h) x_pin(t + h) moves to the
// right-hand side. The matrix is factored once per scene and step size (SparseLdlt3); its time is
// reported apart from stepping (StepCounts::setup_seconds). Colliders: particles the solve puts
// inside one are held on its surface and the step solved again (integrators/contact_holds.h), the
// matrix with the holds factored per new set of them (held_global_matrix.h, in the step's
// time); then the contacts after the step, as every integrator (afterStep). Acceleration:
// Chebyshev over whole passes (Wang 2015, integrators/chebyshev.h) after the floor's plain
// passes, with rho `acceleration_rho` (0: off).
class LocalGlobal final : public Integrator {
 public:
  LocalGlobal(PassControl control, double rho) : control_(control), chebyshev_(rho) {}

  StepCounts step(OdeSystem& system, State& s, double h) override {
    ParticleSystem& ps = *system.particles();
    StepCounts counts{.accepted = 1};
    if (h != factored_h_) {
      counts.setup_seconds = factorFor(ps, h);
      if (!factored_) {
        counts.solver_failures = 1;
        counts.gave_up = true;
        return counts;
      }
    }
    prepareImplicitEulerStep(ps, s, h, step_);
    x_ = step_.target;
    PassesRun run = solve(ps);
    for (int round = 0; round < kContactRounds && holdContacts(ps, step_, x_, residual_); ++round) {
      if (!held_matrix_.factor(lower_, free_index_, step_.holds)) {
        run.converged = false;
        break;
      }
      const PassesRun again = solve(ps);
      run = {run.passes + again.passes, again.converged};
    }
    if (!run.converged) counts.solver_failures = 1;
    counts.derivative_evaluations = run.passes;
    counts.linear_iterations = run.passes;
    finishImplicitEulerStep(system, step_, x_, s);
    return counts;
  }

 private:
  PassesRun solve(const ParticleSystem& ps) {
    return runAcceleratedPasses(control_, chebyshev_, ps, step_, x_, residual_, [&] {
      localStep(ps.model());
      globalStep(ps);
    });
  }

  // Numbers the free particles and factors the constant matrix (local_global_matrix.h); seconds.
  double factorFor(const ParticleSystem& ps, double h) {
    const auto start = std::chrono::steady_clock::now();
    LocalGlobalMatrix matrix = localGlobalMatrix(ps.model(), h);
    free_index_ = std::move(matrix.free_index);
    free_particles_ = std::move(matrix.free_particles);
    weight_ = std::move(matrix.weight);
    std::string error;
    factored_ = factor_.factor(matrix.lower, error);
    lower_ = std::move(matrix.lower);
    held_matrix_.forget();
    factored_h_ = h;
    scale_.resize(weight_.size());
    rhs_.resize(3 * static_cast<Eigen::Index>(free_particles_.size()));
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // The local step: each spring's rest direction at the current iterate, kept as the scalar
  // k rest / l = k - scale with the force loop's vectorised scale = k (1 - rest / l), so the
  // right-hand side's spring term k rest u reads (k - scale)(x_i - x_j).
  void localStep(const Model& model) {
    const int count = static_cast<int>(model.springs.size());
    constexpr int kBlock = 512;  // springs a thread takes at a time (as the force loop)
    const int blocks = (count + kBlock - 1) / kBlock;
#pragma omp parallel for schedule(static) if (count >= 4 * kParallelParticles)
    for (int b = 0; b < blocks; ++b) {
      springScales(model.springs, false, x_.data(), nullptr, scale_.data(), b * kBlock,
                   std::min(count, (b + 1) * kBlock));
    }
  }

  // The global step: each free particle's right-hand side gathered from its springs (seen from
  // either end the terms read the same, d = x_p - x_q):
  //   b_p = m~/h^2 y~_p + sum (k rest / l) d + (c/h) [ d0 + (I - u u^T)(d - d0) ] + w x_q (q pinned),
  // then the two triangular sweeps.
  void globalStep(const ParticleSystem& ps) {
    const Model& model = ps.model();
    const SpringAdjacency& a = ps.adjacency();
    const int unknowns = static_cast<int>(free_particles_.size());
    const double* x = x_.data();
    const double* x0 = step_.x0.data();
    const double inverse_h = 1.0 / step_.h;
#pragma omp parallel for schedule(static) if (unknowns >= kParallelParticles)
    for (int f = 0; f < unknowns; ++f) {
      const int p = free_particles_[f];
      Vec3 b = step_.mass_over_h2[p] * step_.target.segment<3>(3 * p);
      for (int e = a.offsets[p]; e < a.offsets[p + 1]; ++e) {
        const int k = a.spring[e], q = a.other[e];
        const Spring& sp = model.springs[k];
        const Vec3 d = Eigen::Map<const Vec3>(x + 3 * p) - Eigen::Map<const Vec3>(x + 3 * q);
        b += (sp.stiffness - scale_[k]) * d;
        if (sp.damping != 0.0) {
          const double l = d.norm();
          const Vec3 u = l > 0.0 ? Vec3(d / l) : Vec3::Zero();
          const Vec3 d0 = Eigen::Map<const Vec3>(x0 + 3 * p) - Eigen::Map<const Vec3>(x0 + 3 * q);
          const Vec3 moved = d - d0;
          b += (sp.damping * inverse_h) * (d0 + moved - u.dot(moved) * u);
        }
        if (model.pinned[q]) b += weight_[k] * step_.target.segment<3>(3 * q);
      }
      const HingeAdjacency& ha = ps.hingeAdjacency();
      for (int e = ha.offsets[p]; e < ha.offsets[p + 1]; ++e) {
        const Hinge& hinge = model.hinges[ha.hinge[e]];
        const double wp = hinge.weight[ha.slot[e]];
        for (int c = 0; c < 4; ++c) {
          const int q = hinge.particle[c];
          if (model.pinned[q]) {
            b -= (hinge.stiffness * wp * hinge.weight[c]) * step_.target.segment<3>(3 * q);
          }
        }
      }
      rhs_.segment<3>(3 * f) = b;
    }
    if (step_.holds.empty()) {
      factor_.solve(rhs_);
    } else {
      for (const ContactHold& hold : step_.holds.all()) {
        rhs_.segment<3>(3 * free_index_[hold.particle]) += hold.force;  // kinetic friction
      }
      held_matrix_.addHoldTerms(rhs_);
      held_matrix_.solve(rhs_);
    }
    for (int f = 0; f < unknowns; ++f) {
      x_.segment<3>(3 * free_particles_[f]) = rhs_.segment<3>(3 * f);
    }
  }

  PassControl control_;
  ChebyshevAcceleration chebyshev_;
  double factored_h_ = 0.0;
  bool factored_ = false;
  SparseLdlt3 factor_;
  Eigen::SparseMatrix<double> lower_;  // the constant matrix factor_ holds, for the held one
  HeldGlobalMatrix held_matrix_;       // this step's holds: its matrix with them
  std::vector<int> free_index_;      // (N) unknown of each free particle, -1 if pinned
  std::vector<int> free_particles_;  // (F) particle of each unknown
  Vector weight_;                    // (S) k + c/h: each spring's matrix weight
  Vector scale_;                     // (S) k (1 - rest / l) at the current iterate
  Vector rhs_;                       // (3F) the global step's right-hand side, then its solution
  Vector x_;                         // (3N) the iterate
  Vector residual_;                  // (3N) r(x) of implicit_euler_step.h, when measured
  ImplicitEulerStep step_;
};

}  // namespace

std::unique_ptr<Integrator> makeLocalGlobal(const IntegratorSettings& s) {
  return std::make_unique<LocalGlobal>(PassControl::from(s), s.value("acceleration_rho"));
}

}  // namespace mysim
