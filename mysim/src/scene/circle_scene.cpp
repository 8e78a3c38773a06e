#include "mysim/circle_scene.h"

namespace mysim {

void CircleScene::read(FieldReader& system, const std::string&) {
  if (!system.has("start")) return;
  const nlohmann::json& v = system.raw("start");
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) {
    failField(system.field("start"), "an array of 2 numbers", v);
  }
  start = {v[0].get<double>(), v[1].get<double>()};
  if (!start.allFinite() || start.norm() == 0.0) {
    failField(system.field("start"), "a finite, non-zero point", v);
  }
}

void CircleScene::build(Model& model) const {
  model.kind = kType;
  model.circle_start = start;
}

void CircleScene::checkWhole(const IntegratorSettings& integrator) const {
  if (auto refusal = circleRefusal(integrator.name)) {
    throw FieldError{"integrator.name", *refusal};
  }
}

}  // namespace mysim
