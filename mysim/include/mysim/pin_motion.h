#pragma once
#include "mysim/types.h"

namespace mysim {

// Prescribed motion of every pinned particle (the seed's swinging cloth):
//   x(t) = x0 + axis * amplitude * sin(2 pi f t)
struct PinMotion {
  Vec3 axis = Vec3::UnitX();  // unit vector
  double amplitude = 0.0;     // m
  double frequency = 0.0;     // Hz

  Vec3 offset(double t) const;
  Vec3 velocity(double t) const;
  Vec3 acceleration(double t) const;
};

}  // namespace mysim
