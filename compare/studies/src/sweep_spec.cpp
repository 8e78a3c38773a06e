#include "compare/studies/sweep_spec.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "compare/io/text_format.h"
#include "mysim/json_input.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string exactNumber(double v) { return formatNumber(v, 10); }

// True when `interval` is a whole multiple of `dt` (to 1e-9 relative).
bool multipleOf(double interval, double dt) {
  const double ratio = interval / dt;
  return std::abs(ratio - std::round(ratio)) < 1e-9 * ratio;
}

constexpr const char* kSweepSchema = "docs/sweeps.md";
// Cases one spec may expand to: a day of the slowest shipped sweep's cases on 2 cores, and a
// table of tens of megabytes. More is a mistake or a cluster's job, split into specs or shards.
constexpr double kMaxSweepCases = 100000;

// The engines (default mysim) and the integrators of those that take one (default RK4).
void readEngines(mysim::FieldReader& top, const EngineRegistry& registry, SweepSpec& s) {
  using mysim::FieldError;
  s.engines = top.has("engines") ? top.textList("engines") : std::vector<std::string>{"mysim"};
  for (const std::string& e : s.engines) {
    if (e.find(':') != std::string::npos) {
      throw FieldError{"engines", "list integrators under \"integrators\", not as " + e};
    }
    if (auto ok = registry.check(e); !ok) throw FieldError{"engines", ok.error()};
    if (registry.find(e)->takes_integrator) s.integrator_engines.push_back(e);
  }
  s.integrators.clear();
  for (const std::string& name :
       top.has("integrators") ? top.textList("integrators") : std::vector<std::string>{"rk4"}) {
    auto variant = mysim::parseIntegratorVariant(name);  // "xpbd:substeps=10" sets a parameter
    if (!variant) throw FieldError{"integrators", variant.error()};
    s.integrators.push_back(variant->text());
  }
}

// The steps (each within every scene's duration), the stiffness and tolerance axes, the duration
// and the sampling (a multiple of every step, so all runs' frames line up).
void readSteps(mysim::FieldReader& top, SweepSpec& s) {
  using mysim::FieldError;
  s.dts = top.positiveList("dt");
  if (top.has("stiffness_scale")) s.stiffness_scales = top.positiveList("stiffness_scale");
  if (top.has("tolerance")) s.tolerances = top.positiveList("tolerance");
  if (top.has("duration")) s.duration = top.positive("duration");
  s.sample_interval =
      top.positive("sample_interval", *std::max_element(s.dts.begin(), s.dts.end()));
  for (std::size_t k = 0; k < s.dts.size(); ++k) {
    if (!multipleOf(s.sample_interval, s.dts[k])) {
      throw FieldError{"sample_interval", exactNumber(s.sample_interval) +
                                              " s is not a multiple of dt " + exactNumber(s.dts[k]) +
                                              " s (frames of all runs must line up)"};
    }
    // Every scene's run (or the spec's duration) must hold at least one step.
    for (const auto& [path, scene] : s.loaded) {
      const double duration = s.duration.value_or(scene.duration);
      if (s.dts[k] > duration) {
        throw FieldError{"dt[" + std::to_string(k) + "]",
                         "a step no longer than the duration (" + exactNumber(s.dts[k]) + " s > " +
                             exactNumber(duration) + " s of " + path + ")"};
      }
    }
  }
}

// What every row is measured against: the closed form, the case's own engine ("self"), or a
// converged run of one integrator.
void readReference(mysim::FieldReader& top, SweepSpec& s) {
  using mysim::FieldError;
  const json& ref = top.raw("reference");
  if (ref.is_string() && ref.get<std::string>() == "closed_form") {
    s.reference_closed_form = true;
  } else if (ref.is_string() && ref.get<std::string>() == "self") {
    s.reference_self = true;
  } else if (ref.is_object()) {
    mysim::FieldReader r = top.object("reference");
    if (r.has("integrator") && r.has("self")) {
      throw FieldError{"reference", "either \"integrator\" or \"self\", not both"};
    }
    s.reference_self = r.boolean("self", false);
    auto name = mysim::canonicalIntegratorName(r.text("integrator", "rk4"));
    if (!name) throw FieldError{"reference.integrator", name.error()};
    s.reference_integrator = *name;
    s.reference_refine = static_cast<int>(r.integer("refine", 1, 1'000'000, 16));
    r.refuseUnknown(kSweepSchema);
  } else {
    mysim::failField("reference",
                     "\"closed_form\", \"self\", {\"integrator\": NAME, \"refine\": N} or "
                     "{\"self\": true, \"refine\": N}",
                     ref);
  }
}

SweepSpec readSpec(const json& j, const std::string& source, EngineRegistry& registry) {
  using mysim::FieldError;
  mysim::FieldReader top(j, "");
  SweepSpec s;
  s.source = source;
  s.name = top.text("name", fs::path(source).stem().string());
  if (s.name.empty() || s.name.find('/') != std::string::npos || s.name[0] == '.') {
    mysim::failField("name", "a plain name (it names the results table)", top.raw("name"));
  }
  const fs::path base = fs::path(source).parent_path();
  if (top.has("engines_file")) {
    s.engines_file = (base / top.text("engines_file")).lexically_normal().string();
    const auto& read = registry.enginesFiles();
    if (std::find(read.begin(), read.end(), s.engines_file) == read.end()) {
      if (auto added = registry.addEnginesFile(s.engines_file); !added) {
        throw FieldError{"engines_file", added.error()};
      }
    }
  }
  const std::vector<std::string> scenes = top.textList("scenes");
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const std::string path = (base / scenes[k]).lexically_normal().string();
    auto scene = registry.loadScene(path);
    if (!scene) throw FieldError{"scenes[" + std::to_string(k) + "]", scene.error()};
    s.scenes.push_back(path);
    s.loaded.emplace(path, std::move(*scene));
  }
  readEngines(top, registry, s);
  readSteps(top, s);
  readReference(top, s);
  top.refuseUnknown(kSweepSchema);
  // The grid's size, counted before it is expanded (a 10^7-value axis once took gigabytes before
  // the first run): at most kMaxSweepCases cases a spec.
  double cases = 0;
  const double adaptive_axis = s.tolerances.empty() ? 1.0 : double(s.tolerances.size());
  for (const std::string& engine : s.engines) {
    const bool takes = std::find(s.integrator_engines.begin(), s.integrator_engines.end(),
                                 engine) != s.integrator_engines.end();
    cases += takes ? double(s.integrators.size()) * adaptive_axis : 1.0;
  }
  cases *= double(s.scenes.size()) * double(s.stiffness_scales.size()) * double(s.dts.size());
  if (cases > kMaxSweepCases) {
    throw FieldError{"scenes x engines x integrators x dt x stiffness_scale x tolerance", "the grid has " + formatNumber(cases, 3) + " cases; a spec may have at "
                           "most " + formatNumber(kMaxSweepCases, 6) + " (split it into several "
                           "specs, or shards of one: --shard)"};
  }
  return s;
}

}  // namespace

std::expected<SweepSpec, std::string> parseSweepSpec(const std::string& text,
                                                     const std::string& source,
                                                     EngineRegistry& registry) {
  auto root = mysim::parseJson(text, source);
  if (!root) return std::unexpected(root.error());
  return mysim::readFields<SweepSpec>(source, [&] { return readSpec(*root, source, registry); });
}

std::expected<SweepSpec, std::string> loadSweepSpec(const std::string& path,
                                                    EngineRegistry& registry) {
  auto root = mysim::readJsonFile(path, "sweep spec");
  if (!root) return std::unexpected(root.error());
  return mysim::readFields<SweepSpec>(path, [&] { return readSpec(*root, path, registry); });
}

std::vector<SweepCase> expandSweep(const SweepSpec& spec) {
  std::vector<SweepCase> cases;
  for (const std::string& scene : spec.scenes) {
    for (double scale : spec.stiffness_scales) {
      for (const std::string& engine : spec.engines) {
        const bool takes_integrator =
            std::find(spec.integrator_engines.begin(), spec.integrator_engines.end(), engine) !=
            spec.integrator_engines.end();
        const std::vector<std::string> integrators =
            takes_integrator ? spec.integrators : std::vector<std::string>{"-"};
        for (const std::string& integrator : integrators) {
          const auto variant = mysim::parseIntegratorVariant(integrator);
          const mysim::IntegratorInfo* info = variant ? mysim::findIntegrator(variant->name) : nullptr;
          const std::vector<double> tolerances =
              info && info->adaptive() && !spec.tolerances.empty() ? spec.tolerances
                                                                   : std::vector<double>{0.0};
          for (double tolerance : tolerances) {
            for (double dt : spec.dts) {
              cases.push_back({static_cast<int>(cases.size()), scene, engine, integrator, dt, scale,
                               tolerance});
            }
          }
        }
      }
    }
  }
  return cases;
}

SweepSpec sweepAroundScene(const EngineRegistry& registry, const std::string& path,
                           mysim::Scene scene) {
  SweepSpec s;
  s.source = path;
  s.name = "recommend_" + scene.name;
  const std::string file = fs::absolute(path).lexically_normal().string();
  s.scenes = {file};
  for (const Engine& e : registry.engines()) {
    s.engines.push_back(e.name);
    if (e.takes_integrator) s.integrator_engines.push_back(e.name);
  }
  s.integrators = mysim::integratorNames(true);
  const double dt = scene.dt;
  s.dts = {4 * dt, 2 * dt, dt, dt / 2, dt / 4};
  s.sample_interval = 4 * dt;
  s.reference_integrator = "rk4";
  s.reference_refine = 16;
  s.loaded.emplace(file, std::move(scene));
  return s;
}

std::expected<CaseRun, std::string> caseRun(const SweepSpec& spec, const SweepCase& c) {
  const auto cached = spec.loaded.find(c.scene);
  if (cached == spec.loaded.end()) {
    return std::unexpected(spec.source + ": scene " + c.scene + " is not one of the spec's");
  }
  CaseRun run{mysim::buildModel(cached->second), runConfig(cached->second)};
  if (c.integrator != "-") {
    auto variant = mysim::parseIntegratorVariant(c.integrator);
    if (!variant) return std::unexpected(spec.source + ": " + variant.error());
    run.config.integrator.name = variant->name;
    for (const auto& [key, value] : variant->values) run.config.integrator.values[key] = value;
  }
  run.config.run.dt = c.dt;
  if (spec.duration) run.config.run.duration = *spec.duration;
  run.config.run.sample_interval = spec.sample_interval;
  if (c.tolerance > 0)
    run.config.integrator.abs_tolerance = run.config.integrator.rel_tolerance = c.tolerance;
  mysim::scaleStiffness(run.model, c.stiffness_scale);
  return run;
}

}  // namespace springcheck
