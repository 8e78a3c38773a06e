#pragma once
#include <optional>

#include "compare/metrics/heavy_elastica.h"
#include "mysim/model.h"
#include "mysim/simulation.h"

namespace springcheck {

// A strip held in a clamp along its left edge (a material cloth with pins "left_clamp", lying
// level under gravity): the cantilever of ASTM D1388 / ISO 9073-7, and the heavy elastica it
// should settle to.
struct CantileverReference {
  double overhang = 0.0;        // L, m: from the clamp edge to the free end
  double load = 0.0;            // w L^3 / B
  double bending_length = 0.0;  // (B / w)^(1/3), m: the material's own
  ElasticaTip elastica;         // in units of L
  double chord_bending_length = 0.0;   // m: what Peirce's formula reads from the elastica's chord
};
// Nothing unless the model is such a strip with hinge bending.
std::optional<CantileverReference> cantileverReference(const mysim::Model& model);

// What a cantilever tester reads from one frame of such a strip, averaged over the strip's rows:
// the free end's drop below the clamp edge and reach beyond it (m), the chord's angle below the
// horizontal, and Peirce's bending length from it. Nothing unless the model is a clamped
// material strip (either bending model) lying level.
struct CantileverReading {
  double overhang = 0.0, drop = 0.0, reach = 0.0, chord_angle = 0.0, chord_bending_length = 0.0;
};
std::optional<CantileverReading> readCantilever(const mysim::Model& model,
                                                const mysim::ParticleRows& frame);

}  // namespace springcheck
