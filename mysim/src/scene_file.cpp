#include "mysim/scene_file.h"

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace mysim {
namespace {

using nlohmann::json;

// Thrown only inside this file, turned into the error value at parseScene's edge.
struct FieldError {
  std::string field;
  std::string message;
};

std::string describe(const json& value) {
  std::string text = value.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return std::string(value.type_name()) + " " + text;
}

[[noreturn]] void fail(const std::string& field, const std::string& expected, const json& got) {
  throw FieldError{field, "expected " + expected + ", got " + describe(got)};
}

// Reads the fields of one JSON object, checking each, and refuses keys it does not know (a typo
// like "stifness" must not silently fall back to a default).
class ObjectReader {
 public:
  ObjectReader(const json& object, std::string path) : object_(object), path_(std::move(path)) {
    if (!object_.is_object()) fail(path_.empty() ? "(top level)" : path_, "an object", object_);
  }

  std::string field(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
  }
  bool has(const std::string& key) {
    seen_.insert(key);
    return object_.contains(key);
  }
  const json& raw(const std::string& key) {
    if (!has(key)) throw FieldError{field(key), "missing (required)"};
    return object_.at(key);
  }

  double number(const std::string& key) {
    const json& v = raw(key);
    if (!v.is_number()) fail(field(key), "a number", v);
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(field(key), "a finite number", v);
    return d;
  }
  double number(const std::string& key, double fallback) {
    return has(key) ? number(key) : fallback;
  }
  double positive(const std::string& key) {
    const double d = number(key);
    if (!(d > 0.0)) fail(field(key), "a number > 0", raw(key));
    return d;
  }
  double positive(const std::string& key, double fallback) {
    return has(key) ? positive(key) : fallback;
  }
  double nonNegative(const std::string& key, double fallback) {
    if (!has(key)) return fallback;
    const double d = number(key);
    if (d < 0.0) fail(field(key), "a number >= 0", raw(key));
    return d;
  }
  double inRange(const std::string& key, double low, double high) {
    const double d = number(key);
    if (d < low || d > high) {
      fail(field(key), "a number in [" + std::to_string(low) + ", " + std::to_string(high) + "]",
           raw(key));
    }
    return d;
  }
  long integer(const std::string& key, long low, long high) {
    const json& v = raw(key);
    if (!v.is_number_integer() || v.get<long>() < low || v.get<long>() > high) {
      fail(field(key), "an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]",
           v);
    }
    return v.get<long>();
  }
  long integer(const std::string& key, long low, long high, long fallback) {
    return has(key) ? integer(key, low, high) : fallback;
  }
  bool boolean(const std::string& key, bool fallback) {
    if (!has(key)) return fallback;
    const json& v = raw(key);
    if (!v.is_boolean()) fail(field(key), "true or false", v);
    return v.get<bool>();
  }
  std::string text(const std::string& key) {
    const json& v = raw(key);
    if (!v.is_string()) fail(field(key), "a string", v);
    return v.get<std::string>();
  }
  std::string text(const std::string& key, const std::string& fallback) {
    return has(key) ? text(key) : fallback;
  }
  Vec3 vec3(const std::string& key) {
    const json& v = raw(key);
    if (!v.is_array() || v.size() != 3) fail(field(key), "an array of 3 numbers", v);
    Vec3 out;
    for (int k = 0; k < 3; ++k) {
      if (!v[k].is_number() || !std::isfinite(v[k].get<double>())) {
        fail(field(key) + "[" + std::to_string(k) + "]", "a finite number", v[k]);
      }
      out[k] = v[k].get<double>();
    }
    return out;
  }
  Vec3 vec3(const std::string& key, const Vec3& fallback) {
    return has(key) ? vec3(key) : fallback;
  }
  Vec3 unitVec3(const std::string& key, const Vec3& fallback) {
    if (!has(key)) return fallback;
    const Vec3 v = vec3(key);
    if (v.norm() < 1e-12) fail(field(key), "a non-zero direction", raw(key));
    return v.normalized();
  }
  ObjectReader object(const std::string& key) { return ObjectReader(raw(key), field(key)); }

  // Call last: any key never asked for is an error.
  void refuseUnknown() const {
    for (auto it = object_.begin(); it != object_.end(); ++it) {
      if (!seen_.count(it.key())) {
        throw FieldError{field(it.key()), "unknown field (see docs/scenes.md for the schema)"};
      }
    }
  }

 private:
  const json& object_;
  std::string path_;
  std::set<std::string> seen_{"$comment"};
};

std::optional<SpringParameters> readFamily(ObjectReader& system, const std::string& key) {
  if (!system.has(key)) return std::nullopt;
  ObjectReader r = system.object(key);
  SpringParameters p{r.positive("stiffness"), r.nonNegative("damping", 0.0)};
  r.refuseUnknown();
  return p;
}

std::vector<int> readPins(ObjectReader& system, int count, const std::vector<int>& fallback,
                          int rows, int cols) {
  if (!system.has("pins")) return fallback;
  const json& v = system.raw("pins");
  const std::string field = system.field("pins");
  if (v.is_string()) {
    const std::string preset = v.get<std::string>();
    if (rows > 0 && preset == "top_corners") return {0, cols - 1};
    if (rows > 0 && preset == "corners") return {0, cols - 1, (rows - 1) * cols, rows * cols - 1};
    if (preset == "none") return {};
    fail(field,
         rows > 0 ? "\"top_corners\", \"corners\", \"none\" or a list of particle indices"
                  : "\"none\" or a list of particle indices",
         v);
  }
  if (!v.is_array()) fail(field, "a list of particle indices", v);
  std::vector<int> pins;
  std::set<int> unique;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const std::string item = field + "[" + std::to_string(k) + "]";
    if (!v[k].is_number_integer()) fail(item, "a particle index", v[k]);
    const long p = v[k].get<long>();
    if (p < 0 || p >= count) {
      fail(item, "a particle index in [0, " + std::to_string(count - 1) + "]", v[k]);
    }
    if (!unique.insert(static_cast<int>(p)).second) fail(item, "each particle pinned once", v[k]);
    pins.push_back(static_cast<int>(p));
  }
  return pins;
}

void readCircle(ObjectReader& system, Scene& scene) {
  if (system.has("start")) {
    const json& v = system.raw("start");
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) {
      fail(system.field("start"), "an array of 2 numbers", v);
    }
    scene.circle_start = {v[0].get<double>(), v[1].get<double>()};
    if (!scene.circle_start.allFinite() || scene.circle_start.norm() == 0.0) {
      fail(system.field("start"), "a finite, non-zero point", v);
    }
  }
}

void readChain(ObjectReader& system, Scene& scene) {
  ChainShape& c = scene.chain;
  c.particles = static_cast<int>(system.integer("particles", 2, 10'000'000));
  c.rest_length = system.positive("rest_length");
  c.particle_mass = system.positive("particle_mass");
  c.stiffness = system.positive("stiffness");
  c.damping = system.nonNegative("damping", 0.0);
  c.origin = system.vec3("origin", Vec3::Zero());
  c.direction = system.unitVec3("direction", Vec3::UnitX());
  scene.start_velocity = system.vec3("velocity", Vec3::Zero());
  scene.pins = readPins(system, c.particles, {0}, 0, 0);
}

void readCloth(ObjectReader& system, Scene& scene) {
  ClothShape& c = scene.cloth;
  c.rows = static_cast<int>(system.integer("rows", 2, 100'000));
  c.cols = static_cast<int>(system.integer("cols", 2, 100'000));
  c.width = system.positive("width");
  c.height = system.positive("height");
  c.particle_mass = system.positive("particle_mass");
  const std::string orientation = system.text("orientation", "horizontal");
  if (orientation != "horizontal" && orientation != "hanging") {
    fail(system.field("orientation"), "\"horizontal\" or \"hanging\"", system.raw("orientation"));
  }
  c.hanging = orientation == "hanging";
  c.origin = system.vec3("origin", Vec3::Zero());
  c.structural = readFamily(system, "structural");
  c.shear = readFamily(system, "shear");
  c.flex = readFamily(system, "flex");
  scene.start_velocity = system.vec3("velocity", Vec3::Zero());
  const long count = static_cast<long>(c.rows) * c.cols;
  scene.pins = readPins(system, static_cast<int>(std::min(count, 2'000'000'000L)), {0, c.cols - 1},
                        c.rows, c.cols);
}

void readParticles(ObjectReader& system, Scene& scene) {
  const json& list = system.raw("particles");
  if (!list.is_array() || list.empty()) fail(system.field("particles"), "a non-empty list", list);
  for (std::size_t k = 0; k < list.size(); ++k) {
    ObjectReader r(list[k], system.field("particles") + "[" + std::to_string(k) + "]");
    ExplicitParticle p;
    p.position = r.vec3("position");
    p.velocity = r.vec3("velocity", Vec3::Zero());
    p.mass = r.positive("mass");
    p.pinned = r.boolean("pinned", false);
    r.refuseUnknown();
    scene.particles.push_back(p);
  }
  const int n = static_cast<int>(scene.particles.size());
  if (!system.has("springs")) return;
  const json& springs = system.raw("springs");
  if (!springs.is_array()) fail(system.field("springs"), "a list", springs);
  for (std::size_t k = 0; k < springs.size(); ++k) {
    ObjectReader r(springs[k], system.field("springs") + "[" + std::to_string(k) + "]");
    Spring s;
    s.i = static_cast<int>(r.integer("i", 0, n - 1));
    s.j = static_cast<int>(r.integer("j", 0, n - 1));
    if (s.i == s.j) fail(r.field("j"), "a particle other than i", springs[k]["j"]);
    const double distance = (scene.particles[s.j].position - scene.particles[s.i].position).norm();
    s.rest_length = r.positive("rest_length", distance);
    if (!(s.rest_length > 0.0)) {
      throw FieldError{r.field("rest_length"),
                       "expected a number > 0; the default (start distance) is 0 here"};
    }
    s.stiffness = r.positive("stiffness");
    s.damping = r.nonNegative("damping", 0.0);
    s.family = SpringFamily::Custom;
    r.refuseUnknown();
    scene.springs.push_back(s);
  }
}

void readForces(ObjectReader& forces, Scene& scene) {
  scene.gravity = forces.vec3("gravity", Vec3::Zero());
  scene.drag = forces.nonNegative("drag", 0.0);
  if (forces.has("wind")) {
    ObjectReader r = forces.object("wind");
    Wind w;
    w.direction = r.unitVec3("direction", Vec3::UnitZ());
    w.strength = r.nonNegative("strength", 0.0);
    w.gust = r.nonNegative("gust", 0.0);
    if (w.gust > 1.0) fail(r.field("gust"), "a number in [0, 1]", r.raw("gust"));
    w.gust_period = r.positive("gust_period", 0.1);
    w.coverage = r.nonNegative("coverage", 1.0);
    if (w.coverage > 1.0) fail(r.field("coverage"), "a number in [0, 1]", r.raw("coverage"));
    w.seed = static_cast<std::uint64_t>(r.integer("seed", 0, 1L << 62, 1));
    r.refuseUnknown();
    scene.wind = w;
  }
  if (forces.has("pin_motion")) {
    ObjectReader r = forces.object("pin_motion");
    PinMotion m;
    m.axis = r.unitVec3("axis", Vec3::UnitX());
    m.amplitude = r.nonNegative("amplitude", 0.0);
    m.frequency = r.nonNegative("frequency", 0.0);
    r.refuseUnknown();
    scene.pin_motion = m;
  }
}

// Rough bytes per particle of a run: state and integrator buffers (~30 vectors of 6 doubles),
// up to 12 springs, and the sampled trajectory (6 doubles a frame).
double bytesPerParticle(const Scene& scene) {
  const double frames = scene.sample_interval > 0.0
                            ? std::min(1e6, scene.duration / scene.sample_interval) + 2
                            : 202.0;
  return 30 * 48 + 12 * 40 + frames * 48;
}

double physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * page : 8e9;
}

void checkWhole(Scene& scene) {
  int count = 0;
  std::vector<char> pinned;
  if (scene.kind == SystemKind::Chain) count = scene.chain.particles;
  if (scene.kind == SystemKind::Cloth) {
    const double n = static_cast<double>(scene.cloth.rows) * scene.cloth.cols;
    const double need = n * bytesPerParticle(scene), have = physicalMemoryBytes();
    if (need > 0.5 * have) {
      std::ostringstream m;
      m << "a " << scene.cloth.rows << " x " << scene.cloth.cols << " grid needs about "
        << need / (1 << 30) << " GiB, more than half of this machine's " << have / (1 << 30)
        << " GiB";
      throw FieldError{"system.rows", m.str()};
    }
    count = static_cast<int>(n);
  }
  if (scene.kind == SystemKind::Chain || scene.kind == SystemKind::Cloth) {
    if (static_cast<int>(scene.pins.size()) >= count) {
      throw FieldError{"system.pins", "every particle is pinned: nothing would move"};
    }
  }
  if (scene.kind == SystemKind::Particles) {
    bool any_free = false;
    for (const ExplicitParticle& p : scene.particles) any_free |= !p.pinned;
    if (!any_free)
      throw FieldError{"system.particles", "every particle is pinned: nothing would move"};
  }
  if (scene.kind == SystemKind::Circle && scene.integrator.name != "") {
    for (const IntegratorInfo& info : integratorCatalog()) {
      if (info.name == scene.integrator.name && info.needs_particles) {
        throw FieldError{"integrator.name",
                         "'" + info.name +
                             "' needs a particle system; the circle is a "
                             "first-order ODE (use euler, trapezoidal, rk4, dopri5)"};
      }
    }
  }
  if (scene.dt > scene.duration) {
    throw FieldError{"integrator.dt", "a step no longer than integrator.duration"};
  }
}

Scene readScene(const json& root, const std::vector<EngineSection>& sections) {
  Scene scene;
  ObjectReader top(root, "");
  scene.name = top.text("name", "");
  scene.description = top.text("description", "");

  ObjectReader system = top.object("system");
  const std::string type = system.text("type");
  if (type == "circle") {
    scene.kind = SystemKind::Circle;
    readCircle(system, scene);
  } else if (type == "chain") {
    scene.kind = SystemKind::Chain;
    readChain(system, scene);
  } else if (type == "cloth") {
    scene.kind = SystemKind::Cloth;
    readCloth(system, scene);
  } else if (type == "particles") {
    scene.kind = SystemKind::Particles;
    readParticles(system, scene);
  } else {
    fail("system.type", "\"circle\", \"chain\", \"cloth\" or \"particles\"", system.raw("type"));
  }
  system.refuseUnknown();

  if (top.has("forces")) {
    ObjectReader forces = top.object("forces");
    readForces(forces, scene);
    forces.refuseUnknown();
  }
  if (top.has("sphere")) {
    ObjectReader r = top.object("sphere");
    Sphere s;
    s.center = r.vec3("center");
    s.radius = r.positive("radius");
    s.margin = r.nonNegative("margin", 1e-3 * s.radius);
    r.refuseUnknown();
    scene.sphere = s;
  }

  ObjectReader integ = top.object("integrator");
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
  integ.refuseUnknown();

  if (top.has("output")) {
    ObjectReader r = top.object("output");
    scene.sample_interval = r.nonNegative("sample_interval", 0.0);
    r.refuseUnknown();
  }
  if (top.has("blowup")) {
    ObjectReader r = top.object("blowup");
    scene.limits.max_strain = r.positive("max_strain", scene.limits.max_strain);
    scene.limits.max_energy_ratio = r.positive("max_energy_ratio", scene.limits.max_energy_ratio);
    r.refuseUnknown();
  }
  for (const EngineSection& section : sections) {
    std::map<std::string, double>& values = scene.engine_settings[section.name];
    for (const EngineSetting& setting : section.settings) values[setting.key] = setting.fallback;
    if (!top.has(section.name)) continue;
    ObjectReader r = top.object(section.name);
    for (const EngineSetting& setting : section.settings) {
      if (!r.has(setting.key)) continue;
      values[setting.key] =
          setting.integer
              ? static_cast<double>(r.integer(setting.key, static_cast<long>(setting.low),
                                              static_cast<long>(setting.high)))
              : r.inRange(setting.key, setting.low, setting.high);
    }
    r.refuseUnknown();
  }
  top.refuseUnknown();
  checkWhole(scene);
  return scene;
}

std::string stem(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = name.rfind('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

}  // namespace

std::expected<Scene, std::string> parseScene(const std::string& text, const std::string& source,
                                             const std::vector<EngineSection>& sections) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    return std::unexpected(source + ": not valid JSON: " + e.what());
  }
  try {
    Scene scene = readScene(root, sections);
    scene.source = source;
    if (scene.name.empty()) scene.name = stem(source);
    return scene;
  } catch (const FieldError& e) {
    return std::unexpected(source + ": " + e.field + ": " + e.message);
  }
}

std::expected<Scene, std::string> loadScene(const std::string& path,
                                            const std::vector<EngineSection>& sections) {
  std::ifstream in(path);
  if (!in) return std::unexpected(path + ": cannot open the scene file");
  std::stringstream text;
  text << in.rdbuf();
  return parseScene(text.str(), path, sections);
}

}  // namespace mysim
