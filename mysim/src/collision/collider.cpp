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
  r.refuseUnknown("docs/scenes.md");
  return *collider;
}

nlohmann::json describeCollider(const Collider& c) {
  return std::visit([](const auto& shape) { return shape.describe(); }, c);
}

int resolveContacts(const std::vector<Collider>& colliders, const std::vector<char>& pinned,
                    Eigen::Ref<Vector> x, Eigen::Ref<Vector> v) {
  // Each collider's test for exits into the others, built once per call, not once per particle.
  std::vector<Blocked> inside_another;
  for (std::size_t k = 0; k < colliders.size(); ++k) {
    inside_another.push_back([&colliders, k](const Vec3& point) {
      for (std::size_t o = 0; o < colliders.size(); ++o) {
        if (o != k && signedDistance(colliders[o], point) < 0.0) return true;
      }
      return false;
    });
  }
  int contacts = 0;
  for (int p = 0; p < static_cast<int>(pinned.size()); ++p) {
    if (pinned[p]) continue;
    for (std::size_t k = 0; k < colliders.size(); ++k) {
      if (const auto s = contactPoint(colliders[k], x.segment<3>(3 * p), inside_another[k])) {
        applyContact(*s, x.segment<3>(3 * p), v.segment<3>(3 * p));
        ++contacts;
      }
    }
  }
  return contacts;
}

}  // namespace mysim
