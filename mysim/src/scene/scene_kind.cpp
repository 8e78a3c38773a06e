// What scene kinds share: a hanging body's pins and start velocity, and reading its pins.
#include "mysim/scene_kind.h"

#include <set>

#include "read_pins.h"

namespace mysim {

using nlohmann::json;

void HangingStart::apply(Model& model) const {
  for (int p : pins) model.pinned[p] = 1;
  for (int p = 0; p < model.particleCount(); ++p) {
    if (!model.pinned[p]) at3(model.start_velocity, p) = velocity;
  }
  model.hangs_from_pins = true;
}

void HangingStart::checkSomethingMoves(double particles) const {
  if (static_cast<double>(pins.size()) >= particles) {
    throw FieldError{"system.pins", "every particle is pinned: nothing would move"};
  }
}

std::vector<int> readPins(FieldReader& system, int count, const std::vector<int>& fallback,
                          int rows, int cols) {
  if (!system.has("pins")) return fallback;
  const json& v = system.raw("pins");
  const std::string field = system.field("pins");
  if (v.is_string()) {
    const std::string preset = v.get<std::string>();
    if (rows > 0 && preset == "top_corners") return {0, cols - 1};
    if (rows > 0 && preset == "corners") return {0, cols - 1, (rows - 1) * cols, rows * cols - 1};
    if (preset == "none") return {};
    failField(field,
              rows > 0 ? "\"top_corners\", \"corners\", \"none\" or a list of particle indices"
                       : "\"none\" or a list of particle indices",
              v);
  }
  if (!v.is_array()) failField(field, "a list of particle indices", v);
  std::vector<int> pins;
  std::set<int> unique;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const std::string item = field + "[" + std::to_string(k) + "]";
    if (!v[k].is_number_integer()) failField(item, "a particle index", v[k]);
    const long p = v[k].get<long>();
    if (p < 0 || p >= count) {
      failField(item, "a particle index in [0, " + std::to_string(count - 1) + "]", v[k]);
    }
    if (!unique.insert(static_cast<int>(p)).second)
      failField(item, "each particle pinned once", v[k]);
    pins.push_back(static_cast<int>(p));
  }
  return pins;
}

}  // namespace mysim
