#pragma once
// Every engine springcheck can run, in one place: mysim (one per integrator), the Bullet twins,
// and the user's own simulators from engines files. compare, suite, sweep, stability, the gate,
// the viewer, the benchmarks and the tests all read this registry, so they list the same engines.
#include <expected>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mysim/model.h"
#include "mysim/scene.h"
#include "mysim/simulation.h"
#include "mysim/stepper.h"

namespace springcheck {

// How to run a model: a scene's integrator, output, blowup and engine sections, after the
// command line's overrides. Engines read this and the model, never the scene file.
struct RunConfig {
  std::string source;      // the scene file, for messages
  std::string scene_name;  // for output folders and model files
  mysim::IntegratorSettings integrator;
  mysim::RunSettings run;  // dt, duration, sample interval
  mysim::BlowUpLimits limits;
  mysim::EngineSettings engine_settings;
  // Timing: the run is made this many times (the results are identical: runs are
  // deterministic) and its wall time is the fastest; the median is kept beside it.
  int repeats = 1;
};
RunConfig runConfig(const mysim::Scene& scene);

// How runs are timed (docs/timing.md): repeats, and OpenMP threads per mysim run (0: every core,
// fewer while other processes hold some, unless fixed_threads).
struct Timing {
  int repeats = 1;
  int threads = 0;
  bool fixed_threads = false;
};
void applyTiming(const Timing& timing, RunConfig& config);

// An engine set up on a model, ready to step (the viewer steps it; runs go through simulate).
struct EngineInstance {
  // Judges every engine alike: health checks, energy and output rows are mysim's, computed from
  // the model and the engine's states.
  std::unique_ptr<mysim::OdeSystem> system;
  std::unique_ptr<mysim::Stepper> stepper;  // after `system`: it may refer to it
  mysim::State start;
  std::string integrator;  // what steps it: "rk4", "bullet-explicit", "pysim"...
  std::vector<std::string> notes;
};

// Why an engine did not run. Refused: it cannot represent the model (the message names the
// scene field and what to change). Failed: it ran and misbehaved (an external program that
// crashed, timed out or returned a bad result). Unknown: no such engine. Invalid: the run's
// settings break a limit every run is held to (mysim/run_limits.h).
struct EngineError {
  enum class Kind { Unknown, Refused, Failed, Invalid } kind;
  std::string message;
};

// One registry row.
struct Engine {
  std::string name;
  std::string kind;  // "mysim", "bullet" or "external"
  std::string description;
  // "NAME:INTEGRATOR" runs it with another integrator (mysim only).
  bool takes_integrator = false;
  // The mysim integrator whose theory (order, stability limit) its scheme follows, if any
  // (engines that take an integrator follow the one they run).
  std::string scheme;
  // Sets the engine up on a model, or refuses naming the field.
  std::function<std::expected<EngineInstance, EngineError>(const mysim::Model&, const RunConfig&)>
      build;
  // Runs it whole. Empty: build, then mysim::simulate. External engines run their program here.
  std::function<std::expected<mysim::RunRecord, EngineError>(const mysim::Model&, const RunConfig&)>
      run;
};

class EngineRegistry {
 public:
  // mysim and the Bullet engines.
  EngineRegistry();

  // Adds the engines of an engines file (docs/external-engines.md); refuses the whole file,
  // naming the field, if any entry is bad or a name is taken.
  [[nodiscard]] std::expected<void, std::string> addEnginesFile(const std::string& path);
  [[nodiscard]] std::expected<void, std::string> add(Engine engine);

  const std::vector<Engine>& engines() const { return engines_; }
  std::vector<std::string> names() const;
  // Every engine as a spec: each registered engine, and each that takes an integrator once per
  // integrator of the catalogue ("mysim:rk4", ...), without adaptive ones when fixed_step_only.
  std::vector<std::string> specs(bool fixed_step_only = false) const;
  // `specs` with "all" replaced by specs() ("all-fixed-step" by specs(true), "all-direct" by
  // specs(true) without mysim's iterative families).
  std::vector<std::string> expand(const std::vector<std::string>& specs) const;
  // The integrator whose theory applies to a spec run on a scene stepped by `scene_integrator`:
  // "mysim" -> it, "mysim:rk4" -> "rk4", a Bullet engine -> its scheme; empty if none.
  std::string schemeOf(const std::string& spec, const std::string& scene_integrator) const;
  const Engine* find(const std::string& name) const;
  // The engines files read so far, in order.
  const std::vector<std::string>& enginesFiles() const { return engines_files_; }

  // The scene sections engines declare ("bullet"), for the scene reader; and the scene reader
  // with them.
  const std::vector<mysim::EngineSection>& sceneSections() const { return sections_; }
  [[nodiscard]] std::expected<mysim::Scene, std::string> loadScene(const std::string& path) const;

  // The folder of the scenes springcheck ships (the CLI sets it to its data folder's scenes/),
  // and a shipped scene by name ("chain_hanging": the one NAME.json under it), so tolerances
  // files name the matched scenes wherever springcheck is installed. An error lists the names.
  void setShippedScenes(std::string folder) { shipped_scenes_ = std::move(folder); }
  [[nodiscard]] std::expected<std::string, std::string> shippedScene(const std::string& name) const;

  // Whether `spec` names an engine: a registered name, or "mysim:INTEGRATOR".
  [[nodiscard]] std::expected<void, std::string> check(const std::string& spec) const;
  // An instance of the engine on `model`, which its systems borrow (mysim::borrowed): the
  // caller keeps the model alive and unchanged while the instance lives.
  [[nodiscard]] std::expected<EngineInstance, EngineError> build(const std::string& spec,
                                                                 const mysim::Model& model,
                                                                 const RunConfig& config) const;
  // The record's `engine` is `spec`; made config.repeats times (wall_seconds the minimum).
  [[nodiscard]] std::expected<mysim::RunRecord, EngineError> run(const std::string& spec,
                                                                 const mysim::Model& model,
                                                                 const RunConfig& config) const;
  [[nodiscard]] std::expected<mysim::RunRecord, EngineError> run(const std::string& spec,
                                                                 const mysim::Scene& scene) const;

 private:
  // The registered engine behind a spec, and the config with its integrator applied.
  std::expected<std::pair<const Engine*, RunConfig>, EngineError> resolve(
      const std::string& spec, const RunConfig& config) const;

  std::vector<Engine> engines_;
  std::vector<mysim::EngineSection> sections_;
  std::vector<std::string> engines_files_;
  std::string shipped_scenes_;
};

// The wall times of identical runs: the fastest and the median (of at least one).
struct RepeatTimes {
  double fastest = 0.0, median = 0.0;
};
RepeatTimes repeatTimes(std::vector<double> walls);

// "a, b, c": the registered names, for help texts and messages.
std::string engineList(const EngineRegistry& registry);

}  // namespace springcheck
