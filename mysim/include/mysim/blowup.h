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
  // A passive scene (no wind, no moving pins) cannot gain energy: a rise of its total energy
  // above the lowest earlier value by more than this fraction of the energy scale is an
  // instability, even one that levels off or stays below the start. Stable runs rise far less
  // (measured on the undamped chain_swing, scale 4.37 J: bullet-classic's position-based jitter
  // 3.1 %, symplectic Euler's bounded oscillation 1.1 %, trapezoidal 0.6 %, Verlet 0.03 %);
  // 10 % leaves three times the largest and is still tiny against what an unstable run pumps in
  // (forward Euler on the same chain: past 10 % within 0.8 s, exploding soon after).
  double max_energy_rise = 0.1;
  // The same in a passive scene with drag, where every mode decays and stable runs rise less
  // still (measured: bullet-classic 1.9 % on chain_hanging, every mysim integrator and the other
  // Bullet engines below 0.05 % on the matched damped scenes). An instability that levels off
  // hides below 10 % there: RK4 on cloth_hanging at h = 6 ms rises 3.6 % and keeps 8 mJ of
  // motion where the converged run keeps 1.6e-11 J. 2.5 % catches it and passes classic.
  double max_energy_rise_damped = 0.025;
};

// What stopped a run: when, at which step and which check.
struct BlowUp {
  double time = 0.0;  // s, the time of the first unhealthy state
  long step = 0;
  // "non-finite", "strain", "energy" (runaway), "energy-rise" (a passive scene gained energy),
  // "step-limit" (adaptive), "engine" (an external engine said so)
  std::string check;
  std::string detail;
};

}  // namespace mysim
