#pragma once
// The Cusick drape test (BS 5058; ISO 9073-9 for nonwovens): a disc specimen clamped centrally on
// a smaller support disc drapes under gravity; its drape coefficient is
//   DC = (A_shadow - A_support) / (A_specimen - A_support),
// A_shadow the area of its shadow (the settled mesh projected along gravity), A_support the
// support disc's, A_specimen the flat specimen's: 1 for a cloth that stays flat, near 0 for one
// that hangs straight down. Its folds (nodes) are the lobes of the shadow's outline.
#include <optional>
#include <vector>

#include "mysim/model.h"
#include "mysim/simulation.h"

namespace springcheck {

struct DrapeTestReading {
  double specimen_area = 0.0;  // m^2, the mesh flat (its own triangles, not pi R^2)
  double support_area = 0.0;   // m^2, pi r^2, r the farthest pinned vertex from their centre
  double shadow_area = 0.0;    // m^2
  double drape_coefficient = 0.0;
  int folds = 0;
  std::vector<double> rim_radius;  // m, the rim's distance from the centre in the shadow, by angle
};

// For a mesh cloth pinned in its middle under gravity; nothing otherwise. The shadow is
// rasterised on a 4096 x 4096 grid over its bounding square: its area is within about one
// pixel row along its outline, 2.5e-4 of a 30 cm disc's. Folds: the rim's radius around the
// centre, counted as excursions above the mean by a fifth of its largest deviation each way and
// back; 0 if the rim is round to 1e-3 of its radius.
std::optional<DrapeTestReading> readDrapeTest(const mysim::Model& model,
                                              const mysim::ParticleRows& frame);

}  // namespace springcheck
