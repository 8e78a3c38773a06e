#include "mysim/chain_scene.h"

#include "read_pins.h"

namespace mysim {

// A chain from its material: "length" and "resolution" (links) give the links, "material"
// {linear_density kg/m, axial_stiffness EA in N, damping_rate 1/s} their constants: rest length /
// resolution, stiffness EA / rest, a link's mass on every node but the two ends, which carry half
// (docs/materials.md). "span" (default: length) lays it out taut or slack along "direction";
// pins as any chain, or "ends".
void ChainScene::readMaterial(FieldReader& system) {
  for (const char* derived : {"particles", "rest_length", "spacing", "particle_mass", "stiffness",
                              "damping"}) {
    if (system.has(derived)) {
      throw FieldError{system.field(derived),
                       "not with system.material: the material, length and resolution give it "
                       "(docs/materials.md)"};
    }
  }
  FieldReader material = system.object("material");
  const double density = material.positive("linear_density");
  const double axial = material.positive("axial_stiffness");
  const double rate = material.nonNegative("damping_rate", 0.0);
  material.refuseUnknown("docs/materials.md");
  const double length = system.positive("length");
  const int links = static_cast<int>(system.integer("resolution", 1, 10'000'000));
  ChainShape& c = shape;
  c.particles = links + 1;
  c.rest_length = length / links;
  c.spacing = system.positive("span", length) / links;
  c.particle_mass = density * c.rest_length;
  c.stiffness = axial / c.rest_length;
  c.origin = system.vec3("origin", Vec3::Zero());
  c.direction = system.unitVec3("direction", Vec3::UnitX());
  end_mass = 0.5 * c.particle_mass;
  if (rate * c.particle_mass > 0.0) damping_drag = rate * c.particle_mass;
  start.velocity = system.vec3("velocity", Vec3::Zero());
  if (system.has("pins") && system.raw("pins") == "ends") {
    start.pins = {0, links};
  } else {
    start.pins = readPins(system, c.particles, {0}, 0, 0);
  }
}

void ChainScene::read(FieldReader& system, const std::string&) {
  if (system.has("material")) {
    readMaterial(system);
    return;
  }
  ChainShape& c = shape;
  c.particles = static_cast<int>(system.integer("particles", 2, 10'000'000));
  c.rest_length = system.positive("rest_length");
  c.spacing = system.positive("spacing", c.rest_length);
  c.particle_mass = system.positive("particle_mass");
  c.stiffness = system.positive("stiffness");
  c.damping = system.nonNegative("damping", 0.0);
  c.origin = system.vec3("origin", Vec3::Zero());
  c.direction = system.unitVec3("direction", Vec3::UnitX());
  start.velocity = system.vec3("velocity", Vec3::Zero());
  start.pins = readPins(system, c.particles, {0}, 0, 0);
}

void ChainScene::build(Model& model) const {
  model.kind = kType;
  model.naming = FieldNaming::Shared;
  buildChain(shape, model);
  if (end_mass > 0.0) {  // a material chain: its ends carry half a link
    model.mass[0] = model.mass[model.particleCount() - 1] = end_mass;
  }
  start.apply(model);
}

}  // namespace mysim
