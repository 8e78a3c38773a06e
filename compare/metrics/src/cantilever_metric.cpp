#include "compare/metrics/cantilever_metric.h"

#include <cmath>

namespace springcheck {
namespace {

// The strip's direction out of the clamp (+x, the rows) must be level, and so must the
// direction across it (the grid's columns: -z for a horizontal cloth).
bool levelClampedStrip(const mysim::Model& model) {
  if (!model.material || !model.material->clamped || !model.grid) return false;
  const double g = model.gravity.norm();
  if (g == 0.0 || model.wind || model.pin_motion || !model.colliders.empty()) return false;
  const mysim::Vec3 down = model.gravity / g;
  const mysim::Vec3 across = mysim::at3(model.start_position, model.grid->cols) -
                             mysim::at3(model.start_position, 0);
  return std::abs(down.x()) < 1e-12 && std::abs(down.dot(across.normalized())) < 1e-12;
}

}  // namespace

std::optional<CantileverReading> readCantilever(const mysim::Model& model,
                                                const mysim::ParticleRows& frame) {
  if (!levelClampedStrip(model)) return std::nullopt;
  const mysim::GridShape grid = *model.grid;
  const mysim::Vec3 down = model.gravity.normalized();
  CantileverReading r;
  for (int row = 0; row < grid.rows; ++row) {
    // From the clamp's edge, midway between the two pinned columns, to the free end.
    const int first = row * grid.cols, tip = first + grid.cols - 1;
    const mysim::Vec3 edge =
        0.5 * (frame.row(first).head<3>() + frame.row(first + 1).head<3>()).transpose();
    const mysim::Vec3 chord = frame.row(tip).head<3>().transpose() - edge;
    r.drop += chord.dot(down) / grid.rows;
    r.reach += chord.x() / grid.rows;
  }
  r.overhang = (grid.cols - 1.5) * model.material->dx;
  r.chord_angle = std::atan2(r.drop, r.reach);
  static const double steepest = heavyElastica(kLargestReadableLoad).chord_angle;  // solved once
  r.chord_bending_length = r.chord_angle > 0.0 && r.chord_angle < steepest
                               ? bendingLengthFromChord(r.overhang, r.chord_angle)
                               : 0.0;  // no elastica to read it by
  return r;
}

std::optional<CantileverReference> cantileverReference(const mysim::Model& model) {
  if (!levelClampedStrip(model) || model.hinges.empty()) return std::nullopt;
  const mysim::ClothMaterial& m = model.material->material;
  CantileverReference c;
  c.overhang = (model.grid->cols - 1.5) * model.material->dx;
  const double w = m.density * model.gravity.norm();
  c.load = w * std::pow(c.overhang, 3) / m.bending_rigidity;
  if (c.load > kLargestElasticaLoad) return std::nullopt;
  c.bending_length = std::cbrt(m.bending_rigidity / w);
  c.elastica = heavyElastica(c.load);
  c.chord_bending_length = bendingLengthFromChord(c.overhang, c.elastica.chord_angle);
  return c;
}

}  // namespace springcheck
