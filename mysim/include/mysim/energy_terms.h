#pragma once
// The energy a system reports, by term (its computation for a model: mysim/energy.h).

namespace mysim {

// Mechanical energy split by term, in joules. Damping, drag, wind and driven pins change the total
// on purpose, so the terms are kept apart for the reports to tell them.
struct EnergyTerms {
  double kinetic = 0.0;  // sum 1/2 m |v|^2 over free particles
  double gravity = 0.0;  // sum -m g.x over free particles (zero at the origin)
  double spring = 0.0;   // sum 1/2 k (|xj - xi| - rest)^2 over springs, and the hinges' 1/2 k |b|^2
  // Work done on the system since t = 0 by what the scene drives from outside (wind, moving
  // pins), J; not part of total(). total() - external_work cannot rise in a damped scene.
  double external_work = 0.0;
  double total() const { return kinetic + gravity + spring; }
};

}  // namespace mysim
