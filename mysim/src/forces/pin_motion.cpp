#include "mysim/pin_motion.h"

#include <cmath>
#include <numbers>

namespace mysim {

Vec3 PinMotion::offset(double t) const {
  const double w = 2.0 * std::numbers::pi * frequency;
  return amplitude * std::sin(w * t) * axis;
}

Vec3 PinMotion::velocity(double t) const {
  const double w = 2.0 * std::numbers::pi * frequency;
  return amplitude * w * std::cos(w * t) * axis;
}

Vec3 PinMotion::acceleration(double t) const {
  const double w = 2.0 * std::numbers::pi * frequency;
  return -amplitude * w * w * std::sin(w * t) * axis;
}

}  // namespace mysim
