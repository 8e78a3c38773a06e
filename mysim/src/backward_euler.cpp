#include <Eigen/SparseCore>
#include <algorithm>
#include <vector>

#include "mysim/conjugate_gradient.h"
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
//
// The matrix has a fixed pattern (3x3 blocks: a particle and its free neighbours), built once as
// a row-major CSR matrix; each step refills its values in place, row by row, gathered per
// particle from the spring adjacency like the forces (so in parallel, with no write conflicts).
// CG (conjugate_gradient.h) starts from the previous step's dv.
class BackwardEuler final : public Integrator {
 public:
  BackwardEuler(double tolerance, int max_iterations)
      : tolerance_(tolerance), max_iterations_(max_iterations) {}
  bool needsParticles() const override { return true; }

  StepCounts step(OdeSystem& system, State& s, double h) override {
    ParticleSystem& ps = *system.particles();
    const Model& model = ps.model();
    const int n = ps.particleCount(), n3 = 3 * n;
    if (free_index_.empty()) buildPattern(ps);

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

    const CgResult cg = conjugateGradient(matrix_, rhs_, dv_free_, tolerance_, max_iterations_);
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
  // Numbers the free particles and lays out the matrix: for free particle p, the block columns
  // are p and its free neighbours, sorted; every block is dense 3x3.
  void buildPattern(const ParticleSystem& ps) {
    const Model& model = ps.model();
    const SpringAdjacency& a = ps.adjacency();
    const int n = ps.particleCount();
    free_index_.assign(n, -1);
    int free_count = 0;
    for (int p = 0; p < n; ++p) {
      if (!model.pinned[p]) free_index_[p] = free_count++;
    }
    // Per incidence, the block column slot in its row (or -1 for a pinned neighbour); per
    // particle, its diagonal slot.
    incidence_slot_.assign(a.other.size(), -1);
    diagonal_slot_.assign(n, -1);
    std::vector<Eigen::Triplet<double>> pattern;
    for (int p = 0; p < n; ++p) {
      if (free_index_[p] < 0) continue;
      std::vector<int> columns = {p};
      for (int e = a.offsets[p]; e < a.offsets[p + 1]; ++e) {
        if (free_index_[a.other[e]] >= 0) columns.push_back(a.other[e]);
      }
      std::sort(columns.begin(), columns.end());
      columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
      auto slot = [&](int q) {
        return static_cast<int>(std::lower_bound(columns.begin(), columns.end(), q) - columns.begin());
      };
      diagonal_slot_[p] = slot(p);
      for (int e = a.offsets[p]; e < a.offsets[p + 1]; ++e) {
        if (free_index_[a.other[e]] >= 0) incidence_slot_[e] = slot(a.other[e]);
      }
      for (int q : columns) {
        for (int r = 0; r < 3; ++r) {
          for (int c = 0; c < 3; ++c) {
            pattern.emplace_back(3 * free_index_[p] + r, 3 * free_index_[q] + c, 0.0);
          }
        }
      }
    }
    matrix_.resize(3 * free_count, 3 * free_count);
    matrix_.setFromTriplets(pattern.begin(), pattern.end());
    matrix_.makeCompressed();
    rhs_.setZero(3 * free_count);
    dv_free_.setZero(3 * free_count);
  }

  // Adds a 3x3 block at (row particle p, block slot) of the CSR values.
  void addBlock(int p, int slot, const Mat3& block) {
    double* values = matrix_.valuePtr();
    const int* starts = matrix_.outerIndexPtr();
    const int row = 3 * free_index_[p];
    for (int r = 0; r < 3; ++r) {
      double* entry = values + starts[row + r] + 3 * slot;
      for (int c = 0; c < 3; ++c) entry[c] += block(r, c);
    }
  }

  // Matrix values and right-hand side for this step, one free particle (three rows) at a time.
  void fill(const ParticleSystem& ps, const Eigen::Ref<const Vector>& x,
            const Eigen::Ref<const Vector>& v, double h) {
    const Model& model = ps.model();
    const SpringAdjacency& a = ps.adjacency();
    const int n = ps.particleCount();
    std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
#pragma omp parallel for schedule(static) if (n >= 2048)
    for (int p = 0; p < n; ++p) {
      if (free_index_[p] < 0) continue;
      const Vec3 xp = x.segment<3>(3 * p), vp = v.segment<3>(3 * p);
      Mat3 diagonal = (model.mass[p] + h * model.drag) * Mat3::Identity();
      // h f0, plus h^2 (df/dx v0)_p = h^2 sum J (v_q - v_p) over p's springs.
      Vec3 rhs = h * f_.segment<3>(3 * p);
      for (int e = a.offsets[p]; e < a.offsets[p + 1]; ++e) {
        const int q = a.other[e];
        const SpringAdjacency::Parameters& sp = a.parameters[a.parameter[e]];
        const ImplicitSpringBlock b = implicitSpringBlock(xp, x.segment<3>(3 * q), sp.rest_length,
                                                          sp.stiffness, sp.damping, h);
        const Mat3 block = b.matrix();
        rhs += h * h * b.timesJ(v.segment<3>(3 * q) - vp);
        diagonal += block;
        if (incidence_slot_[e] >= 0) {
          addBlock(p, incidence_slot_[e], -block);
        } else {
          rhs += block * dv_known_.segment<3>(3 * q);  // -(-block) times the pinned dv
        }
      }
      addBlock(p, diagonal_slot_[p], diagonal);
      rhs_.segment<3>(3 * free_index_[p]) = rhs;
    }
  }

  std::vector<int> free_index_;      // (N) block row of each free particle, -1 if pinned
  std::vector<int> incidence_slot_;  // (2S) block column slot of each incidence, -1 if pinned
  std::vector<int> diagonal_slot_;   // (N)
  Vector f_, dv_known_, rhs_, dv_free_;
  RowMajorMatrix matrix_;
  double tolerance_;
  int max_iterations_;
};

}  // namespace

std::unique_ptr<Integrator> makeBackwardEuler(double cg_tolerance, int cg_max_iterations) {
  return std::make_unique<BackwardEuler>(cg_tolerance, cg_max_iterations);
}

}  // namespace mysim
