#pragma once
#include "mysim/model.h"

namespace mysim {

// A chain of particles joined by springs, particle 0 first, laid out from `origin` along
// `direction` at rest length spacing (the seed's pendulum: particle 0 pinned, the rest along +x).
// A single pendulum is a chain of two particles.
struct ChainShape {
  int particles = 2;
  double rest_length = 0.1;     // m, between neighbours
  double spacing = 0.0;         // m, between neighbours at the start; 0 = rest_length (a taut chain: more)
  double particle_mass = 0.01;  // kg
  double stiffness = 100.0;     // N/m
  double damping = 0.0;         // N s/m along each spring
  Vec3 origin = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();  // unit vector
};

// Fills masses, start positions and springs; pins, forces and velocities are left to the caller.
void buildChain(const ChainShape& shape, Model& model);

}  // namespace mysim
