// The model file an external engine reads (docs/external-engines.md).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "compare/engines/external_engine.h"
#include "compare/io/atomic_file.h"
#include "compare/io/npy.h"
#include "mysim/circle_system.h"
#include "mysim/cloth_surface.h"
#include "mysim/particle_system.h"
#include "mysim/wind.h"

namespace springcheck {

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

// The integrator's name and the parameters it declares (the catalogue's), as the run has them:
// only those, so an engine is not told of substeps an integrator does not have.
json integratorSettings(const mysim::IntegratorSettings& settings) {
  json j{{"name", settings.name}};
  const mysim::IntegratorInfo* info = mysim::findIntegrator(settings.name);
  if (!info) return j;
  for (const mysim::IntegratorParameter& p : info->parameters) {
    if (p.in_values) {
      j[p.name] = settings.value(p.name);
    } else if (p.name == "abs_tolerance") {
      j[p.name] = settings.abs_tolerance;
    } else if (p.name == "rel_tolerance") {
      j[p.name] = settings.rel_tolerance;
    } else if (p.name == "cg_tolerance") {
      j[p.name] = settings.cg_tolerance;
    } else if (p.name == "cg_max_iterations") {
      j[p.name] = settings.cg_max_iterations;
    } else if (p.name == "cg_preconditioner") {
      j[p.name] = mysim::preconditionerName(settings.preconditioner);
    }
  }
  return j;
}

json vec3(const mysim::Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

json rows3(const mysim::Vector& flat) {
  json rows = json::array();
  for (int p = 0; p < flat.size() / 3; ++p) rows.push_back(vec3(mysim::at3(flat, p)));
  return rows;
}

// The colliders (with their friction), "sphere" for engines written for a model with at most one
// sphere (filled only when the sphere is the one collider, so such an engine never silently
// drops another), and self-collision only when asked for (every other model file reads as
// before it existed).
void describeContacts(const mysim::Model& model, json& j) {
  for (const mysim::Collider& c : model.colliders) j["colliders"].push_back(describeCollider(c));
  if (model.self_collision_thickness) j["self_collision"] = {{"thickness", *model.self_collision_thickness}};
  if (model.colliders.size() == 1 && std::holds_alternative<mysim::Sphere>(model.colliders[0])) {
    j["sphere"] = j["colliders"][0];
    j["sphere"].erase("type");
  }
}

json describeParticles(const mysim::Model& model, const mysim::State& start) {
  const int n = model.particleCount();
  json particles = {{"count", n},
                    {"position", rows3(start.y.head(3 * n))},
                    {"velocity", rows3(start.y.tail(3 * n))},
                    {"mass", std::vector<double>(model.mass.data(), model.mass.data() + n)},
                    {"pinned", json::array()}};
  for (char pinned : model.pinned) particles["pinned"].push_back(pinned != 0);
  return particles;
}

json describeSprings(const mysim::Model& model) {
  json springs = {{"count", model.springs.size()}};
  for (const char* key : {"i", "j", "rest_length", "stiffness", "damping", "family"}) {
    springs[key] = json::array();
  }
  for (const mysim::Spring& s : model.springs) {
    springs["i"].push_back(s.i);
    springs["j"].push_back(s.j);
    springs["rest_length"].push_back(s.rest_length);
    springs["stiffness"].push_back(s.stiffness);
    springs["damping"].push_back(s.damping);
    springs["family"].push_back(mysim::familyName(s.family));
  }
  return springs;
}

// Hinges (mysim/hinge.h): b = sum_a weight[a] x[particles[a]], E = 1/2 stiffness |b|^2, flat
// at rest (rest_angle 0 for every one: the quadratic model bends about a flat rest state).
json describeHinges(const mysim::Model& model) {
  json hinges = {{"count", model.hinges.size()},
                 {"particles", json::array()},
                 {"weights", json::array()},
                 {"stiffness", json::array()},
                 {"rest_angle", json::array()}};
  for (const mysim::Hinge& h : model.hinges) {
    hinges["particles"].push_back(h.particle);
    hinges["weights"].push_back(h.weight);
    hinges["stiffness"].push_back(h.stiffness);
    hinges["rest_angle"].push_back(0.0);
  }
  return hinges;
}

// The wind's force table (wind.npy) and its description in j["wind"].
std::expected<void, std::string> writeWindTable(const std::string& dir, const mysim::Model& model,
                                                double duration, json& j) {
  const int n = model.particleCount();
  const mysim::Wind& w = *model.wind;
  // The force on particle p in gust window floor(t / gust_period) is
  // table[window, p] * direction: the same hash mysim evaluates, tabulated.
  const long windows = static_cast<long>(std::floor(duration / w.gust_period)) + 2;
  j["wind"] = {{"direction", vec3(w.direction)}, {"strength", w.strength}, {"gust", w.gust},
               {"gust_period", w.gust_period},   {"coverage", w.coverage}, {"seed", w.seed},
               {"force_table", "wind.npy"},      {"windows", windows}};
  std::vector<double> table(static_cast<std::size_t>(windows) * n);
  for (long k = 0; k < windows; ++k) {
    // The middle of the window, so no rounding of k * period can land in the next one.
    const double t = (static_cast<double>(k) + 0.5) * w.gust_period;
    for (int p = 0; p < n; ++p) {
      table[k * n + p] = model.pinned[p] ? 0.0 : mysim::windForce(w, p, t).dot(w.direction);
    }
  }
  return writeNpy((fs::path(dir) / "wind.npy").string(), {windows, n}, table);
}

}  // namespace

FramePlan framePlan(const mysim::RunSettings& settings, bool every_step) {
  const long steps = mysim::stepCount(settings);
  const long stride = every_step ? 1 : mysim::sampleStride(settings);
  FramePlan plan{{0}, {0.0}};
  double t = 0.0;
  for (long step = 1; step <= steps; ++step) {
    t += settings.dt;
    if (step % stride == 0 || step == steps) {
      plan.steps.push_back(step);
      plan.times.push_back(t);
    }
  }
  return plan;
}

std::expected<void, std::string> writeModelFile(const std::string& dir, const mysim::Model& given,
                                                const RunConfig& config, const FramePlan& frames) {
  const mysim::Model model = given.isCircle() ? mysim::circleTwin(given) : given;
  // The start state as mysim starts from it: the after-step rule applied once at t = 0 (pinned
  // particles carry their prescribed velocity, contacts resolved), so an engine that simply
  // starts from the file starts where mysim does.
  const mysim::State start = mysim::ParticleSystem(model, {}).initialState();
  // A cloth's triangles (its grid's or its mesh's), for engines that draw or collide surfaces.
  json triangles = json::array();
  for (const Eigen::Vector3i& t : mysim::clothTriangles(model)) triangles.push_back({t[0], t[1], t[2]});
  const long steps = mysim::stepCount(config.run);
  json j = {{"format", "springcheck-model"},
            {"version", 1},
            {"units", "SI: m, kg, s, N"},
            {"scene", config.scene_name},
            {"source", config.source},
            {"system", given.isCircle() ? "circle (as its mechanical twin)"
                                        : given.kind},
            {"particles", describeParticles(model, start)},
            {"springs", describeSprings(model)},
            {"hinges", describeHinges(model)},
            {"triangles", triangles},
            {"gravity", vec3(model.gravity)},
            {"drag", model.drag},
            {"wind", nullptr},
            {"pin_motion", nullptr},
            {"colliders", json::array()},
            {"sphere", nullptr},
            {"integrator", integratorSettings(config.integrator)},
            {"dt", config.run.dt},
            {"duration", config.run.duration},
            {"steps", steps},
            {"frame_steps", frames.steps},
            {"frame_times", frames.times}};
  if (model.pin_motion) {
    j["pin_motion"] = {{"axis", vec3(model.pin_motion->axis)},
                       {"amplitude", model.pin_motion->amplitude},
                       {"frequency", model.pin_motion->frequency}};
  }
  describeContacts(model, j);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (model.wind) {
    if (auto written = writeWindTable(dir, model, config.run.duration, j); !written) return written;
  }
  return writeFileAtomically((fs::path(dir) / "model.json").string(),
                             [&](std::ostream& out) { out << jsonText(j, 1) << '\n'; });
}

}  // namespace springcheck
