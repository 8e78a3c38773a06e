#pragma once
// Scenes the benchmarks share: the matched hanging cloth (1 m square, 0.5 kg, structural and
// shear 100 N/m, flex 10 N/m, drag 2 /s, top corners pinned) at any resolution.
#include "mysim/scene.h"

namespace bench {

inline mysim::Scene hangingCloth(int n, const std::string& integrator = "symplectic-euler",
                                 double dt = 5e-4) {
  mysim::Scene s;
  s.name = "cloth" + std::to_string(n);
  s.source = "(benchmark cloth)";
  mysim::ClothScene& cloth = s.system.emplace<mysim::ClothScene>();
  cloth.shape.rows = cloth.shape.cols = n;
  cloth.shape.particle_mass = 0.5 / (double(n) * n);
  cloth.shape.structural = cloth.shape.shear = mysim::SpringParameters{100.0, 0.0};
  cloth.shape.flex = mysim::SpringParameters{10.0, 0.0};
  cloth.start.pins = {0, n - 1};
  s.gravity = mysim::Vec3(0, -9.8, 0);
  s.drag = 2.0 * cloth.shape.particle_mass;
  s.integrator.name = integrator;
  s.dt = dt;
  s.duration = 1.0;
  return s;
}

// Stable explicit step for an n x n cloth: the fastest mode grows as n (spacing 1/n, mass 1/n^2),
// w_max ~ sqrt(8 k / m) = sqrt(8 * 100 * 2) n = 40 n; h w < 1 keeps every explicit method stable.
inline double stableStep(int n) { return 1.0 / (40.0 * n); }

}  // namespace bench
