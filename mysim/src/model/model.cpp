#include "mysim/model.h"

namespace mysim {

const char* systemKindName(SystemKind kind) {
  switch (kind) {
    case SystemKind::Circle:
      return "circle";
    case SystemKind::Chain:
      return "chain";
    case SystemKind::Cloth:
      return "cloth";
    case SystemKind::Particles:
      return "particles";
  }
  return "?";
}

std::string springField(const Model& model, int spring, const std::string& parameter) {
  switch (model.kind) {
    case SystemKind::Chain:
      return "system." + parameter;
    case SystemKind::Cloth:
      return std::string("system.") + familyName(model.springs[spring].family) + "." + parameter;
    default:
      return "system.springs[" + std::to_string(spring) + "]." + parameter;
  }
}

Vec3 pinnedPosition(const Model& model, int particle, double t) {
  const Vec3 start = at3(model.start_position, particle);
  return model.pin_motion ? Vec3(start + model.pin_motion->offset(t)) : start;
}

Vec3 pinnedVelocity(const Model& model, double t) {
  return model.pin_motion ? model.pin_motion->velocity(t) : Vec3::Zero();
}

void scaleStiffness(Model& model, double scale) {
  for (Spring& s : model.springs.edit()) s.stiffness *= scale;
  for (Hinge& h : model.hinges) h.stiffness *= scale;
  if (model.material) {  // the material the scaled model now is
    ClothMaterial& m = model.material->material;
    m.stretch_stiffness *= scale;
    m.shear_stiffness *= scale;
    m.bending_rigidity *= scale;
    m.flex_stiffness *= scale;
  }
}

}  // namespace mysim
