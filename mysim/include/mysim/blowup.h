#pragma once
#include <string>

namespace mysim {

// Bounds past which a run is declared blown up and stopped.
struct BlowUpLimits {
  // Largest |l / rest - 1| of any spring. A cloth under gravity stays far below 1; 5 (six times
  // its rest length) is no physical drape.
  double max_strain = 5.0;
  // Kinetic energy above this many times the scene's energy scale (see ParticleSystem) is runaway:
  // gravity, springs, wind and pins cannot supply that much in any of our scenes.
  double max_energy_ratio = 100.0;
};

// What stopped a run: when, at which step and which check.
struct BlowUp {
  double time = 0.0;  // s, the time of the first unhealthy state
  long step = 0;
  std::string check;  // "non-finite", "strain", "energy", "step-limit" (adaptive), "engine"
  std::string detail;
};

}  // namespace mysim
