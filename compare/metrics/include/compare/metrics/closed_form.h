#pragma once
#include <expected>
#include <optional>
#include <string>

#include "mysim/model.h"
#include "mysim/simulation.h"

namespace springcheck {

// Error of a run against the scene's closed form, where it has one:
//  - circle: max over frames of |(x, y) - exact|, exact = the start rotated by t;
//  - a chain hanging straight down along gravity from one pin: max |y_j - y_j(closed form)| at
//    the last frame, y_j = -[j L0 + (m g / k) j (2N - j + 1) / 2];
//  - a pendulum (chain of two, one pinned): relative error of the period measured from the
//    x-crossings of the bob against the rigid pendulum's T = 4 sqrt(L / g) K(sin(theta0 / 2));
//  - a chain pinned at both ends (not one above the other): max |x_j - x_j(closed form)| at the
//    last frame, x_j the discrete elastic catenary (closed_form.cpp: the tension's horizontal part
//    and the first segment's vertical part solved by Newton to 1e-13 of the span);
//  - a material strip in a clamp with hinge bending (cantilever_metric.h): |tip drop - the heavy
//    elastica's| at the last frame, m;
//  - a body resting on one plane, sliding or held by Coulomb friction (sliding_contact.h): the
//    largest |centroid displacement - the rigid block's| over the frames, m.
struct ClosedFormError {
  std::string quantity;  // what was compared
  double error = 0.0;    // in `unit`
  double exact = 0.0;    // the closed-form value compared against (end position or period)
  // For a closed form of the state at rest: how far the nodes still moved over the run's last
  // tenth, m. An error not much above it is the motion left at the end, not the engine's
  // accuracy (the same for float and double engines): run longer to see that.
  std::optional<double> motion_left;
  // "m" for a position or distance, "rel" for a relative error (a period, a frequency): the
  // unit a table, a gate and the report print beside the error.
  std::string unit = "m";
  // motion_left is close enough to the error to be its floor (error < 10 x motion_left).
  bool atMotionFloor() const { return motion_left && error < 10.0 * *motion_left; }
};
// The error, or why the run has no closed form to be held to (a blank in a table would not say
// whether the reference does not apply, was never computed, or failed): a sentence for tables
// and the report.
using ClosedFormResult = std::expected<ClosedFormError, std::string>;
// Read from the model (so a sweep's scaled model gets its own closed form): a chain of equal
// springs and masses, pinned at particle 0 only, with no wind, pin motion or sphere. A run that
// blew up has none (its last frame is only the last healthy one).
ClosedFormResult closedFormError(const mysim::Model& model, const mysim::RunRecord& run);

// The discrete elastic catenary's nodes, pins included, for a uniform chain pinned at its two
// ends (nothing when the model is not one, or the pins are one above the other).
std::optional<std::vector<mysim::Vec3>> twoPinCatenaryNodes(const mysim::Model& model);

// Whether the springs join particle p to p + 1 for every p and nothing else (in any order): a
// chain whatever the scene called it (the uniform chain's closed forms, the capstan).
bool isIndexOrderedPath(const mysim::Model& model);

// Complete elliptic integral of the first kind K(k), by the arithmetic-geometric mean.
double ellipticK(double k);

}  // namespace springcheck
