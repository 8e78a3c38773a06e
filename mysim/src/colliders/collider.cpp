#include "mysim/collider.h"

#include <nlohmann/json.hpp>

#include "mysim/json_input.h"

namespace mysim {
namespace {

// Every alternative of the variant, in order, as a call f(Shape{}) each: the variant is the
// only list of shapes.
template <typename F, std::size_t... I>
void forEachShape(F f, std::index_sequence<I...>) {
  (f(std::variant_alternative_t<I, Collider>{}), ...);
}
template <typename F>
void forEachShape(F f) {
  forEachShape(f, std::make_index_sequence<std::variant_size_v<Collider>>{});
}

}  // namespace

std::string colliderTypes() {
  std::string types;
  forEachShape(
      [&](auto shape) { types += (types.empty() ? "" : ", ") + std::string(shape.kType); });
  return types;
}

Collider readCollider(FieldReader& r) {
  const std::string type = r.text("type");
  std::optional<Collider> collider;
  forEachShape([&](auto shape) {
    if (!collider && type == shape.kType) collider = decltype(shape)::read(r);
  });
  if (!collider) failField(r.field("type"), "one of " + colliderTypes(), r.raw("type"));
  const Friction friction = readFriction(r);
  std::visit([&](auto& shape) { shape.friction = friction; }, *collider);
  r.refuseUnknown("docs/scenes.md");
  return *collider;
}

Friction readFriction(FieldReader& r) {
  if (!r.has("friction")) return {};
  FieldReader f = r.object("friction");
  Friction friction;
  friction.static_coefficient = f.inRange("static", 0.0, 100.0);
  friction.kinetic = f.has("kinetic") ? f.inRange("kinetic", 0.0, 100.0) : friction.static_coefficient;
  if (friction.kinetic > friction.static_coefficient) {
    failField(f.field("kinetic"), "at most friction.static (Coulomb: mu_k <= mu_s)", f.raw("kinetic"));
  }
  f.refuseUnknown("docs/scenes.md");
  return friction;
}

nlohmann::json describeCollider(const Collider& c) {
  nlohmann::json j = std::visit([](const auto& shape) { return shape.describe(); }, c);
  const Friction& friction = colliderFriction(c);
  if (friction.any()) j["friction"] = {{"static", friction.static_coefficient}, {"kinetic", friction.kinetic}};
  return j;
}

}  // namespace mysim
