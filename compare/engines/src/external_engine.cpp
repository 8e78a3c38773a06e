// A user's simulator as an engine: model file out, program run under a time limit, states back,
// checked, and replayed through mysim's run loop so every metric is computed by springcheck.
#include "compare/engines/external_engine.h"

#include <cstdlib>
#include <filesystem>
#include <optional>

#include "compare/engines/engine_registry.h"
#include "compare/engines/interrupts.h"
#include "compare/engines/python_interpreter.h"
#include "compare/io/text_format.h"
#include "mysim/circle_system.h"
#include "process.h"
#include "reference/bullet_engine.h"

namespace springcheck {

namespace {
namespace fs = std::filesystem;

EngineError failed(const std::string& message) {
  return EngineError{EngineError::Kind::Failed, message};
}

// A private folder for one run, removed with everything in it when the run is over.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& engine) {
    std::error_code ec;  // TMPDIR naming no folder: no scratch (the caller says where), no throw
    const fs::path base = fs::temp_directory_path(ec);
    if (ec) return;
    std::string pattern = (base / ("springcheck-" + engine + "-XXXXXX"));
    if (mkdtemp(pattern.data())) {
      path_ = pattern;
      tracked_.emplace(path_);  // removed by the interrupt handler too
    }
  }
  ~ScratchDir() {
    std::error_code ec;
    if (!path_.empty()) fs::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::optional<TrackedScratch> tracked_;
};

std::string number(double v) { return formatNumber(v, 17); }  // round-trips exactly

}  // namespace

std::expected<std::string, std::string> substitutePlaceholders(
    const std::string& arg, const std::vector<std::pair<std::string, std::string>>& values) {
  // One pass, left to right: what a placeholder becomes is never read again, so a folder named
  // "{dir}" or a TMPDIR holding "{out}" is text, not another placeholder.
  std::string result;
  for (std::size_t at = 0; at < arg.size();) {
    if (arg.compare(at, 2, "{{") == 0 || arg.compare(at, 2, "}}") == 0) {  // a literal brace
      result += arg[at];
      at += 2;
      continue;
    }
    if (arg.compare(at, 5, "{env:") == 0) {
      const std::size_t close = arg.find('}', at);
      const std::string name = close == std::string::npos ? "" : arg.substr(at + 5, close - at - 5);
      const char* value = name.empty() ? nullptr : std::getenv(name.c_str());
      if (!value) {
        return std::unexpected("'" + arg + "': " +
                               (name.empty() ? std::string("{env:NAME} needs a name and a closing brace")
                                             : "the environment has no " + name));
      }
      result += value;
      at = close + 1;
      continue;
    }
    bool replaced = false;
    for (const auto& [key, value] : values) {
      if (arg.compare(at, key.size(), key) == 0) {
        result += value;
        at += key.size();
        replaced = true;
        break;
      }
    }
    if (!replaced) result += arg[at++];
  }
  return result;
}

namespace {

// Replays an engine's frames through the run loop: at each step a frame was asked for, the state
// becomes that frame; between frames only the time moves (those states are never recorded).
// Frames that run out (a declared blow-up) leave a non-finite state, which the run loop reports.
class ReplayStepper final : public mysim::Stepper {
 public:
  ReplayStepper(ExternalResult result, FramePlan plan, bool circle)
      : result_(std::move(result)), plan_(std::move(plan)), circle_(circle) {}

  mysim::StepCounts step(mysim::State& state, double h) override {
    ++step_;
    state.t += h;
    while (next_ < result_.frames.size() && plan_.steps[next_] < step_) ++next_;
    if (next_ >= result_.frames.size()) {
      state.y.setConstant(std::numeric_limits<double>::quiet_NaN());
    } else if (plan_.steps[next_] == step_) {
      setState(result_.frames[next_], state);
      state.t = result_.times[next_];
    }
    return {.accepted = 1};
  }

  void setState(const mysim::ParticleRows& rows, mysim::State& state) const {
    if (circle_) {
      state.y = rows.block<1, 2>(mysim::kCircleTwinParticle, 0).transpose();
      return;
    }
    const int n = static_cast<int>(rows.rows());
    state.y.resize(6 * n);
    for (int p = 0; p < n; ++p) {
      state.y.segment<3>(3 * p) = rows.block<1, 3>(p, 0).transpose();
      state.y.segment<3>(3 * n + 3 * p) = rows.block<1, 3>(p, 3).transpose();
    }
  }
  const ExternalResult& result() const { return result_; }

 private:
  ExternalResult result_;
  FramePlan plan_;
  bool circle_;
  long step_ = 0;
  std::size_t next_ = 0;
};

struct Execution {
  ExternalResult result;
  FramePlan plan;
  double process_seconds = 0.0;
};

// The engine's command with its placeholders filled in ({python} found now, on this machine, only
// if the command asks for it); a relative program path is the engines file's.
std::expected<std::vector<std::string>, std::string> commandLine(const ExternalEngineSpec& spec,
                                                                 const RunConfig& config,
                                                                 const std::string& scratch) {
  std::string python = "python3";
  for (const std::string& arg : spec.command) {
    if (arg.find("{python}") == std::string::npos) continue;
    auto found = findPython({"numpy"});
    if (!found) return std::unexpected("{python} in " + spec.source + ": " + found.error());
    python = *found;
    break;
  }
  const std::vector<std::pair<std::string, std::string>> values = {
      {"{model}", scratch + "/model.json"},
      {"{out}", scratch + "/out"},
      {"{dir}", spec.dir},
      {"{python}", python},
      {"{dt}", number(config.run.dt)},
      {"{duration}", number(config.run.duration)},
      {"{integrator}", config.integrator.name},
      {"{scene}", config.scene_name}};
  std::vector<std::string> argv;
  for (const std::string& arg : spec.command) {
    auto substituted = substitutePlaceholders(arg, values);
    if (!substituted) {
      return std::unexpected("command in " + spec.source + ": " + substituted.error());
    }
    argv.push_back(*substituted);
  }
  if (argv[0].find('/') != std::string::npos && fs::path(argv[0]).is_relative()) {
    argv[0] = (fs::path(spec.dir) / argv[0]).lexically_normal().string();
  }
  return argv;
}

// Why a finished engine process failed (it did not start, timed out, was killed, exited non-zero),
// with the last lines it wrote; nothing if it exited 0.
std::optional<std::string> processFailure(const ProcessResult& p, const ExternalEngineSpec& spec,
                                          const std::string& log) {
  if (!p.started || !p.error.empty()) return p.error;
  if (p.timed_out) {
    return "killed at its time limit of " + number(spec.time_limit) + " s (time_limit in " +
           spec.source + "); it said last:" + lastLines(log, 5);
  }
  if (p.signal != 0) {
    return "ended by signal " + std::to_string(p.signal) + "; it said last:" + lastLines(log, 5);
  }
  if (p.exit_code != 0) {
    return "exited with code " + std::to_string(p.exit_code) + "; it said last:" +
           lastLines(log, 5);
  }
  return std::nullopt;
}

// Writes the model, runs the program, reads back and checks what it wrote.
std::expected<Execution, EngineError> execute(const ExternalEngineSpec& spec,
                                              const mysim::Model& model, const RunConfig& config,
                                              bool every_step) {
  const std::string who = "engine '" + spec.name + "'";
  if (!(config.run.dt > 0) || !(config.run.duration >= config.run.dt)) {
    return std::unexpected(failed(who + ": needs dt > 0 and a duration >= dt"));
  }
  ScratchDir scratch(spec.name);
  if (scratch.path().empty()) {
    return std::unexpected(
        failed(who + ": cannot make a scratch folder under TMPDIR (" +
               std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp") +
               "): it must name a writable folder"));
  }
  const std::string out = scratch.path() + "/out";
  fs::create_directories(out);
  // Driven models (wind, moving pins) need every step: the work they do is summed step by step.
  Execution run;
  run.plan = framePlan(config.run, every_step || model.wind || model.pin_motion);
  if (auto written = writeModelFile(scratch.path(), model, config, run.plan); !written) {
    return std::unexpected(failed(who + ": " + written.error()));
  }
  auto argv = commandLine(spec, config, scratch.path());
  if (!argv) return std::unexpected(failed(who + ": " + argv.error()));
  const std::string log = scratch.path() + "/engine.log";
  const ProcessResult p = runProcess(*argv, log, spec.time_limit);
  run.process_seconds = p.wall_seconds;
  if (auto why = processFailure(p, spec, log)) return std::unexpected(failed(who + ": " + *why));
  const int particles = model.isCircle() ? 2 : model.particleCount();
  auto result = readExternalResult(spec.name, out, particles, run.plan, config.run.dt);
  if (!result) return std::unexpected(failed(result.error()));
  run.result = std::move(*result);
  return run;
}

// What the engine declared of itself against what the scene needs: hinge bending needs an engine
// that reads hinges, friction and self-collision one that applies them; forces that ignore time cannot take wind or driven pins. Such a scene is
// refused, naming both sides.
std::optional<EngineError> refusal(const ExternalEngineSpec& spec, const mysim::Model& model,
                                   const RunConfig& config) {
  if (!model.hinges.empty() && !spec.hinges) {
    return EngineError{EngineError::Kind::Refused,
                       "engine '" + spec.name + "' does not declare hinges (\"hinges\": true in " +
                           spec.source + "); " + config.source +
                           " bends by hinges (system.material.bending), which it would ignore"};
  }
  if (!spec.friction) {
    for (std::size_t k = 0; k < model.colliders.size(); ++k) {
      if (!mysim::colliderFriction(model.colliders[k]).any()) continue;
      return EngineError{EngineError::Kind::Refused,
                         "engine '" + spec.name + "' does not declare friction (\"friction\": true in " +
                             spec.source + "); " + config.source + " gives colliders[" +
                             std::to_string(k) + "] friction, which it would ignore"};
    }
  }
  if (model.self_collision_thickness && !spec.self_collision) {
    return EngineError{EngineError::Kind::Refused,
                       "engine '" + spec.name + "' does not declare self-collision (\"self_collision\": "
                       "true in " + spec.source + "); " + config.source +
                           " asks for it (system.self_collision), which it would ignore"};
  }
  if (spec.time_dependent_forces) return std::nullopt;
  const char* driver = model.wind         ? "wind (forces.wind)"
                       : model.pin_motion ? "driven pins (forces.pin_motion)"
                                          : nullptr;
  if (!driver) return std::nullopt;
  return EngineError{EngineError::Kind::Refused,
                     "engine '" + spec.name +
                         "' declares forces that do not depend on time (time_dependent_forces: "
                         "false in " + spec.source + "); " + config.source + " has " + driver +
                         ", whose force changes with time"};
}

// A single-precision engine's floor: half an ulp of float (2^-24 relative) at the largest
// coordinate the run reached. Its round-off grows from there with the steps, so this is the
// least distance it can be from a double-precision answer, not the most.
void declarePrecision(const ExternalEngineSpec& spec, mysim::RunRecord& record) {
  if (spec.precision != "float32") return;
  double largest = 0.0;
  for (const mysim::ParticleRows& f : record.frames) {
    largest = std::max(largest, f.leftCols<3>().cwiseAbs().maxCoeff());
  }
  record.precision_floor = std::ldexp(largest, -24);
  record.notes.push_back("computes in single precision (precision: float32 in " + spec.source +
                         "): positions carry round-off of at least " +
                         formatNumber(record.precision_floor, 2) +
                         " m here, so a distance near that is its precision, not integration error");
}

}  // namespace

Engine externalEngine(const ExternalEngineSpec& spec) {
  Engine e;
  e.name = spec.name;
  e.kind = "external";
  e.description =
      (spec.description.empty() ? "a user's engine" : spec.description) + " (" + spec.source + ")";
  e.run = [spec](const mysim::Model& model,
                 const RunConfig& config) -> std::expected<mysim::RunRecord, EngineError> {
    if (auto refused = refusal(spec, model, config)) return std::unexpected(*refused);
    auto run = execute(spec, model, config, false);
    if (!run) return std::unexpected(run.error());
    const std::optional<double> blowup = run->result.blowup_time;
    const std::string reason = run->result.blowup_reason;
    const std::optional<double> own_seconds = run->result.wall_seconds;
    const std::optional<long> evaluations = run->result.derivative_evaluations;
    const bool summary_present = run->result.summary_present;
    auto system = mysim::makeSystem(mysim::borrowed(model), config.limits);
    ReplayStepper replay(std::move(run->result), run->plan, model.isCircle());
    mysim::RunRecord record = mysim::simulate(*system, replay, system->initialState(), config.run);
    // Its own method, whatever the scene names (the model file passes that on; it may follow it),
    // and a thread count springcheck does not know (0: unknown, null in summary.json).
    record.integrator = "own method (the scene names " + config.integrator.name + ")";
    record.threads = 0;
    // The engine's own stepping time if it reported one, else the whole process's.
    record.wall_seconds = own_seconds.value_or(run->process_seconds);
    if (!own_seconds) {
      record.notes.push_back(summary_present
                                 ? "wall time is the whole process's (summary.json has no wall_seconds)"
                                 : "wall time is the whole process's (no summary.json)");
    }
    // Unknown, not zero, when the engine does not say (written as null; mysim/integrator.h).
    record.counts.derivative_evaluations = evaluations.value_or(-1);
    declarePrecision(spec, record);
    if (record.blowup && blowup && record.blowup->check == "non-finite") {
      // At the time the engine declared, not at the step after its last frame.
      record.blowup->time = *blowup;
      record.blowup->step = std::lround(*blowup / config.run.dt);
      record.blowup->check = "engine";
      record.blowup->detail = "the engine reported a blow-up at t = " + number(*blowup) + " s" +
                              (reason.empty() ? "" : ": " + reason);
    }
    return record;
  };
  e.build = [spec](const mysim::Model& model,
                   const RunConfig& config) -> std::expected<EngineInstance, EngineError> {
    // Interactive use: the whole run at every step, then played back step by step.
    if (auto refused = refusal(spec, model, config)) return std::unexpected(*refused);
    auto run = execute(spec, model, config, true);
    if (!run) return std::unexpected(run.error());
    EngineInstance instance;
    instance.system = mysim::makeSystem(mysim::borrowed(model), config.limits);
    instance.start = instance.system->initialState();
    instance.stepper =
        std::make_unique<ReplayStepper>(std::move(run->result), run->plan, model.isCircle());
    instance.integrator = spec.name;
    instance.notes.push_back("played back from a run of the whole duration");
    return instance;
  };
  return e;
}

}  // namespace springcheck
