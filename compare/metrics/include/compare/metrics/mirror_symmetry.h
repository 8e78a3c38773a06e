#pragma once
// A scene's plane of mirror symmetry, found from its model, and the drape distance that allows
// for it: a fold that can buckle either way (docs/findings.md section 7) settles to one of two
// mirror images, and two engines that pick different ones are not in disagreement about the
// shape. The plane is one of a grid cloth's two mid-planes (across its columns, across its rows)
// that maps the model onto itself: start positions, masses, pins, springs, gravity, pin motion
// and colliders; wind (a seeded random field) has no symmetry.
#include <optional>
#include <vector>

#include "compare/metrics/drape_metric.h"
#include "mysim/model.h"

namespace springcheck {

struct MirrorSymmetry {
  mysim::Vec3 point, normal;  // the plane: through point, unit normal
  std::vector<int> image;     // node p's mirror image is node image[p]
  const char* across = "";    // "columns" or "rows", for messages
};

// The first of the grid's mid-planes the model is symmetric under (to 1e-9 of its extent), if any.
std::optional<MirrorSymmetry> mirrorSymmetry(const mysim::Model& model);

// `b` reflected across the plane, node p taking the place of its image: compared with `a` node by
// node, the distance of a to b's mirror image.
Positions mirrored(const MirrorSymmetry& mirror, const Positions& b);

}  // namespace springcheck
