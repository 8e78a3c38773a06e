#include <algorithm>
#include <cmath>
#include <vector>

#include "solvers/graph_coloring.h"
#include "integrators/implicit_euler_step.h"
#include "mysim/integrator.h"
#include "mysim/particle_system.h"
#include "integrators/pass_control.h"

namespace mysim {
namespace {

// Extended position-based dynamics: Macklin, Mueller, Chentanez, "XPBD: position-based
// simulation of compliant constrained dynamics" (MIG 2016), with the step split into substeps
// as in Macklin et al., "Small steps in physics simulation" (SCA 2019). Each spring is a distance
// constraint C = |x_i - x_j| - rest with compliance alpha = 1/k; its damping c enters as XPBD's
// constraint damping beta = c. A substep of h_s = h / substeps:
//   v += h_s f_ext / m (gravity, drag, wind),  x_prev = x,  x += h_s v,  pins to x_pin(t + h_s),
//   lambda = 0 (warm_start: the last substep's, its push applied first), then `iterations`
//   Gauss-Seidel passes over the springs, colour by colour:
//     alpha~ = alpha / h_s^2,  gamma = alpha~ beta h_s = c / (k h_s),
//     dlambda = (-C - alpha~ lambda - gamma grad C . (x - x_prev)) / ((1 + gamma)(w_i + w_j) +
//     alpha~) x_i += w_i dlambda n,  x_j -= w_j dlambda n,  lambda += dlambda   (eq. 18 and 26)
//   v = (x - x_prev) / h_s, then the colliders' contacts (afterStep).
// What it converges to: with iterations enough that lambda solves each substep's system, a
// substep is an implicit (backward) Euler step of the compliant dynamics (Macklin 2016, sec. 4),
// so as substeps grow the trajectory converges to the ODE's, at first order in h_s. With one
// iteration per substep the residual of that solve also shrinks with h_s (Macklin 2019).
// Springs of one colour share no particle, so a colour runs in parallel with the same bits at
// any thread count.
class Xpbd final : public Integrator {
 public:
  Xpbd(int substeps, PassControl control, bool warm_start)
      : substeps_(substeps), control_(control), warm_start_(warm_start) {}

  StepCounts step(OdeSystem& system, State& s, double h) override {
    ParticleSystem& ps = *system.particles();
    const Model& model = ps.model();
    const int n = ps.particleCount();
    if (inverse_mass_.size() != n) prepare(model);
    const double hs = h / substeps_;
    if (hs != prepared_hs_) prepareSubstep(model, hs);
    StepCounts counts{.accepted = 1, .derivative_evaluations = substeps_};
    for (int sub = 0; sub < substeps_; ++sub) {
      predict(ps, s, hs);
      if (warm_start_) {
        pushCarried(ps.model(), s);
      } else {
        lambda_.setZero();
        hinge_lambda_.setZero();
      }
      counts.linear_iterations += solveSubstep(ps, s, counts);
      s.y.tail(3 * n) = (s.y.head(3 * n) - x_prev_) / hs;
      // Pins on their path with its velocity, then the contacts: after every substep.
      system.afterStep(s);
    }
    return counts;
  }

 private:
  void prepare(const Model& model) {
    colors_ = colorSprings(model.particleCount(), model.springs);
    lambda_ = Vector::Zero(static_cast<Eigen::Index>(model.springs.size()));
    hinge_lambda_ = Vector::Zero(3 * static_cast<Eigen::Index>(model.hinges.size()));
    residual_squares_ = Vector::Zero(lambda_.size());
    hinge_residual_squares_ = Vector::Zero(static_cast<Eigen::Index>(model.hinges.size()));
    inverse_mass_.resize(model.particleCount());
    for (int p = 0; p < model.particleCount(); ++p) {
      inverse_mass_[p] = model.pinned[p] ? 0.0 : 1.0 / model.mass[p];
    }
  }

  // The springs of each colour laid out one after another, with their constants for substeps of
  // hs (alpha~ and gamma, computed as the pass would): a pass then streams one array instead of
  // gathering spring records from all over the list (the same operations in the same order, so
  // the same bits).
  void prepareSubstep(const Model& model, double hs) {
    packed_.clear();
    packed_.reserve(model.springs.size());  // exactly: grown by doubling it held up to twice that
    for (const std::vector<int>& color : colors_) {
      for (int k : color) {
        const Spring& sp = model.springs[k];
        packed_.push_back({sp.i, sp.j, sp.rest_length, inverse_mass_[sp.i], inverse_mass_[sp.j],
                           1.0 / (sp.stiffness * hs * hs), sp.damping / (sp.stiffness * hs)});
      }
    }
    hinge_alpha_.resize(static_cast<Eigen::Index>(model.hinges.size()));
    for (int k = 0; k < static_cast<int>(model.hinges.size()); ++k) {
      hinge_alpha_[k] = 1.0 / (model.hinges[k].stiffness * hs * hs);
    }
    // lambda is an impulse times h_s (k C h_s^2 at rest): carried to substeps of another length
    // it keeps its force.
    if (prepared_hs_ > 0.0) {
      const double scale = (hs * hs) / (prepared_hs_ * prepared_hs_);
      lambda_ *= scale;
      hinge_lambda_ *= scale;
    }
    prepared_hs_ = hs;
    hs2_ = hs * hs;
  }

  // Passes over the constraints until pass_control.h stops them; the passes made. A pass's
  // residual is the norm of every constraint's force left unbalanced as the pass meets it,
  // k (C + alpha~ lambda + damping term), held against the forces acting: the largest of the
  // substep's load (gravity, wind) and the constraints' forces lambda / h_s^2.
  int solveSubstep(const ParticleSystem& ps, State& s, StepCounts& counts) {
    const bool measure = control_.adaptive();
    const double load = measure ? stepLoad(ps, s.t) : 0.0;
    int passes = 0;
    double residual = 0.0, forces = 0.0;
    do {
      projectSprings(s, measure);
      projectHinges(ps.model(), s, measure);
      ++passes;
      if (measure) {
        residual = std::sqrt(residual_squares_.sum() + hinge_residual_squares_.sum());
        const double carried = std::sqrt(lambda_.squaredNorm() + hinge_lambda_.squaredNorm()) / hs2_;
        forces = std::max(load, carried);
      }
    } while (!control_.stopAfter(passes, residual, forces));
    if (!control_.reachedTolerance(residual, forces)) counts.solver_failures = 1;
    return passes;
  }

  // Unconstrained motion under the other forces, the pins on their path at the substep's end.
  void predict(const ParticleSystem& ps, State& s, double hs) {
    const Model& model = ps.model();
    const int n = ps.particleCount();
    x_prev_ = s.y.head(3 * n);
    const double* v = s.y.data() + 3 * n;
    for (int p = 0; p < n; ++p) {
      if (model.pinned[p]) continue;
      s.y.segment<3>(3 * n + 3 * p) += hs * inverse_mass_[p] * ps.externalForce(p, s.t, v);
    }
    s.t += hs;
    for (int p = 0; p < n; ++p) {
      s.y.segment<3>(3 * p) =
          model.pinned[p] ? ps.pinPosition(p, s.t)
                          : Vec3(s.y.segment<3>(3 * p) + hs * s.y.segment<3>(3 * n + 3 * p));
    }
  }

  // One Gauss-Seidel pass, colour by colour (a colour in parallel: its springs share no end).
  void projectSprings(State& s, bool measure) {
    double* x = s.y.data();
    const double* xp = x_prev_.data();
    int begin = 0;
    for (const std::vector<int>& color : colors_) {
      const int count = static_cast<int>(color.size());
      const PackedSpring* springs = packed_.data() + begin;
      begin += count;
#pragma omp parallel for schedule(static) if (count >= kParallelSprings)
      for (int c = 0; c < count; ++c) {
        const PackedSpring& sp = springs[c];
        const double wi = sp.wi, wj = sp.wj;
        if (wi + wj == 0.0) continue;
        Eigen::Map<Vec3> xi(x + 3 * sp.i), xj(x + 3 * sp.j);
        const Vec3 d = xi - xj;
        const double length = d.norm();
        if (length == 0.0) {  // no direction to push along
          if (measure) residual_squares_[begin - count + c] = 0.0;
          continue;
        }
        const Vec3 unit = d / length;
        const Vec3 moved = (xi - Eigen::Map<const Vec3>(xp + 3 * sp.i)) -
                           (xj - Eigen::Map<const Vec3>(xp + 3 * sp.j));
        double& lambda = lambda_[begin - count + c];
        const double unsolved =
            -(length - sp.rest_length) - sp.alpha * lambda - sp.gamma * unit.dot(moved);
        // Each spring's own slot, summed after the pass in one order: the same bits at any
        // thread count.
        if (measure) residual_squares_[begin - count + c] = square(unsolved / (sp.alpha * hs2_));
        const double dlambda = unsolved / ((1.0 + sp.gamma) * (wi + wj) + sp.alpha);
        xi += wi * dlambda * unit;
        xj -= wj * dlambda * unit;
        lambda += dlambda;
      }
    }
  }

  // Warm start: the last substep's multipliers pushed again along each constraint's gradient at
  // the predicted positions, as the passes would push them (the same equations, started nearer:
  // near rest the multipliers that held the cloth hold it again, so the passes begin at the last
  // substep's residual instead of at the whole load's). Why: from 0 a substep rebuilds every
  // multiplier each time, three to seven passes to 1 % on the check cloth; warm, one. The solved
  // substep is XPBD's either way, up to the path its pushes take (docs/performance.md "XPBD at
  // rest": 4.8e-6 m apart after 1 s solved to 1e-6, test XpbdWarmStart).
  void pushCarried(const Model& model, State& s) {
    double* x = s.y.data();
    int begin = 0;
    for (const std::vector<int>& color : colors_) {
      const int count = static_cast<int>(color.size());
      const PackedSpring* springs = packed_.data() + begin;
      const double* lambda = lambda_.data() + begin;
      begin += count;
#pragma omp parallel for schedule(static) if (count >= kParallelSprings)
      for (int c = 0; c < count; ++c) {
        const PackedSpring& sp = springs[c];
        Eigen::Map<Vec3> xi(x + 3 * sp.i), xj(x + 3 * sp.j);
        const Vec3 d = xi - xj;
        const double length = d.norm();
        if (sp.wi + sp.wj == 0.0 || length == 0.0) continue;
        const Vec3 push = (lambda[c] / length) * d;
        xi += sp.wi * push;
        xj -= sp.wj * push;
      }
    }
    for (int k = 0; k < static_cast<int>(model.hinges.size()); ++k) {
      const Hinge& hinge = model.hinges[k];
      const Vec3 lambda = hinge_lambda_.segment<3>(3 * k);
      for (int a = 0; a < 4; ++a) {
        const int p = hinge.particle[a];
        Eigen::Map<Vec3>(x + 3 * p) += (hinge.weight[a] * inverse_mass_[p]) * lambda;
      }
    }
  }

  // Hinges (hinge.h) as vector constraints C = b = sum w_a x_a with compliance 1/k (energy
  // 1/2 k |C|^2), grad_a C = w_a I, so XPBD's update is, with alpha~ = 1 / (k h_s^2),
  //   dlambda = (-C - alpha~ lambda) / (sum_a w_a^2 / m_a + alpha~),  x_a += w_a dlambda / m_a.
  // One after another in list order after the springs (a hinge's four particles are shared with
  // its neighbours' hinges, and there are few enough that this pass is not the step's cost).
  void projectHinges(const Model& model, State& s, bool measure) {
    double* x = s.y.data();
    for (int k = 0; k < static_cast<int>(model.hinges.size()); ++k) {
      const Hinge& hinge = model.hinges[k];
      double denominator = hinge_alpha_[k];
      for (int a = 0; a < 4; ++a) {
        denominator += hinge.weight[a] * hinge.weight[a] * inverse_mass_[hinge.particle[a]];
      }
      if (denominator == hinge_alpha_[k]) continue;  // all four pinned
      Eigen::Map<Vec3> lambda(hinge_lambda_.data() + 3 * k);
      const Vec3 unsolved = -hingeVector(hinge, x) - hinge_alpha_[k] * lambda;
      if (measure) hinge_residual_squares_[k] = (unsolved / (hinge_alpha_[k] * hs2_)).squaredNorm();
      const Vec3 dlambda = unsolved / denominator;
      for (int a = 0; a < 4; ++a) {
        const int p = hinge.particle[a];
        Eigen::Map<Vec3>(x + 3 * p) += (hinge.weight[a] * inverse_mass_[p]) * dlambda;
      }
      lambda += dlambda;
    }
  }

  // Below this many springs in a colour, threads cost more than they save.
  static constexpr int kParallelSprings = 2048;
  struct PackedSpring {
    int i, j;
    double rest_length, wi, wj;  // wi, wj: the ends' inverse masses (0 pinned)
    double alpha, gamma;         // alpha~ = 1 / (k h_s^2), gamma = c / (k h_s)
  };
  int substeps_;
  PassControl control_;
  bool warm_start_;
  double prepared_hs_ = 0.0;
  double hs2_ = 0.0;  // prepared_hs_^2: k (C + alpha~ lambda) = (C + alpha~ lambda) / (alpha~ h_s^2)
  static double square(double v) { return v * v; }
  std::vector<PackedSpring> packed_;  // (S) the springs in colour order, for substeps of prepared_hs_
  std::vector<std::vector<int>> colors_;
  Vector lambda_;        // (S) accumulated multiplier of each spring (colour order), this substep
  Vector hinge_lambda_;  // (3H) accumulated multiplier of each hinge, this substep (warm_start:
                         // from the last substep's)
  Vector hinge_alpha_;   // (H) 1 / (k h_s^2)
  Vector residual_squares_, hinge_residual_squares_;  // (S), (H) this pass's, when measured
  Vector inverse_mass_;  // (N) 0 for pinned particles
  Vector x_prev_;        // (3N) positions at the substep's start
};

}  // namespace

std::unique_ptr<Integrator> makeXpbd(const IntegratorSettings& s) {
  // Warm starts with a tolerance only: the fixed-count form (tolerance 0) is published XPBD and
  // the protocol's rule, every substep from lambda = 0.
  const bool warm_start = s.value("warm_start") != 0.0 && s.value("tolerance") > 0.0;
  return std::make_unique<Xpbd>(static_cast<int>(s.value("substeps")), PassControl::from(s),
                                warm_start);
}

}  // namespace mysim
