#include "mysim/model.h"

namespace mysim {

std::string springField(const Model& model, int spring, const std::string& parameter) {
  switch (model.naming) {
    case FieldNaming::Shared:
      return "system." + parameter;
    case FieldNaming::PerFamily:
      return std::string("system.") + familyName(model.springs[spring].family) + "." + parameter;
    case FieldNaming::PerItem:
      break;
  }
  return "system.springs[" + std::to_string(spring) + "]." + parameter;
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
