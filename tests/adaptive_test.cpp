// Dormand-Prince 5(4): the tolerance is the user's speed/accuracy knob.
// ctest-label: physics
#include <gtest/gtest.h>

#include "test_support.h"

namespace mysim {
namespace {

struct AdaptiveRun {
  double error;  // |u(T) - exact| / amplitude
  StepCounts counts;
};

AdaptiveRun runAdaptive(double tolerance) {
  testing::Oscillator osc;
  osc.drag = 0.4;
  ParticleSystem system(osc.model(), {});
  IntegratorSettings settings{
      .name = "dopri5", .abs_tolerance = tolerance * osc.amplitude, .rel_tolerance = tolerance};
  auto method = std::move(makeIntegrator(settings).value());
  State s = system.initialState();
  AdaptiveRun run;
  const double frame = 0.5, T = 10.0;  // scene step: the adaptive method subdivides it
  for (int n = 0; n < T / frame; ++n) run.counts += method->step(system, s, frame);
  run.error = std::abs(s.y[3] - osc.rest_length - osc.displacement(s.t)) / osc.amplitude;
  EXPECT_DOUBLE_EQ(s.t, T);
  return run;
}

TEST(Dopri5, MeetsItsToleranceOnTheOscillator) {
  for (double tol : {1e-4, 1e-6, 1e-8}) {
    const AdaptiveRun run = runAdaptive(tol);
    // The tolerance bounds the local error per step; over ~3 oscillation periods the global error
    // stays within a small multiple of it (10x leaves room for accumulation across steps).
    EXPECT_LT(run.error, 10 * tol) << tol;
  }
}

TEST(Dopri5, LooserToleranceTakesFewerSteps) {
  const AdaptiveRun tight = runAdaptive(1e-8), loose = runAdaptive(1e-4);
  EXPECT_LT(loose.counts.accepted, tight.counts.accepted);
  EXPECT_LT(loose.counts.derivative_evaluations, tight.counts.derivative_evaluations);
  EXPECT_LT(tight.error, loose.error);
  // Fifth order: 10^4 tighter costs about 10^(4/5) = 6.3x more steps; allow 3x to 12x.
  const double ratio = double(tight.counts.accepted) / loose.counts.accepted;
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(ratio, 12.0);
}

TEST(Dopri5, RejectsStepsWhenTheSceneStepIsFarTooLong) {
  const AdaptiveRun run = runAdaptive(1e-8);
  // The first trial step is the whole 0.5 s frame (h w0 = 1): too long for 1e-8.
  EXPECT_GT(run.counts.rejected, 0);
}

}  // namespace
}  // namespace mysim
