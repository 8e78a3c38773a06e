#include "mysim/scene_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "mysim/cloth_material.h"
#include "mysim/json_input.h"
#include "mysim/model_terms.h"
#include "mysim/run_limits.h"

namespace mysim {
namespace {

using nlohmann::json;

void readForces(FieldReader& forces, Scene& scene) {
  scene.gravity = forces.vec3("gravity", Vec3::Zero());
  scene.drag = forces.nonNegative("drag", 0.0);
  if (forces.has("wind")) {
    FieldReader r = forces.object("wind");
    Wind w;
    w.direction = r.unitVec3("direction", Vec3::UnitZ());
    w.strength = r.nonNegative("strength", 0.0);
    w.gust = r.nonNegative("gust", 0.0);
    if (w.gust > 1.0) failField(r.field("gust"), "a number in [0, 1]", r.raw("gust"));
    w.gust_period = r.positive("gust_period", 0.1);
    w.coverage = r.nonNegative("coverage", 1.0);
    if (w.coverage > 1.0) failField(r.field("coverage"), "a number in [0, 1]", r.raw("coverage"));
    w.seed = static_cast<std::uint64_t>(r.integer("seed", 0, 1L << 62, 1));
    r.refuseUnknown("docs/scenes.md");
    scene.wind = w;
  }
  if (forces.has("pin_motion")) {
    FieldReader r = forces.object("pin_motion");
    PinMotion m;
    m.axis = r.unitVec3("axis", Vec3::UnitX());
    m.amplitude = r.nonNegative("amplitude", 0.0);
    m.frequency = r.nonNegative("frequency", 0.0);
    r.refuseUnknown("docs/scenes.md");
    scene.pin_motion = m;
  }
}

void checkWhole(Scene& scene) {
  const SystemSize size = std::visit([](const auto& kind) { return kind.size(); }, scene.system);
  if (auto error = checkRunLimits(size.particles, size.springs,
                                  {scene.dt, scene.duration, scene.sample_interval})) {
    throw FieldError{error->field, error->message};
  }
  std::visit([&](const auto& kind) { kind.checkWhole(scene.integrator); }, scene.system);
}

bool isPlainName(const std::string& name) {
  if (name.empty() || name.size() > 100 || name[0] == '.') return false;
  return std::all_of(name.begin(), name.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '.' || c == '_' || c == '-';
  });
}

// "sphere" (the seed's one sphere, kept as its own field), then "colliders".
void readColliders(FieldReader& top, Scene& scene) {
  if (top.has("sphere")) {
    FieldReader r = top.object("sphere");
    Sphere sphere = Sphere::read(r);
    sphere.friction = readFriction(r);
    scene.colliders.push_back(sphere);
    r.refuseUnknown("docs/scenes.md");
  }
  if (top.has("colliders")) {
    top.objects("colliders",
                [&](FieldReader& r, std::size_t) { scene.colliders.push_back(readCollider(r)); });
  }
}

// The kind whose kType is `type`, made the scene's and read from "system"; false if none is.
template <class... Kinds>
bool readKind(std::variant<Kinds...>& kinds, const std::string& type, FieldReader& system,
              const std::string& source) {
  const auto read = [&]<class Kind>(Kind*) {
    if (type != Kind::kType) return false;
    kinds.template emplace<Kind>().read(system, source);
    return true;
  };
  return (read(static_cast<Kinds*>(nullptr)) || ...);
}

// "\"circle\", \"chain\", \"cloth\" or \"particles\"": every kind's type, for the message.
template <class... Kinds>
std::string kindNames(const std::variant<Kinds...>&) {
  const std::vector<std::string> types{Kinds::kType...};
  std::string names;
  for (std::size_t k = 0; k < types.size(); ++k) {
    names += (k == 0 ? "" : k + 1 == types.size() ? " or " : ", ") + ("\"" + types[k] + "\"");
  }
  return names;
}

// "system": which kind, and its own fields.
void readSystem(FieldReader& top, Scene& scene) {
  FieldReader system = top.object("system");
  const std::string type = system.text("type");
  if (!readKind(scene.system, type, system, scene.source)) {
    failField("system.type", kindNames(scene.system), system.raw("type"));
  }
  if (system.has("self_collision")) {
    FieldReader self = system.object("self_collision");
    scene.self_collision_thickness = self.positive("thickness");
    self.refuseUnknown("docs/scenes.md");
  }
  system.refuseUnknown("docs/scenes.md");
}

// "integrator": method (canonical name), step, duration and each method's settings.
void readIntegrator(FieldReader& top, Scene& scene) {
  FieldReader integ = top.object("integrator");
  IntegratorSettings& is = scene.integrator;
  is.name = integ.text("name", "rk4");
  auto canonical = canonicalIntegratorName(is.name);
  if (!canonical) throw FieldError{"integrator.name", canonical.error()};
  is.name = *canonical;
  scene.dt = integ.positive("dt");
  scene.duration = integ.positive("duration");
  is.abs_tolerance = integ.positive("abs_tolerance", is.abs_tolerance);
  is.rel_tolerance = integ.positive("rel_tolerance", is.rel_tolerance);
  is.cg_tolerance = integ.positive("cg_tolerance", is.cg_tolerance);
  is.cg_max_iterations =
      static_cast<int>(integ.integer("cg_max_iterations", 1, 1'000'000, is.cg_max_iterations));
  if (integ.has("cg_preconditioner")) {
    auto preconditioner = preconditionerByName(integ.text("cg_preconditioner", ""));
    if (!preconditioner) throw FieldError{"integrator.cg_preconditioner", preconditioner.error()};
    is.preconditioner = *preconditioner;
  }
  // Every integrator's own numeric parameters (the catalogue declares them) that the scene
  // gives; the rest take the default of the integrator that runs (IntegratorSettings::value:
  // families differ, e.g. XPBD's one pass a substep against local/global's ten).
  for (const IntegratorInfo& info : integratorCatalog()) {
    for (const IntegratorParameter& p : info.parameters) {
      if (!p.in_values || is.values.count(p.name) || !integ.has(p.name)) continue;
      is.values[p.name] = p.integer
                              ? static_cast<double>(integ.integer(p.name, static_cast<long>(p.low),
                                                                  static_cast<long>(p.high)))
                              : integ.inRange(p.name, p.low, p.high);
    }
  }
  integ.refuseUnknown("docs/scenes.md");
}

// The sections engines declare ("bullet"): each setting checked against its declaration, the
// declared default where the scene is silent.
void readEngineSections(FieldReader& top, const std::vector<EngineSection>& sections,
                        Scene& scene) {
  for (const EngineSection& section : sections) {
    std::map<std::string, double>& values = scene.engine_settings[section.name];
    for (const EngineSetting& setting : section.settings) values[setting.key] = setting.fallback;
    if (!top.has(section.name)) continue;
    FieldReader r = top.object(section.name);
    for (const EngineSetting& setting : section.settings) {
      if (!r.has(setting.key)) continue;
      values[setting.key] =
          setting.integer
              ? static_cast<double>(r.integer(setting.key, static_cast<long>(setting.low),
                                              static_cast<long>(setting.high)))
              : r.inRange(setting.key, setting.low, setting.high);
    }
    r.refuseUnknown("docs/scenes.md");
  }
}

// What a material's constants mean for the rest of the scene: its damping rate is the drag (so
// forces.drag would say it twice), and hinges need a preconditioner that sees them.
void applyMaterialTerms(Scene& scene) {
  const auto drag = std::visit([](const auto& kind) { return kind.materialDrag(); }, scene.system);
  if (drag) {
    if (scene.drag > 0.0) {
      throw FieldError{"forces.drag",
                       "not with system.material.damping_rate: the rate gives the drag"};
    }
    scene.drag = *drag;
  }
  const bool hinges = std::visit([](const auto& kind) { return kind.bendsByHinges(); }, scene.system);
  if (hinges && scene.integrator.preconditioner == CgPreconditioner::Ssor) {
    throw FieldError{"integrator.cg_preconditioner",
                     "\"block-jacobi\", \"jacobi\", \"cholesky\" or \"auto\" with hinge bending (SSOR sweeps "
                     "the springs' matrix alone)"};
  }
}

// The model terms the scene declares it needs (model_terms.h): each one the catalogue knows and
// the scene carries, so an ablation keeps them without a warning.
std::vector<std::string> readNeeds(FieldReader& top, const json& root) {
  std::vector<std::string> needs = top.textList("needs");
  for (std::size_t k = 0; k < needs.size(); ++k) {
    const std::string field = "needs[" + std::to_string(k) + "]";
    const ModelTerm* term = findModelTerm(needs[k]);
    if (!term) {
      throw FieldError{field, "unknown model term '" + clip(needs[k], 40) + "'; expected one of " +
                                  modelTermNames()};
    }
    if (!term->present(root)) {
      throw FieldError{field, "'" + needs[k] + "': the scene does not carry it, so there is "
                                  "nothing to keep (taking it out means: " + term->description + ")"};
    }
  }
  return needs;
}

Scene readScene(const json& root, const std::string& source,
                const std::vector<EngineSection>& sections) {
  Scene scene;
  scene.source = source;  // mesh files are found beside it
  FieldReader top(root, "");
  scene.name = top.text("name", "");
  // The name names output folders: one plain path component, never "..", "/" or a hidden name.
  if (!scene.name.empty() && !isPlainName(scene.name)) {
    failField("name", "letters, digits, '.', '_' or '-' (not starting with '.'; at most 100)",
              top.raw("name"));
  }
  scene.description = top.text("description", "");
  if (top.has("needs")) scene.needed_terms = readNeeds(top, root);

  readSystem(top, scene);

  if (top.has("forces")) {
    FieldReader forces = top.object("forces");
    readForces(forces, scene);
    forces.refuseUnknown("docs/scenes.md");
  }
  readColliders(top, scene);

  readIntegrator(top, scene);
  applyMaterialTerms(scene);

  if (top.has("output")) {
    FieldReader r = top.object("output");
    scene.sample_interval = r.nonNegative("sample_interval", 0.0);
    r.refuseUnknown("docs/scenes.md");
  }
  if (top.has("blowup")) {
    FieldReader r = top.object("blowup");
    scene.limits.max_strain = r.positive("max_strain", scene.limits.max_strain);
    scene.limits.max_energy_ratio = r.positive("max_energy_ratio", scene.limits.max_energy_ratio);
    scene.limits.max_energy_rise = r.positive("max_energy_rise", scene.limits.max_energy_rise);
    scene.limits.max_energy_rise_damped =
        r.positive("max_energy_rise_damped", scene.limits.max_energy_rise_damped);
    r.refuseUnknown("docs/scenes.md");
  }
  readEngineSections(top, sections, scene);
  top.refuseUnknown("docs/scenes.md");
  checkWhole(scene);
  return scene;
}

// The default name: the file name without its extension, made a plain name.
std::string stem(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = name.rfind('.');
  if (dot != std::string::npos) name = name.substr(0, dot);
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
  }
  if (name.empty() || name[0] == '.') name = "scene" + name;
  return name.substr(0, 100);
}

std::expected<Scene, std::string> sceneFrom(const nlohmann::json& root, const std::string& source,
                                            const std::vector<EngineSection>& sections) {
  return readFields<Scene>(source, [&] {
    Scene scene = readScene(root, source, sections);
    scene.source = source;
    if (scene.name.empty()) scene.name = stem(source);
    return scene;
  });
}

}  // namespace

std::expected<Scene, std::string> parseScene(const std::string& text, const std::string& source,
                                             const std::vector<EngineSection>& sections) {
  auto root = parseJson(text, source);
  if (!root) return std::unexpected(root.error());
  return sceneFrom(*root, source, sections);
}

std::expected<Scene, std::string> loadScene(const std::string& path,
                                            const std::vector<EngineSection>& sections) {
  auto root = readJsonFile(path, "scene file");
  if (!root) return std::unexpected(root.error());
  return sceneFrom(*root, path, sections);
}

}  // namespace mysim
