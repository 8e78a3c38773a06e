#include "mysim/start_state.h"

#include <algorithm>
#include <sstream>

#include <nlohmann/json.hpp>

#include "mysim/collider.h"

namespace mysim {

std::optional<LimitError> checkStartOutsideColliders(const Model& model) {
  for (std::size_t k = 0; k < model.colliders.size(); ++k) {
    int inside = 0, first = -1;
    double deepest = 0.0;
    for (int p = 0; p < model.particleCount(); ++p) {
      if (model.pinned[p]) continue;
      // Round-off on a surface is not inside: a thousandth of a micrometre of slack.
      const double d = signedDistance(model.colliders[k], at3(model.start_position, p));
      if (d < -1e-9) {
        if (first < 0) first = p;
        ++inside;
        deepest = std::min(deepest, d);
      }
    }
    if (inside == 0) continue;
    std::ostringstream m;
    m.precision(3);
    m << inside << " free particle(s) start inside this " << describeCollider(model.colliders[k])["type"].get<std::string>()
      << " (particle " << first << " first, the deepest " << -deepest
      << " m in): start them outside; a node that crosses a surface during a step leaves through "
         "the nearest face, but nodes placed inside would be pushed onto one another";
    return LimitError{"colliders[" + std::to_string(k) + "]", m.str()};
  }
  return std::nullopt;
}

}  // namespace mysim
