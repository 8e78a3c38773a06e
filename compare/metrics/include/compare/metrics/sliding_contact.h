#pragma once
#include <optional>

#include "compare/metrics/closed_form.h"
#include "mysim/contact.h"

namespace springcheck {

// A body on one flat plane under gravity, with the plane's Coulomb friction (or none): every
// particle free and on the plane (its surface grown by the margin) at the first frame, the body
// unstressed and moving as one, under gravity and drag (equal masses, so drag slows every
// particle alike: dv/dt = a - k v, k = drag / m). It then slides as a rigid block, which has a
// closed form (without drag; with it the same phases on exponentials):
// gravity splits into g_n pressing on the plane and g_t along it; at rest the block sticks when
// |g_t| <= mu_s g_n, else slides along g_t with |g_t| - mu_k g_n; moving at u along e it changes
// speed at g_t . e - mu_k g_n, stops after u^2 / (2 (mu_k g_n - g_t . e)) when that is negative
// (v0^2 / (2 mu_k g) on level ground), and then sticks or slides down as from rest.
struct SlidingBlock {
  mysim::Vec3 start;        // the mass-weighted centroid at the first frame, m
  mysim::Vec3 velocity;     // its velocity along the plane, m/s
  mysim::Vec3 along_plane;  // g_t, m/s^2
  double pressing = 0.0;    // g_n > 0, m/s^2
  mysim::Friction friction;
  double drag_rate = 0.0;   // drag / particle mass, 1/s (equal masses: the block slows as one)
};

// The centroid's displacement after t seconds, m.
mysim::Vec3 slideDisplacement(const SlidingBlock& block, double t);

// Nothing when the run is not a body resting on one plane (the other closed forms are tried);
// else the largest |centroid displacement - closed form| over the frames, m, or why this body on
// a plane has no closed form (wind, drag on unequal masses, a stressed start, uneven velocities,
// a slide across the slope).
std::optional<ClosedFormResult> slidingError(const mysim::Model& model, const mysim::RunRecord& run);

}  // namespace springcheck
