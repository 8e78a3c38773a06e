#include "viewer/viewer_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "mysim/particle_system.h"
#include "compare/metrics/penetration_metric.h"

namespace viewer {

ViewerSession::ViewerSession(springcheck::EngineRegistry registry, std::vector<std::string> scenes,
                             const std::string& first, std::vector<std::string> engines,
                             const std::string& integrator, double dt)
    : registry_(std::move(registry)),
      scenes_(std::move(scenes)),
      engine_names_(std::move(engines)),
      integrator_(integrator),
      requested_dt_(dt) {
  auto it = std::find(scenes_.begin(), scenes_.end(), first);
  if (it == scenes_.end()) it = scenes_.insert(scenes_.begin(), first);
  scene_index_ = it - scenes_.begin();
  load();
}

void ViewerSession::load() {
  auto scene = registry_.loadScene(scenes_[scene_index_]);
  error_.clear();
  if (!scene) {
    error_ = scene.error();
    engines_.clear();
    return;
  }
  // The scene stops here: what the keys change is the model and the run's settings.
  file_model_ = mysim::buildModel(*scene);
  file_config_ = springcheck::runConfig(*scene);
  if (integrator_.empty()) integrator_ = file_config_.integrator.name;
  build();
  frameCamera();
}

void ViewerSession::build() {
  engines_.clear();  // their systems refer to model_, which changes here
  model_ = file_model_;
  config_ = file_config_;
  // The circle takes first-order methods only: fall back to RK4 there.
  const mysim::IntegratorInfo* info = mysim::findIntegrator(integrator_);
  config_.integrator.name =
      (model_.isCircle() && info && info->needs_particles) ? "rk4" : integrator_;
  if (requested_dt_ > 0) config_.run.dt = requested_dt_;
  dt_ = config_.run.dt;
  if (wind_ && togglesApply()) {
    // A gusting breeze along +z of about a quarter of a particle's weight, seeded.
    model_.wind = mysim::Wind{mysim::Vec3::UnitZ(), 0.25 * 9.8 * model_.mass[0], 0.8, 0.1, 0.5, 42};
  }
  if (swing_ && togglesApply()) {
    model_.pin_motion = mysim::PinMotion{mysim::Vec3::UnitZ(), 0.2, 0.5};  // the seed's swing
  }
  for (const std::string& name : engine_names_) {
    EngineView view;
    view.engine = name;
    auto instance = registry_.build(name, model_, config_);
    if (instance) {
      view.system = std::move(instance->system);
      view.stepper = std::move(instance->stepper);
      view.state = instance->start;
      view.integrator = instance->integrator;
    } else {
      view.refused = instance.error().message;
    }
    engines_.push_back(std::move(view));
  }
  time_ = 0.0;
  owed_ = 0.0;
}

void ViewerSession::frameCamera() {
  // Framed on the first engine that runs (the first may have refused the scene).
  auto shown = std::find_if(engines_.begin(), engines_.end(),
                            [](const EngineView& e) { return e.system != nullptr; });
  if (shown == engines_.end()) return;
  const auto rows = shown->system->particleRows(shown->state);
  const Eigen::Vector3d low = rows.leftCols<3>().colwise().minCoeff();
  const Eigen::Vector3d high = rows.leftCols<3>().colwise().maxCoeff();
  Eigen::Vector3d centre = 0.5 * (low + high);
  double size = std::max((high - low).norm(), 0.5);
  if (model_.hangsFromPins()) {
    // Things hang below their pins by about their own size: look a little lower.
    centre.y() -= 0.4 * size;
    size *= 1.4;
  }
  if (model_.isCircle()) {
    size = 2.5;
    centre.setZero();
    camera_.yaw = camera_.pitch = 0.0;  // face on: the orbit lies in the x-y plane
  } else {
    camera_.yaw = Camera{}.yaw;
    camera_.pitch = Camera{}.pitch;
  }
  for (int k = 0; k < 3; ++k) camera_.target[k] = centre[k];
  camera_.distance = 1.6 * size;
}

void ViewerSession::stepOnce() {
  for (EngineView& e : engines_) {
    if (!e.running()) continue;
    const auto start = std::chrono::steady_clock::now();
    e.stepper->step(e.state, dt_);
    e.step_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (auto bad = e.system->checkHealth(e.state)) {
      e.blowup_time = e.state.t;
      e.blowup_check = bad->check;
    }
  }
  time_ += dt_;
}

void ViewerSession::advance(double real_seconds, double budget_seconds) {
  if (paused_) return;
  for (EngineView& e : engines_) e.step_seconds = 0.0;
  const auto start = std::chrono::steady_clock::now();
  const double frame = std::min(real_seconds, 0.1);
  owed_ += frame;  // simulated time owed to real time, carried over between frames
  int steps = 0;
  while (owed_ > (1.0 - 1e-9) * dt_) {  // round-off must not lose a step
    stepOnce();
    owed_ -= dt_;
    ++steps;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
        budget_seconds) {
      owed_ = 0.0;  // cannot keep up: run slower than real time instead of falling behind
      break;
    }
  }
  speed_ = frame > 0 && owed_ == 0.0 && steps * dt_ < frame ? steps * dt_ / frame : 1.0;
}

void ViewerSession::reset() { build(); }  // toggles and the pause state are kept

bool ViewerSession::handleKey(char key) {
  notice_.clear();
  if ((key == 'd' || key == 's') && !togglesApply()) {
    notice_ = std::string(key == 'd' ? "wind" : "swing") +
              " does not apply to the circle (a first-order ODE, no particles)";
    return true;
  }
  switch (key) {
    case 't':
      scene_index_ = (scene_index_ + 1) % scenes_.size();
      load();
      return true;
    case 'd':
      wind_ = !wind_;
      build();
      return true;
    case 's':
      swing_ = !swing_;
      build();
      return true;
    case 'w':
      shaded_ = !shaded_;
      return true;
    case 'r':
      reset();
      return true;
    case 'i': {
      const auto& catalog = mysim::integratorCatalog();
      auto it = std::find_if(catalog.begin(), catalog.end(),
                             [&](const auto& i) { return i.name == integrator_; });
      std::size_t k = it == catalog.end() ? 0 : (it - catalog.begin() + 1) % catalog.size();
      if (model_.isCircle()) {
        while (catalog[k].needs_particles) k = (k + 1) % catalog.size();
      }
      integrator_ = catalog[k].name;
      build();
      return true;
    }
    case ' ':
      paused_ = !paused_;
      return true;
    case '.':
      if (paused_) stepOnce();
      return true;
    default:
      return false;
  }
}

std::string ViewerSession::summary() const {
  char t[32];
  std::snprintf(t, sizeof t, "%.3f", time_);
  char step[32];
  std::snprintf(step, sizeof step, "%.4g", dt_);
  std::string text = "scene " + config_.scene_name + ", t " + t + " s, mysim " + activeIntegrator() +
                     ", dt " + step + " s, " + (paused_ ? "paused" : "running") + ", " +
                     (shaded_ ? "shaded" : "springs");
  if (togglesApply()) {
    text += std::string(", wind ") + (wind_ ? "on" : "off") + ", swing " + (swing_ ? "on" : "off");
  }
  return text;
}

std::optional<double> ViewerSession::energy(const EngineView& e) const {
  if (!e.system) return std::nullopt;
  auto terms = e.system->energy(e.state);
  return terms ? std::optional(terms->total()) : std::nullopt;
}

std::optional<double> ViewerSession::engineDistance() const {
  const EngineView* first = nullptr;
  for (const EngineView& e : engines_) {
    if (!e.system || e.blowup_time) continue;
    if (!first) {
      first = &e;
      continue;
    }
    const auto a = first->system->particleRows(first->state);
    const auto b = e.system->particleRows(e.state);
    if (a.rows() != b.rows()) return std::nullopt;
    return std::sqrt((a.leftCols<3>() - b.leftCols<3>()).rowwise().squaredNorm().mean());
  }
  return std::nullopt;
}

std::optional<double> ViewerSession::penetration() const {
  if (model_.colliders.empty()) return std::nullopt;
  double deepest = 0.0;
  for (const EngineView& e : engines_) {
    if (!e.system) continue;
    const auto rows = e.system->particleRows(e.state);
    deepest = std::max(deepest, springcheck::penetration(model_.colliders, rows).deepest);
  }
  return deepest;
}

}  // namespace viewer
