// Each kind of "system" a scene file can hold, read into the scene (scene_file.cpp reads the
// file's other sections and calls these by the system's "type").
#include "scene_system_readers.h"

#include <algorithm>
#include <cmath>

#include "mysim/cloth_material.h"
#include "model/mesh_cloth.h"

namespace mysim {

using nlohmann::json;

namespace {

std::optional<SpringParameters> readFamily(FieldReader& system, const std::string& key) {
  if (!system.has(key)) return std::nullopt;
  FieldReader r = system.object(key);
  SpringParameters p{r.positive("stiffness"), r.nonNegative("damping", 0.0)};
  r.refuseUnknown("docs/scenes.md");
  return p;
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

}  // namespace

void readCircle(FieldReader& system, Scene& scene) {
  if (system.has("start")) {
    const json& v = system.raw("start");
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) {
      failField(system.field("start"), "an array of 2 numbers", v);
    }
    scene.circle_start = {v[0].get<double>(), v[1].get<double>()};
    if (!scene.circle_start.allFinite() || scene.circle_start.norm() == 0.0) {
      failField(system.field("start"), "a finite, non-zero point", v);
    }
  }
}

namespace {

// A chain (a rope, a cable) from its material: "length" and "resolution" (links) give the links,
// "material" {linear_density kg/m, axial_stiffness EA in N, damping_rate 1/s} their constants:
// rest length / resolution, stiffness EA / rest, a link's mass on every node but the two ends,
// which carry half (docs/materials.md). "span" (default: length) lays it out taut or slack
// along "direction"; pins as any chain, or "ends".
void readMaterialChain(FieldReader& system, Scene& scene) {
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
  ChainShape& c = scene.chain;
  c.particles = links + 1;
  c.rest_length = length / links;
  c.spacing = system.positive("span", length) / links;
  c.particle_mass = density * c.rest_length;
  c.stiffness = axial / c.rest_length;
  c.origin = system.vec3("origin", Vec3::Zero());
  c.direction = system.unitVec3("direction", Vec3::UnitX());
  scene.chain_end_mass = 0.5 * c.particle_mass;
  scene.material_drag = rate * c.particle_mass;
  scene.start_velocity = system.vec3("velocity", Vec3::Zero());
  if (system.has("pins") && system.raw("pins") == "ends") {
    scene.pins = {0, links};
  } else {
    scene.pins = readPins(system, c.particles, {0}, 0, 0);
  }
}

}  // namespace

void readChain(FieldReader& system, Scene& scene) {
  if (system.has("material")) {
    readMaterialChain(system, scene);
    return;
  }
  ChainShape& c = scene.chain;
  c.particles = static_cast<int>(system.integer("particles", 2, 10'000'000));
  c.rest_length = system.positive("rest_length");
  c.spacing = system.positive("spacing", c.rest_length);
  c.particle_mass = system.positive("particle_mass");
  c.stiffness = system.positive("stiffness");
  c.damping = system.nonNegative("damping", 0.0);
  c.origin = system.vec3("origin", Vec3::Zero());
  c.direction = system.unitVec3("direction", Vec3::UnitX());
  scene.start_velocity = system.vec3("velocity", Vec3::Zero());
  scene.pins = readPins(system, c.particles, {0}, 0, 0);
}

namespace {

// "orientation": whether a grid cloth starts hanging (rows along -y) or horizontal (along -z).
bool readHanging(FieldReader& system) {
  const std::string orientation = system.text("orientation", "horizontal");
  if (orientation != "horizontal" && orientation != "hanging") {
    failField(system.field("orientation"), "\"horizontal\" or \"hanging\"",
              system.raw("orientation"));
  }
  return orientation == "hanging";
}

// "material": what the cloth is made of (cloth_material.h); its springs, hinges and masses
// follow from it at the scene's resolution.
ClothMaterial readClothMaterial(FieldReader& r, bool mesh) {
  ClothMaterial m;
  m.density = r.positive("density");
  m.stretch_stiffness = r.positive("stretch_stiffness");
  if (!mesh) {
    m.shear_stiffness = r.positive("shear_stiffness");
  } else if (r.has("shear_stiffness")) {
    throw FieldError{r.field("shear_stiffness"),
                     "not for a mesh cloth: a triangle mesh of springs has Poisson's ratio 1/3, so "
                     "its shear stiffness is 3/8 of stretch_stiffness (docs/materials.md)"};
  } else {
    m.shear_stiffness = 0.375 * m.stretch_stiffness;
  }
  m.damping_rate = r.nonNegative("damping_rate", 0.0);
  FieldReader bending = r.object("bending");
  const std::string model = bending.text("model");
  if (model == "hinge") {
    m.bending = BendingModel::Hinge;
    m.bending_rigidity = bending.positive("rigidity");
  } else if (model == "flex") {
    m.bending = BendingModel::Flex;
    m.flex_stiffness = bending.positive("stiffness");
  } else if (model == "none") {
    m.bending = BendingModel::None;
  } else {
    failField(bending.field("model"), "\"hinge\", \"flex\" or \"none\"", bending.raw("model"));
  }
  bending.refuseUnknown("docs/materials.md");
  r.refuseUnknown("docs/materials.md");
  return m;
}

// system.mesh: {"obj": FILE} (beside the scene file unless absolute) or {"shape": "disc", "radius"}
// with system.resolution rings.
TriangleMesh readClothTriangles(FieldReader& system, const std::string& source) {
  FieldReader mesh = system.object("mesh");
  TriangleMesh triangles;
  if (mesh.has("obj")) {
    if (system.has("resolution")) {
      throw FieldError{system.field("resolution"), "not with mesh.obj: the file is its resolution"};
    }
    std::string file = mesh.text("obj");
    if (!file.empty() && file[0] != '/') {
      const std::size_t slash = source.find_last_of('/');
      if (slash != std::string::npos) file = source.substr(0, slash + 1) + file;
    }
    auto read = readObjMesh(file);
    if (!read) throw FieldError{mesh.field("obj"), read.error()};
    triangles = std::move(*read);
  } else {
    const std::string shape = mesh.text("shape");
    if (shape != "disc") failField(mesh.field("shape"), "\"disc\" (or give \"obj\")", mesh.raw("shape"));
    const double radius = mesh.positive("radius");
    triangles = discMesh(radius, static_cast<int>(system.integer("resolution", 1, 500)));
  }
  mesh.refuseUnknown("docs/materials.md");
  return triangles;
}

// A cloth from a triangle mesh and its material (mesh_cloth.h): "mesh" is {"shape": "disc",
// "radius"} (resolution: its rings) or {"obj": FILE} (beside the scene file unless absolute; its
// own resolution); "pins" may also be {"within": R}, every vertex within R of the origin.
void readMeshCloth(FieldReader& system, Scene& scene) {
  for (const char* grid_only : {"rows", "cols", "width", "height", "particle_mass", "structural",
                                "shear", "flex", "orientation"}) {
    if (system.has(grid_only)) {
      throw FieldError{system.field(grid_only), "not with system.mesh: a grid cloth's field"};
    }
  }
  if (!system.has("material")) {
    throw FieldError{system.field("material"),
                     "expected the material a mesh cloth is made of (docs/materials.md)"};
  }
  FieldReader material = system.object("material");
  scene.cloth_material = readClothMaterial(material, true);
  if (scene.cloth_material->bending == BendingModel::Flex) {
    throw FieldError{system.field("material") + ".bending.model",
                     "\"hinge\" for a mesh cloth (flex springs join grid nodes two apart)"};
  }
  scene.cloth_mesh = readClothTriangles(system, scene.source);
  const Vec3 origin = system.vec3("origin", Vec3::Zero());
  scene.cloth.origin = origin;
  // Built once here, so a mesh that cannot be a cloth is refused with the scene.
  Model trial;
  auto built = buildMeshCloth(*scene.cloth_mesh, *scene.cloth_material, origin, trial);
  if (!built) throw FieldError{system.field("mesh"), built.error()};
  scene.mesh_drag = *built;
  const int n = trial.particleCount();
  scene.pins.clear();
  if (system.has("pins") && system.raw("pins").is_object()) {
    FieldReader pins = system.object("pins");
    const double within = pins.positive("within");
    pins.refuseUnknown("docs/materials.md");
    for (int p = 0; p < n; ++p) {
      if ((at3(trial.start_position, p) - origin).norm() <= within * (1.0 + 1e-12)) {
        scene.pins.push_back(p);
      }
    }
    if (scene.pins.empty()) {
      throw FieldError{system.field("pins") + ".within", "a radius that holds at least one vertex"};
    }
  } else {
    scene.pins = readPins(system, n, {}, 0, 0);
  }
  scene.start_velocity = system.vec3("velocity", Vec3::Zero());
}

// A cloth from its material: the grid from "resolution" (cells across the width), the
// constants from "material"; "pins": "left_clamp" holds the left edge in a clamp one cell deep.
void readMaterialCloth(FieldReader& system, Scene& scene) {
  for (const char* derived : {"rows", "cols", "particle_mass", "structural", "shear", "flex"}) {
    if (system.has(derived)) {
      throw FieldError{system.field(derived),
                       "not with system.material: the material and system.resolution give it "
                       "(docs/materials.md)"};
    }
  }
  ClothShape& c = scene.cloth;
  FieldReader material = system.object("material");
  scene.cloth_material = readClothMaterial(material, false);
  const int resolution = static_cast<int>(system.integer("resolution", 1, 10'000));
  c.width = system.positive("width");
  c.height = system.positive("height");
  const bool clamped = system.has("pins") && system.raw("pins") == "left_clamp";
  const MaterialGrid grid = materialGrid(c.width, c.height, resolution, clamped);
  scene.material_grid = grid;
  scene.material_clamped = clamped;
  if (!latticeSprings(scene.cloth_material->stretch_stiffness,
                      scene.cloth_material->shear_stiffness, grid.dx, grid.dy)) {
    throw FieldError{system.field("material") + ".shear_stiffness",
                     "at most what the grid's cells allow: a structural spring would need "
                     "negative stiffness (cells " + std::to_string(grid.dx) + " x " +
                         std::to_string(grid.dy) + " m; docs/materials.md)"};
  }
  c.rows = grid.rows;
  c.cols = grid.cols;
  c.particle_mass = 1.0;  // replaced by the lumped masses
  const SpringParameters placeholder{1.0, 0.0};  // replaced by the lattice's constants
  c.structural = c.shear = placeholder;
  if (scene.cloth_material->bending == BendingModel::Flex) c.flex = placeholder;
  c.hanging = readHanging(system);
  c.origin = system.vec3("origin", Vec3::Zero());
  if (clamped) {
    // The clamp's two columns straddle its edge at origin.x: the overhang is `width` from it at
    // every resolution (materialGrid).
    c.origin.x() -= 0.5 * grid.dx;
    c.width = (grid.cols - 1) * grid.dx;
    scene.pins.clear();
    for (int r = 0; r < c.rows; ++r) {
      scene.pins.push_back(r * c.cols);
      scene.pins.push_back(r * c.cols + 1);
    }
  } else {
    scene.pins = readPins(system, c.rows * c.cols, {0, c.cols - 1}, c.rows, c.cols);
  }
  scene.start_velocity = system.vec3("velocity", Vec3::Zero());
}

}  // namespace

void readCloth(FieldReader& system, Scene& scene) {
  if (system.has("mesh")) {
    readMeshCloth(system, scene);
    return;
  }
  if (system.has("material")) {
    readMaterialCloth(system, scene);
    return;
  }
  ClothShape& c = scene.cloth;
  c.rows = static_cast<int>(system.integer("rows", 2, 100'000));
  c.cols = static_cast<int>(system.integer("cols", 2, 100'000));
  c.width = system.positive("width");
  c.height = system.positive("height");
  c.particle_mass = system.positive("particle_mass");
  c.hanging = readHanging(system);
  c.origin = system.vec3("origin", Vec3::Zero());
  c.structural = readFamily(system, "structural");
  c.shear = readFamily(system, "shear");
  c.flex = readFamily(system, "flex");
  scene.start_velocity = system.vec3("velocity", Vec3::Zero());
  const long count = static_cast<long>(c.rows) * c.cols;
  scene.pins = readPins(system, static_cast<int>(std::min(count, 2'000'000'000L)), {0, c.cols - 1},
                        c.rows, c.cols);
}

void readParticles(FieldReader& system, Scene& scene) {
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
    scene.particles.push_back(p);
  }
  const int n = static_cast<int>(scene.particles.size());
  if (!system.has("springs")) return;
  const json& springs = system.raw("springs");
  if (!springs.is_array()) failField(system.field("springs"), "a list", springs);
  for (std::size_t k = 0; k < springs.size(); ++k) {
    FieldReader r(springs[k], system.field("springs") + "[" + std::to_string(k) + "]");
    Spring s;
    s.i = static_cast<int>(r.integer("i", 0, n - 1));
    s.j = static_cast<int>(r.integer("j", 0, n - 1));
    if (s.i == s.j) failField(r.field("j"), "a particle other than i", springs[k]["j"]);
    const double distance = (scene.particles[s.j].position - scene.particles[s.i].position).norm();
    s.rest_length = r.positive("rest_length", distance);
    if (!(s.rest_length > 0.0)) {
      throw FieldError{r.field("rest_length"),
                       "expected a number > 0; the default (start distance) is 0 here"};
    }
    s.stiffness = r.positive("stiffness");
    s.damping = r.nonNegative("damping", 0.0);
    s.family = SpringFamily::Custom;
    r.refuseUnknown("docs/scenes.md");
    scene.springs.push_back(s);
  }
}

}  // namespace mysim
