#include <algorithm>
#include <array>
#include <cmath>

#include "mysim/integrator.h"

namespace mysim {
namespace {

// Dormand and Prince, "A family of embedded Runge-Kutta formulae" (J. Comp. Appl. Math. 6, 1980):
// a fifth-order solution with an embedded fourth-order one; their difference estimates the local
// error. A call advances by the scene step H with as many internal steps as the tolerance needs:
//   err = rms_i( e_i / (atol + rtol max(|y0_i|, |y1_i|)) ),  accept if err <= 1,
//   h_next = h min(5, max(0.2, 0.9 err^(-1/5))).
// The first-same-as-last stage is not reused: afterStep() (pins, collider) may move the state.
constexpr std::array<double, 7> c = {0.0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1.0, 1.0};
constexpr double a[7][6] = {
    {},
    {1.0 / 5},
    {3.0 / 40, 9.0 / 40},
    {44.0 / 45, -56.0 / 15, 32.0 / 9},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
    {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
// Fifth-order weights are the last row of a; e = b5 - b4 gives the error estimate.
constexpr std::array<double, 7> e = {71.0 / 57600,      0.0,        -71.0 / 16695, 71.0 / 1920,
                                     -17253.0 / 339200, 22.0 / 525, -1.0 / 40};

class DormandPrince final : public Integrator {
 public:
  DormandPrince(double atol, double rtol) : atol_(atol), rtol_(rtol) {}

  StepCounts step(OdeSystem& system, State& s, double H) override {
    StepCounts counts;
    const double t_end = s.t + H;
    if (h_ <= 0.0) h_ = H;
    while (t_end - s.t > 1e-12 * H) {
      const bool last = h_ >= t_end - s.t;
      const double h = last ? t_end - s.t : h_;
      // Limits: a step below kMinStep H, or more than kMaxSteps trials in one scene step, means
      // the tolerance cannot be met (tighter than double precision, or a blowing-up solution).
      // Stop, and say so, rather than crawl forever.
      if (h < kMinStep * H || counts.accepted + counts.rejected >= kMaxSteps) {
        counts.gave_up = true;
        return counts;
      }
      const double err = trialStep(system, s, h);
      counts.derivative_evaluations += 7;
      const double factor = std::isfinite(err)
                                ? std::clamp(0.9 * std::pow(std::max(err, 1e-10), -0.2), 0.2, 5.0)
                                : 0.2;
      if (err <= 1.0) {
        s.y = y5_;
        s.t = last ? t_end : s.t + h;
        system.afterStep(s);
        ++counts.accepted;
        // A step cut short to land on t_end says nothing about the step the error allows.
        if (!last || factor < 1.0) h_ = h * factor;
      } else {
        ++counts.rejected;
        h_ = h * factor;
      }
    }
    return counts;
  }

 private:
  static constexpr double kMinStep = 1e-10;   // of the scene step: 10^10 internal steps a step
  static constexpr long kMaxSteps = 100'000;  // trials in one scene step

  // Fills y5_ with the fifth-order solution at s.t + h and returns the scaled error norm.
  double trialStep(OdeSystem& system, const State& s, double h) {
    for (int i = 0; i < 7; ++i) {
      trial_ = s.y;
      for (int j = 0; j < i; ++j) {
        if (a[i][j] != 0.0) trial_ += (h * a[i][j]) * k_[j];
      }
      system.derivative(s.t + c[i] * h, trial_, k_[i]);
    }
    y5_ = trial_;  // stage 7 is evaluated at the fifth-order solution itself
    error_ = Vector::Zero(s.y.size());
    for (int i = 0; i < 7; ++i) {
      if (e[i] != 0.0) error_ += (h * e[i]) * k_[i];
    }
    const Vector scale = (atol_ + rtol_ * s.y.cwiseAbs().cwiseMax(y5_.cwiseAbs()).array()).matrix();
    return std::sqrt((error_.array() / scale.array()).square().mean());
  }

  double atol_, rtol_;
  double h_ = 0.0;  // the step the error control proposes next
  std::array<Vector, 7> k_;
  Vector trial_, y5_, error_;
};

}  // namespace

std::unique_ptr<Integrator> makeDormandPrince(double abs_tolerance, double rel_tolerance) {
  return std::make_unique<DormandPrince>(abs_tolerance, rel_tolerance);
}

}  // namespace mysim
