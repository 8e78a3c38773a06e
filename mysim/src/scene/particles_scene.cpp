#include "mysim/particles_scene.h"

namespace mysim {

using nlohmann::json;

namespace {

Spring readSpring(const json& item, const std::string& field,
                  const std::vector<ExplicitParticle>& particles) {
  FieldReader r(item, field);
  const int n = static_cast<int>(particles.size());
  Spring s;
  s.i = static_cast<int>(r.integer("i", 0, n - 1));
  s.j = static_cast<int>(r.integer("j", 0, n - 1));
  if (s.i == s.j) failField(r.field("j"), "a particle other than i", item["j"]);
  const double distance = (particles[s.j].position - particles[s.i].position).norm();
  s.rest_length = r.positive("rest_length", distance);
  if (!(s.rest_length > 0.0)) {
    throw FieldError{r.field("rest_length"),
                     "expected a number > 0; the default (start distance) is 0 here"};
  }
  s.stiffness = r.positive("stiffness");
  s.damping = r.nonNegative("damping", 0.0);
  s.family = SpringFamily::Custom;
  r.refuseUnknown("docs/scenes.md");
  return s;
}

}  // namespace

void ParticlesScene::read(FieldReader& system, const std::string&) {
  const json& list = system.raw("particles");
  if (!list.is_array() || list.empty())
    failField(system.field("particles"), "a non-empty list", list);
  for (std::size_t k = 0; k < list.size(); ++k) {
    FieldReader r(list[k], system.field("particles") + "[" + std::to_string(k) + "]");
    ExplicitParticle p;
    p.position = r.vec3("position");
    p.velocity = r.vec3("velocity", Vec3::Zero());
    p.mass = r.positive("mass");
    p.pinned = r.boolean("pinned", false);
    r.refuseUnknown("docs/scenes.md");
    particles.push_back(p);
  }
  if (!system.has("springs")) return;
  const json& list_of_springs = system.raw("springs");
  if (!list_of_springs.is_array()) failField(system.field("springs"), "a list", list_of_springs);
  for (std::size_t k = 0; k < list_of_springs.size(); ++k) {
    springs.push_back(readSpring(list_of_springs[k],
                                 system.field("springs") + "[" + std::to_string(k) + "]",
                                 particles));
  }
}

void ParticlesScene::build(Model& model) const {
  model.kind = kType;
  model.naming = FieldNaming::PerItem;
  const int n = static_cast<int>(particles.size());
  model.mass.resize(n);
  model.pinned.assign(n, 0);
  model.start_position.resize(3 * n);
  model.start_velocity.resize(3 * n);
  for (int p = 0; p < n; ++p) {
    const ExplicitParticle& particle = particles[p];
    model.mass[p] = particle.mass;
    model.pinned[p] = particle.pinned;
    at3(model.start_position, p) = particle.position;
    at3(model.start_velocity, p) = particle.velocity;
  }
  model.springs = springs;
}

void ParticlesScene::checkWhole(const IntegratorSettings&) const {
  for (const ExplicitParticle& p : particles) {
    if (!p.pinned) return;
  }
  throw FieldError{"system.particles", "every particle is pinned: nothing would move"};
}

}  // namespace mysim
