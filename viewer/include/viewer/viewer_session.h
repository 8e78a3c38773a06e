#pragma once
// What the viewer shows and how keys change it, with no window: the window (window.cpp) and the
// tests drive this same object, so every key is tested through the handler the window uses.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compare/engines/engine_registry.h"
#include "mysim/integrator.h"
#include "mysim/scene.h"

namespace viewer {

// One engine of the registry running the current scene: its stepper, over the OdeSystem that
// judges every engine alike (health, energy, rows).
struct EngineView {
  std::string engine;
  std::unique_ptr<mysim::OdeSystem> system;
  std::unique_ptr<mysim::Stepper> stepper;
  mysim::State state;
  std::string integrator;             // what steps it ("rk4", "bullet-explicit", ...)
  std::string refused;                // why this engine cannot run the scene, if it cannot
  std::optional<double> blowup_time;  // s
  std::string blowup_check;
  double step_seconds = 0.0;  // wall time of the last frame's stepping
  bool running() const { return refused.empty() && !blowup_time; }
};

struct Camera {
  double yaw = 0.6, pitch = 0.35;  // rad
  double distance = 3.0;           // m, from the target
  double target[3] = {0, 0, 0};
};

class ViewerSession {
 public:
  // `scenes`: the files `t` cycles through; `first` is shown first (added if not in the list).
  // `engines` are names in `registry`.
  ViewerSession(springcheck::EngineRegistry registry, std::vector<std::string> scenes,
                const std::string& first, std::vector<std::string> engines,
                const std::string& integrator, double dt);

  // Keys as the original program had them, plus i, space and '.':
  //   t next scene, d wind on/off, s swing on/off, w shaded cloth / springs, r reset,
  //   i next integrator (mysim), ' ' pause / run, '.' one step while paused.
  // Returns false for a key with no meaning.
  bool handleKey(char key);

  // Advances every running engine by whole steps towards `real_seconds` more of simulated time
  // (real time), spending at most `budget_seconds` of wall time; if that is not enough the
  // simulation runs slower than real time and `speed()` says how much.
  void advance(double real_seconds, double budget_seconds = 0.03);
  void stepOnce();
  void reset();

  // The model the engines run (the file's, with the wind and swing toggles applied) and its
  // run settings (the scene's, with the integrator and dt chosen).
  const mysim::Model& model() const { return model_; }
  const springcheck::RunConfig& config() const { return config_; }
  const std::string& sceneFile() const { return scenes_[scene_index_]; }
  const std::vector<EngineView>& engines() const { return engines_; }
  // The mysim integrator chosen (i), and the one mysim steps this scene with: they differ on the
  // circle, which takes first-order methods only and falls back to RK4.
  const std::string& integrator() const { return integrator_; }
  const std::string& activeIntegrator() const { return config_.integrator.name; }
  // Wind and swing act on particles: not on the circle.
  bool togglesApply() const { return !model_.isCircle(); }
  // What the last key did not do and why (empty when it did what it says).
  const std::string& notice() const { return notice_; }
  // One line of state, printed by the window after every key: scene, time, integrator, toggles.
  std::string summary() const;
  double time() const { return time_; }
  double dt() const { return dt_; }
  bool paused() const { return paused_; }
  bool shaded() const { return shaded_; }
  bool wind() const { return wind_; }
  bool swing() const { return swing_; }
  double speed() const { return speed_; }  // simulated seconds per real second, last frame
  Camera& camera() { return camera_; }
  const std::string& error() const { return error_; }

  // Current metrics: energy of each engine (J, if it has one), RMS node distance between the
  // first two running engines (m), deepest node inside a collider over engines (m).
  std::optional<double> energy(const EngineView& e) const;
  std::optional<double> engineDistance() const;
  std::optional<double> penetration() const;

 private:
  void load();
  void build();
  void frameCamera();

  springcheck::EngineRegistry registry_;
  std::vector<std::string> scenes_;
  std::size_t scene_index_ = 0;
  std::vector<std::string> engine_names_;
  std::string integrator_;
  double requested_dt_;
  mysim::Model file_model_;             // built from the file
  springcheck::RunConfig file_config_;  // the file's run settings
  mysim::Model model_;                  // with the toggles applied
  springcheck::RunConfig config_;       // with the integrator and dt applied
  std::vector<EngineView> engines_;
  double dt_ = 0.0, time_ = 0.0, speed_ = 1.0, owed_ = 0.0;
  bool paused_ = false, shaded_ = true, wind_ = false, swing_ = false;
  Camera camera_;
  std::string error_;
  std::string notice_;
};

}  // namespace viewer
