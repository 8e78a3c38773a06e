#include "mysim/cloth_scene.h"

#include <algorithm>

#include "model/mesh_cloth.h"
#include "read_pins.h"

namespace mysim {

namespace {

std::optional<SpringParameters> readFamily(FieldReader& system, const std::string& key) {
  if (!system.has(key)) return std::nullopt;
  FieldReader r = system.object(key);
  SpringParameters p{r.positive("stiffness"), r.nonNegative("damping", 0.0)};
  r.refuseUnknown("docs/scenes.md");
  return p;
}

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

// A mesh cloth's "pins": a list, a preset, or {"within": R}, every vertex within R of the origin.
std::vector<int> readMeshPins(FieldReader& system, const Model& trial, const Vec3& origin) {
  const int n = trial.particleCount();
  if (!system.has("pins") || !system.raw("pins").is_object()) return readPins(system, n, {}, 0, 0);
  FieldReader pins = system.object("pins");
  const double within = pins.positive("within");
  pins.refuseUnknown("docs/materials.md");
  std::vector<int> held;
  for (int p = 0; p < n; ++p) {
    if ((at3(trial.start_position, p) - origin).norm() <= within * (1.0 + 1e-12)) held.push_back(p);
  }
  if (held.empty()) {
    throw FieldError{system.field("pins") + ".within", "a radius that holds at least one vertex"};
  }
  return held;
}

}  // namespace

// A cloth from a triangle mesh and its material (mesh_cloth.h): "mesh" is {"shape": "disc",
// "radius"} (resolution: its rings) or {"obj": FILE} (beside the scene file unless absolute; its
// own resolution); "pins" may also be {"within": R}, every vertex within R of the origin.
void ClothScene::readMesh(FieldReader& system, const std::string& source) {
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
  FieldReader given = system.object("material");
  material = readClothMaterial(given, true);
  if (material->bending == BendingModel::Flex) {
    throw FieldError{system.field("material") + ".bending.model",
                     "\"hinge\" for a mesh cloth (flex springs join grid nodes two apart)"};
  }
  mesh = readClothTriangles(system, source);
  const Vec3 origin = system.vec3("origin", Vec3::Zero());
  shape.origin = origin;
  // Built once here, so a mesh that cannot be a cloth is refused with the scene.
  Model trial;
  auto built = buildMeshCloth(*mesh, *material, origin, trial);
  if (!built) throw FieldError{system.field("mesh"), built.error()};
  mesh_drag = *built;
  start.pins = readMeshPins(system, trial, origin);
  start.velocity = system.vec3("velocity", Vec3::Zero());
}

// A cloth from its material: the grid from "resolution" (cells across the width), the
// constants from "material"; "pins": "left_clamp" holds the left edge in a clamp one cell deep.
void ClothScene::readMaterialGrid(FieldReader& system) {
  for (const char* derived : {"rows", "cols", "particle_mass", "structural", "shear", "flex"}) {
    if (system.has(derived)) {
      throw FieldError{system.field(derived),
                       "not with system.material: the material and system.resolution give it "
                       "(docs/materials.md)"};
    }
  }
  ClothShape& c = shape;
  FieldReader given = system.object("material");
  material = readClothMaterial(given, false);
  const int resolution = static_cast<int>(system.integer("resolution", 1, 10'000));
  c.width = system.positive("width");
  c.height = system.positive("height");
  const bool clamped = system.has("pins") && system.raw("pins") == "left_clamp";
  const MaterialGrid grid = materialGrid(c.width, c.height, resolution, clamped);
  material_grid = grid;
  material_clamped = clamped;
  if (!latticeSprings(material->stretch_stiffness, material->shear_stiffness, grid.dx, grid.dy)) {
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
  if (material->bending == BendingModel::Flex) c.flex = placeholder;
  c.hanging = readHanging(system);
  c.origin = system.vec3("origin", Vec3::Zero());
  if (clamped) {
    // The clamp's two columns straddle its edge at origin.x: the overhang is `width` from it at
    // every resolution (materialGrid).
    c.origin.x() -= 0.5 * grid.dx;
    c.width = (grid.cols - 1) * grid.dx;
    start.pins.clear();
    for (int r = 0; r < c.rows; ++r) {
      start.pins.push_back(r * c.cols);
      start.pins.push_back(r * c.cols + 1);
    }
  } else {
    start.pins = readPins(system, c.rows * c.cols, {0, c.cols - 1}, c.rows, c.cols);
  }
  start.velocity = system.vec3("velocity", Vec3::Zero());
}

void ClothScene::read(FieldReader& system, const std::string& source) {
  if (system.has("mesh")) {
    readMesh(system, source);
  } else if (system.has("material")) {
    readMaterialGrid(system);
  } else {
    readGrid(system);
  }
}

void ClothScene::readGrid(FieldReader& system) {
  ClothShape& c = shape;
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
  start.velocity = system.vec3("velocity", Vec3::Zero());
  const long count = static_cast<long>(c.rows) * c.cols;
  start.pins = readPins(system, static_cast<int>(std::min(count, 2'000'000'000L)), {0, c.cols - 1},
                        c.rows, c.cols);
}

void ClothScene::build(Model& model) const {
  model.kind = kType;
  model.naming = FieldNaming::PerFamily;
  if (mesh) {
    (void)buildMeshCloth(*mesh, *material, shape.origin, model);  // checked when read
  } else {
    buildCloth(shape, model);
    if (material) {
      applyClothMaterial(*material, material_grid.dx, material_grid.dy, model);
      model.material->clamped = material_clamped;
    }
  }
  start.apply(model);
}

SystemSize ClothScene::size() const {
  if (mesh) {
    const double n = double(mesh->vertices.size());
    return {n, 3 * n};
  }
  const double n = double(shape.rows) * shape.cols;
  return {n, 6 * n};
}

std::optional<double> ClothScene::materialDrag() const {
  if (!material || !(material->damping_rate > 0.0)) return std::nullopt;
  return mesh ? mesh_drag : material->damping_rate * material->density * material_grid.dx * material_grid.dy;
}

}  // namespace mysim
