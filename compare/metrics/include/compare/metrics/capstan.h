#pragma once
#include <optional>

#include "compare/metrics/closed_form.h"

namespace springcheck {

// The capstan (Euler-Eytelwein): a chain over a fixed collider with friction (a sphere, which is
// a cylinder to a chain in one plane through its centre), a heavy mass at each end. Static
// friction holds it while the tension on the load side is at most e^(mu_s phi) times the tension
// on the holding side, phi the angle the chain turns through on the collider. Read from the
// model and its first frame: a chain of springs joining particle p to p + 1, no pins, both ends at
// least 10 times heavier than any other particle, exactly one collider with friction, a sphere,
// touched by one unbroken run of the chain's particles (others, frictionless, may redirect it
// as pulleys).
struct Capstan {
  int hold = 0, load = 0;  // the lighter end particle and the heavier (equal: the last is load)
  double wrap = 0.0;       // rad: the angle between the links entering and leaving the contact
  double mu = 0.0;         // the collider's static coefficient
  // The chain's weight each side adds to its end's, as a mass: its mass per length times the
  // height from the end up to the contact (a chain at rest on frictionless supports gains tension
  // w g dy as it climbs, whatever its path), kg.
  double hold_side = 0.0, load_side = 0.0;
  mysim::Vec3 down = -mysim::Vec3::UnitY();  // gravity's direction
  double ratio() const;  // e^(mu phi)
  // The largest load-end mass static friction holds: e^(mu phi) (M_hold + hold_side) - load_side.
  double holdingLoad(const mysim::Model& model) const;
};
std::optional<Capstan> capstanOf(const mysim::Model& model, const mysim::ParticleRows& first);

// How far the load end sank (along gravity) over the last half of a run, m: a capstan that holds
// stops within the first half (a step load sets the chain sliding until friction stops it). Along
// gravity only: the hanging load sways sideways as a pendulum (+-2 mm, a period of 0.9 s, which
// backward Euler hardly damps) without slipping.
double loadDriftOverLastHalf(const Capstan& capstan, const mysim::RunRecord& run);

// Nothing when the run is not a capstan; a load within the holding load: its drift over the
// last half (exact 0); a heavier one: why it has no closed form (it slips; `springcheck capstan`
// measures the largest load that holds).
std::optional<ClosedFormResult> capstanError(const mysim::Model& model, const mysim::RunRecord& run);

}  // namespace springcheck
