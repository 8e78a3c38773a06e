#pragma once
// A user's simulator, in any language, as an engine: springcheck writes the model file, runs the
// program, and reads back its trajectory (the protocol: docs/external-engines.md).
#include <expected>
#include <string>
#include <vector>

#include "compare/engines/engine_registry.h"

namespace springcheck {

// One entry of an engines file.
struct ExternalEngineSpec {
  std::string name;
  std::string description;
  // argv, with placeholders {model} {out} {dir} {python} {dt} {duration} {integrator} {scene},
  // {env:NAME}, and {{ }} for literal braces.
  std::vector<std::string> command;
  double time_limit = 600.0;  // s, for one run
  // What the engine declares of itself: the floating-point type it steps in ("float64" or
  // "float32"), and whether its forces may depend on time (false: it cannot take wind or driven
  // pins, and refuses such scenes instead of running them wrong).
  std::string precision = "float64";
  bool time_dependent_forces = true;
  // Whether it applies the model file's hinges (bending, docs/external-engines.md). False, the
  // default: a scene with hinge bending is refused for it, since an engine that never read the
  // field would run the cloth without bending and look merely soft.
  bool hinges = false;
  // Whether it applies colliders' friction (the model file's colliders[k].friction): a scene
  // with friction is refused for one that does not declare it (it would slide frictionless).
  bool friction = false;
  // Whether it keeps the mesh from passing through itself (the model file's self_collision):
  // a scene asking for it is refused for one that does not declare it.
  bool self_collision = false;
  std::string source;         // the engines file, for messages
  std::string dir;            // its folder: {dir}, and relative programs resolve against it
};

// A command argument with its placeholders replaced in one pass, left to right (a value is never
// read again: a folder named "{dir}" stays text): `values` ({"{model}", path}, ...), {env:NAME}
// (an error if the environment has no NAME), "{{" and "}}" for literal braces.
[[nodiscard]] std::expected<std::string, std::string> substitutePlaceholders(
    const std::string& arg, const std::vector<std::pair<std::string, std::string>>& values);

// Reads and validates an engines file: {"engines": [{"name", "command", "time_limit",
// "description"}]}. Refuses, naming the file and the field: a missing or mistyped field, a name
// that is not [a-z0-9._-]+, an unknown placeholder, a non-positive time limit.
[[nodiscard]] std::expected<std::vector<ExternalEngineSpec>, std::string> loadEnginesFile(
    const std::string& path);
// The same from text; `source` names it and its folder is {dir}.
[[nodiscard]] std::expected<std::vector<ExternalEngineSpec>, std::string> parseEnginesFile(
    const std::string& text, const std::string& source);

// The frames a run is asked for: every `stride`-th step, and the last (as mysim::simulate
// records them), or every step. Times are summed t += dt in double precision, as springcheck's
// integrators advance time, so an engine that does the same matches them exactly.
struct FramePlan {
  std::vector<long> steps;
  std::vector<double> times;
};
FramePlan framePlan(const mysim::RunSettings& settings, bool every_step);

// Writes `dir`/model.json (and `dir`/wind.npy with the gust table when the model has wind): the
// fully expanded model and run settings, as the protocol describes. The circle is written as its
// mechanical twin (mysim::circleTwin).
[[nodiscard]] std::expected<void, std::string> writeModelFile(const std::string& dir,
                                                              const mysim::Model& model,
                                                              const RunConfig& config,
                                                              const FramePlan& frames);

// The states an engine returned: (F) times and (F, N, 6) rows, checked against the plan.
struct ExternalResult {
  std::vector<double> times;
  std::vector<mysim::ParticleRows> frames;
  bool summary_present = false;        // summary.json was there (its fields are optional)
  std::optional<double> wall_seconds;  // the engine's own stepping time, if it said
  std::optional<long> derivative_evaluations;  // if it said (a non-negative integer)
  std::optional<double> blowup_time;  // the engine stopped: it blew up then
  std::string blowup_reason;
};
// Reads `out_dir` (times.npy or times.csv, trajectory.npy or trajectory.csv, summary.json if
// present) and checks it whole: files present, shapes, particle count, finite values, the frame
// times asked for (a shorter run only with a blow-up declared in summary.json). Messages name the
// engine and the file.
[[nodiscard]] std::expected<ExternalResult, std::string> readExternalResult(
    const std::string& engine, const std::string& out_dir, int particles, const FramePlan& plan,
    double dt);

}  // namespace springcheck
