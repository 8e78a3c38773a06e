// The vectorised force (every spring once, then gathered per particle) against the plain per-end
// reference loop, on a cloth with every spring family, spring damping, drag, gravity and wind, in
// a disturbed state: the AVX2 kernel and the baseline one, at 1 and 2 threads.
// ctest-label: unit
#include <gtest/gtest.h>
#include <omp.h>

#include <random>

#include "mysim/cloth.h"
#include "mysim/particle_system.h"
#include "forces/spring_forces.h"

namespace mysim {
namespace {

ParticleSystem dampedCloth() {
  ClothShape shape;
  shape.rows = shape.cols = 40;  // 1600 particles: above the threshold where the loops go parallel
  shape.structural = SpringParameters{100, 0.3};
  shape.shear = SpringParameters{60, 0.2};
  shape.flex = SpringParameters{10, 0.05};
  Model model;
  buildCloth(shape, model);
  model.gravity = Vec3(0, -9.8, 0);
  model.drag = 0.5;
  model.wind = Wind{Vec3::UnitZ(), 0.01, 0.8, 0.1, 0.5, 7};
  model.pinned[0] = model.pinned[shape.cols - 1] = 1;
  return ParticleSystem(model, BlowUpLimits{});
}

struct Disturbed {
  Vector x, v;
};

Disturbed disturbed(const ParticleSystem& system) {
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> shake(-0.01, 0.01);
  Disturbed d{system.model().start_position, system.model().start_velocity};
  for (double& value : d.x) value += shake(random);
  for (double& value : d.v) value += 20 * shake(random);
  return d;
}

TEST(SpringForceKernel, EqualsThePerEndReferenceAtOneAndTwoThreadsWithAndWithoutSimd) {
  const ParticleSystem system = dampedCloth();
  const Disturbed d = disturbed(system);
  const int n3 = 3 * system.particleCount();
  Vector reference(n3);
  system.referenceForce(0.37, d.x, d.v, reference);
  const double scale = reference.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  for (bool simd : {true, false}) {
    setSpringForcesSimd(simd);
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      Vector fast(n3);
      system.force(0.37, d.x, d.v, fast);
      const double worst = (fast - reference).cwiseAbs().maxCoeff();
      // Round-off: the same operations in the same order give the same bits; allow a few ulps of
      // the largest force in case a compiler reorders.
      EXPECT_LE(worst, 1e-14 * scale)
          << "kernel " << springForcesKernel() << ", " << threads << " threads";
    }
  }
  setSpringForcesSimd(true);
  omp_set_num_threads(omp_get_num_procs());
}

TEST(SpringForceKernel, AnUndampedClothTakesTheVelocityFreeLoopAndStillMatches) {
  ClothShape shape;
  shape.rows = shape.cols = 24;
  shape.structural = SpringParameters{100, 0};
  shape.shear = SpringParameters{100, 0};
  shape.flex = SpringParameters{10, 0};
  Model model;
  buildCloth(shape, model);
  const ParticleSystem system(model, BlowUpLimits{});
  const Disturbed d = disturbed(system);
  Vector reference(d.x.size()), fast(d.x.size());
  system.referenceForce(0.0, d.x, d.v, reference);
  system.force(0.0, d.x, d.v, fast);
  EXPECT_LE((fast - reference).cwiseAbs().maxCoeff(), 1e-14 * reference.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace mysim
