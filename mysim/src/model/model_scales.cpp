#include "mysim/model_scales.h"

#include <array>
#include <cmath>
#include <sstream>

namespace mysim {
namespace {

std::string text(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

// Nonzero, finite and within the scales, or an error text.
std::optional<std::string> outOfScale(double value, const std::string& what) {
  const double a = std::abs(value);
  if (a == 0.0) return std::nullopt;
  if (!std::isfinite(a) || a < kSmallestScale || a > kLargestScale) {
    return what + " is " + text(value) + ": outside " + text(kSmallestScale) + " .. " +
           text(kLargestScale) + " in SI units, where double precision can step it (" +
           "mysim/model_scales.h)";
  }
  return std::nullopt;
}

// The scene field a particle's mass came from, for messages.
std::string massField(const Model& model, int p) {
  if (model.material) return "system.material.density";
  if (model.naming != FieldNaming::PerItem) return "system.particle_mass";
  return "system.particles[" + std::to_string(p) + "].mass";
}

std::string hingeField(const Model& model) {
  return model.material ? "system.material.bending.rigidity" : "system.hinges";
}

// A material cloth's springs come from its membrane: the stretch or shear stiffness.
std::string springSource(const Model& model, int s, const std::string& parameter) {
  if (!model.material) return springField(model, s, parameter);
  if (parameter == "damping") return "system.material.damping_rate";
  return model.springs[s].family == SpringFamily::Shear ? "system.material.shear_stiffness"
                                                        : "system.material.stretch_stiffness";
}

std::optional<LimitError> checkMagnitudes(const Model& model) {
  for (int p = 0; p < model.particleCount(); ++p) {
    if (auto e = outOfScale(model.mass[p], "particle " + std::to_string(p) + "'s mass (kg)")) {
      return LimitError{massField(model, p), *e};
    }
    // Coordinates only from above: a tiny one is just near the origin (a rotation leaves 6e-17).
    for (int c = 0; c < 3; ++c) {
      const double x = model.start_position[3 * p + c];
      if (!std::isfinite(x) || std::abs(x) > kLargestScale) {
        return LimitError{"system", "particle " + std::to_string(p) + "'s coordinate is " +
                                        text(x) + " m: beyond " + text(kLargestScale) +
                                        " m, where double precision can step it; sizes and "
                                        "origins give the coordinates (mysim/model_scales.h)"};
      }
    }
  }
  for (int s = 0; s < static_cast<int>(model.springs.size()); ++s) {
    const Spring& sp = model.springs[s];
    if (auto e = outOfScale(sp.stiffness, "spring " + std::to_string(s) + "'s stiffness (N/m)")) {
      return LimitError{springSource(model, s, "stiffness"), *e};
    }
    if (auto e = outOfScale(sp.rest_length, "spring " + std::to_string(s) + "'s rest length (m)")) {
      return LimitError{model.material ? "system" : springField(model, s, "rest_length"),
                        *e + "; sizes and resolutions give the lengths"};
    }
    if (auto e = outOfScale(sp.damping, "spring " + std::to_string(s) + "'s damping (N s/m)")) {
      return LimitError{springSource(model, s, "damping"), *e};
    }
  }
  for (std::size_t h = 0; h < model.hinges.size(); ++h) {
    if (auto e = outOfScale(model.hinges[h].stiffness,
                            "hinge " + std::to_string(h) + "'s stiffness (N/m)")) {
      return LimitError{hingeField(model), *e};
    }
  }
  if (auto e = outOfScale(model.drag, "the drag (N s/m)")) return LimitError{"forces.drag", *e};
  if (auto e = outOfScale(model.gravity.norm(), "|gravity| (m/s^2)")) {
    return LimitError{"forces.gravity", *e};
  }
  return std::nullopt;
}

// h^2 k / m of a spring or hinge on its lightest free particle (0 when all its ends are pinned).
template <typename Ends>
double stepStiffness(const Model& model, double k, const Ends& ends, double dt) {
  double lightest = 0.0;
  for (int p : ends) {
    if (!model.pinned[p] && (lightest == 0.0 || model.mass[p] < lightest)) lightest = model.mass[p];
  }
  return lightest > 0.0 ? dt * dt * k / lightest : 0.0;
}

}  // namespace

std::optional<LimitError> checkModelScales(const Model& model, double dt) {
  if (auto e = outOfScale(dt, "the step (s)")) return LimitError{"integrator.dt", *e};
  if (model.isCircle()) return std::nullopt;
  if (auto e = checkMagnitudes(model)) return e;
  double stiffest = 0.0;
  for (const Spring& s : model.springs) {
    const double v = stepStiffness(model, s.stiffness, std::array{s.i, s.j}, dt);
    stiffest = std::max(stiffest, v);
  }
  for (const Hinge& h : model.hinges) {
    const double v = stepStiffness(model, h.stiffness, h.particle, dt);
    stiffest = std::max(stiffest, v);
  }
  if (std::sqrt(stiffest) > kLargestStepStiffness) {
    return LimitError{"integrator.dt",
                      text(dt) + " s gives the stiffest spring h w = " + text(std::sqrt(stiffest)) +
                          ", past " + text(kLargestStepStiffness) +
                          ": the step's inertia is lost in round-off (mysim/model_scales.h)"};
  }
  return std::nullopt;
}

}  // namespace mysim
