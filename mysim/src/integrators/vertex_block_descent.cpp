#include <algorithm>
#include <cmath>
#include <vector>

#include "solvers/graph_coloring.h"
#include "integrators/implicit_euler_step.h"
#include "mysim/integrator.h"
#include "mysim/particle_system.h"
#include "integrators/accelerated_passes.h"

namespace mysim {
namespace {

// Vertex block descent: Chen, Macklin, Yang, Kim and Mueller, "Vertex Block Descent" (SIGGRAPH
// 2024). The implicit-Euler step (implicit_euler_step.h) solved by Gauss-Seidel over vertices:
// each free vertex in turn takes one 3 x 3 Newton step on its own part of the step's problem,
// the others held (Algorithm 1):
//   f_i = -m~/h^2 (x_i - y~_i) - sum_s [ k (l - rest) u + (c/h) u u^T (dx_i - dx_j) ]   (u from j to i)
//   H_i =  m~/h^2 I + sum_s [ k (u u^T + max(0, 1 - rest/l)(I - u u^T)) + (c/h) u u^T ]
//   x_i += H_i^-1 f_i.
// The spring Hessian's compressive term is clamped so H_i is positive definite (the paper skips a
// vertex whose H_i is near singular; with the clamp none is). A fixed point has f_i = 0 for every
// vertex: the step's equations, so VBD converges to the same minimiser as backward Euler iterated
// to convergence and local/global. Vertices of one colour (graph_coloring.h) share no spring, so a
// colour runs in parallel with the same bits at any thread count.
// Initial guess: the paper's adaptive one (sec. 3.7), x0 + h v0 + h^2 a~ with a~ the external
// acceleration scaled by the part of it the vertex had last step, clamp(a_prev . a^ / |a|, 0, 1)
// (a_prev = (v0 - v_prev) / h; the first step takes all of it). Acceleration: Chebyshev
// (sec. 3.8, after Wang 2015) with spectral radius estimate rho (default 0.95, measured in the
// catalogue); rho = 0 turns it off.
class VertexBlockDescent final : public Integrator {
  struct Color {
    int begin, end;  // its vertices in vertices_
  };
  struct Vertex {
    int particle, first;  // its incidences: [first, next vertex's first)
    int first_hinge;      // its hinges: [first_hinge, next vertex's first_hinge)
  };
  struct HingeIncidence {
    int hinge;
    double weight;  // this vertex's weight in it
  };
  struct Incidence {
    int other;
    double rest_length, stiffness, damping;
  };

 public:
  VertexBlockDescent(PassControl control, double rho) : control_(control), chebyshev_(rho) {}

  StepCounts step(OdeSystem& system, State& s, double h) override {
    ParticleSystem& ps = *system.particles();
    const int n = ps.particleCount();
    if (vertices_.empty() && n > 0) pack(ps);
    hinges_ = &ps.model().hinges;
    prepareImplicitEulerStep(ps, s, h, step_);
    initialGuess(ps, s, h);
    PassesRun run = solve(ps);
    for (int round = 0; round < kContactRounds && holdContacts(ps, step_, x_, residual_); ++round) {
      const PassesRun again = solve(ps);
      run = {run.passes + again.passes, again.converged};
    }
    previous_velocity_ = s.y.tail(3 * n);
    finishImplicitEulerStep(system, step_, x_, s);
    return {.accepted = 1,
            .derivative_evaluations = run.passes,
            .linear_iterations = run.passes,
            .solver_failures = run.converged ? 0 : 1};
  }

 private:
  PassesRun solve(const ParticleSystem& ps) {
    return runAcceleratedPasses(control_, chebyshev_, ps, step_, x_, residual_, [&] {
      for (const Color& color : colors_) relaxColor(color);
    });
  }

  void initialGuess(const ParticleSystem& ps, const State& s, double h) {
    const Model& model = ps.model();
    const int n = ps.particleCount();
    const Vector zero_velocity = Vector::Zero(3 * n);
    const bool has_previous = previous_velocity_.size() == 3 * n;
    x_ = step_.target;  // pinned: on their path
    for (int p = 0; p < n; ++p) {
      if (model.pinned[p]) continue;
      const Vec3 a = ps.externalForce(p, step_.t_end, zero_velocity.data()) / model.mass[p];
      double share = 1.0;
      if (has_previous && a.norm() > 0.0) {
        const Vec3 a_prev = (s.y.segment<3>(3 * n + 3 * p) - previous_velocity_.segment<3>(3 * p)) / h;
        share = std::clamp(a_prev.dot(a) / a.squaredNorm(), 0.0, 1.0);
      }
      x_.segment<3>(3 * p) =
          s.y.segment<3>(3 * p) + h * s.y.segment<3>(3 * n + 3 * p) + h * h * share * a;
    }
  }

  // The free vertices in colour order, each with its springs' far ends and parameters laid out
  // one after another, so a pass streams one array instead of gathering spring records.
  void pack(const ParticleSystem& ps) {
    const Model& model = ps.model();
    const SpringAdjacency& a = ps.adjacency();
    const HingeAdjacency& ha = ps.hingeAdjacency();
    // Exactly their sizes (at most: pinned vertices are left out): grown by doubling, the
    // incidences held up to twice their 32 B a spring end, most of VBD's memory.
    vertices_.reserve(model.particleCount() + 1);
    incidences_.reserve(a.other.size());
    hinge_incidences_.reserve(ha.hinge.size());
    for (const std::vector<int>& color : colorParticles(couplings(ps))) {
      Color packed{static_cast<int>(vertices_.size()), 0};
      for (int p : color) {
        if (model.pinned[p]) continue;
        vertices_.push_back({p, static_cast<int>(incidences_.size()),
                             static_cast<int>(hinge_incidences_.size())});
        for (int e = a.offsets[p]; e < a.offsets[p + 1]; ++e) {
          const Spring& sp = model.springs[a.spring[e]];
          incidences_.push_back({a.other[e], sp.rest_length, sp.stiffness, sp.damping});
        }
        for (int e = ha.offsets[p]; e < ha.offsets[p + 1]; ++e) {
          hinge_incidences_.push_back({ha.hinge[e], model.hinges[ha.hinge[e]].weight[ha.slot[e]]});
        }
      }
      packed.end = static_cast<int>(vertices_.size());
      colors_.push_back(packed);
    }
    // The last one's end.
    vertices_.push_back({-1, static_cast<int>(incidences_.size()),
                         static_cast<int>(hinge_incidences_.size())});
  }

  // Who moves whom: the springs, and with hinges every pair of a hinge's four particles (two
  // vertices of one hinge must not relax at once, whether or not a spring joins them).
  static SpringAdjacency couplings(const ParticleSystem& ps) {
    const Model& model = ps.model();
    if (model.hinges.empty()) return ps.adjacency();
    std::vector<Spring> pairs(model.springs.begin(), model.springs.end());
    for (const Hinge& h : model.hinges) {
      for (int a = 0; a < 4; ++a) {
        for (int c = a + 1; c < 4; ++c) pairs.push_back({h.particle[a], h.particle[c]});
      }
    }
    return SpringAdjacency::build(model.particleCount(), pairs);
  }

  // One Newton step per vertex of a colour (in parallel: they share no spring). The Hessian as
  // a I + sum beta u u^T, its six distinct entries summed.
  void relaxColor(const Color& color) {
    double* x = x_.data();
    const double* x0 = step_.x0.data();
    const double inverse_h = 1.0 / step_.h;
#pragma omp parallel for schedule(static) if (color.end - color.begin >= kParallelVertices)
    for (int v = color.begin; v < color.end; ++v) {
      const int p = vertices_[v].particle;
      Eigen::Map<Vec3> xp(x + 3 * p);
      const Vec3 x0p = Eigen::Map<const Vec3>(x0 + 3 * p);
      const double m = step_.mass_over_h2[p];
      Vec3 f = -m * (xp - step_.target.segment<3>(3 * p));
      double diagonal = m, hxx = 0, hyy = 0, hzz = 0, hxy = 0, hxz = 0, hyz = 0;
      for (int e = vertices_[v].first; e < vertices_[v + 1].first; ++e) {
        const Incidence& in = incidences_[e];
        const Vec3 d = xp - Eigen::Map<const Vec3>(x + 3 * in.other);
        const double l = d.norm();
        if (l == 0.0) continue;  // no direction: the spring gives no step
        const double inverse_l = 1.0 / l;  // one division for u and rest / l
        const Vec3 u = inverse_l * d;
        const Vec3 moved = d - (x0p - Eigen::Map<const Vec3>(x0 + 3 * in.other));
        const double damping = in.damping * inverse_h;
        f -= (in.stiffness * (l - in.rest_length) + damping * u.dot(moved)) * u;
        const double across = in.stiffness * std::max(0.0, 1.0 - in.rest_length * inverse_l);
        const double along = in.stiffness + damping - across;
        diagonal += across;
        hxx += along * u.x() * u.x(), hyy += along * u.y() * u.y(), hzz += along * u.z() * u.z();
        hxy += along * u.x() * u.y(), hxz += along * u.x() * u.z(), hyz += along * u.y() * u.z();
      }
      // Hinges: energy 1/2 k |b|^2, so f -= k w b and the Hessian gains k w^2 I (hinge.h).
      for (int e = vertices_[v].first_hinge; e < vertices_[v + 1].first_hinge; ++e) {
        const Hinge& hinge = (*hinges_)[hinge_incidences_[e].hinge];
        const double w = hinge_incidences_[e].weight;
        f -= (hinge.stiffness * w) * hingeVector(hinge, x);
        diagonal += hinge.stiffness * w * w;
      }
      Mat3 hessian;
      hessian << diagonal + hxx, hxy, hxz, hxy, diagonal + hyy, hyz, hxz, hyz, diagonal + hzz;
      const int held = step_.holds.of(p);
      if (held < 0) {
        xp += hessian.llt().solve(f);
      } else if (!step_.holds.all()[held].whole) {  // held on a contact plane (contact_holds.h)
        const ContactHold& hold = step_.holds.all()[held];
        xp = stepOnPlane(hessian.llt(), f + hold.force, xp, hold);
      }
    }
  }

  static constexpr int kParallelVertices = 1024;  // below this, threads cost more than they save
  PassControl control_;
  ChebyshevAcceleration chebyshev_;
  std::vector<Color> colors_;
  std::vector<Vertex> vertices_;  // free vertices in colour order, then one end marker
  std::vector<Incidence> incidences_;
  std::vector<HingeIncidence> hinge_incidences_;
  const std::vector<Hinge>* hinges_ = nullptr;  // the system's, this step
  Vector x_;                  // (3N) the iterate
  Vector residual_;           // (3N) r(x) of implicit_euler_step.h, when measured
  Vector previous_velocity_;  // (3N) the last step's start velocity (initial guess)
  ImplicitEulerStep step_;
};

}  // namespace

std::unique_ptr<Integrator> makeVertexBlockDescent(const IntegratorSettings& s) {
  return std::make_unique<VertexBlockDescent>(PassControl::from(s), s.value("acceleration_rho"));
}

}  // namespace mysim
