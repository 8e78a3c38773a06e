// springcheck roundoff: each engine's sensitivity to round-off on a scene (its run against its
// own run from a start nudged by a few ulps), and, for two engines, whether their difference is
// round-off amplification or real (compare/studies/roundoff.h).
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "compare/io/atomic_file.h"
#include "compare/io/text_format.h"
#include "compare/metrics/drape_metric.h"
#include "compare/studies/roundoff.h"

namespace springcheck {
namespace {

std::string formatNumber3(double v) { return formatNumber(v, 3); }

struct RoundoffOptions {
  std::string scene_path;
  std::string engines = "mysim";
  int ulps = 4;
  double duration = 0.0;  // 0: the scene's
  std::string json_out;
  std::vector<std::string> engines_files;
};

nlohmann::json sensitivityJson(const RoundoffSensitivity& s) {
  return {{"engine", s.engine},          {"ulps", s.ulps},
          {"nudge_m", s.nudge},          {"final_divergence_m", s.final_divergence},
          {"largest_divergence_m", s.largest_divergence},
          {"amplification", s.amplification}, {"growth_rate_per_s", s.growth_rate},
          {"times", s.times},            {"divergence_m", s.divergence}};
}

void printSensitivity(const RoundoffSensitivity& s) {
  std::cout << "  " << s.engine << ": a nudge of " << s.ulps << " ulps (" << formatNumber3(s.nudge)
            << " m) drifts to " << formatNumber3(s.largest_divergence) << " m (x"
            << formatNumber3(s.amplification) << ", e-folding rate "
            << formatNumber3(s.growth_rate) << " /s), " << formatNumber3(s.final_divergence)
            << " m at the end\n";
}

// The two engines' node distance at each frame both sampled.
std::vector<double> differenceOf(const RoundoffSensitivity& a, const RoundoffSensitivity& b) {
  std::vector<double> d;
  const std::size_t frames = std::min(a.run.frames.size(), b.run.frames.size());
  for (std::size_t f = 0; f < frames; ++f) {
    d.push_back(nodeDistance(a.run.frames[f].leftCols<3>(), b.run.frames[f].leftCols<3>()).max);
  }
  return d;
}

int roundoff(const RoundoffOptions& o) {
  const std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  auto scene = loadSceneOrSay(*registry, o.scene_path, 0.0, o.duration);
  if (!scene) return kBadInput;
  const std::vector<std::string> engines = splitList(o.engines);
  if (engines.empty() || engines.size() > 2) {
    std::cerr << "error: --engines: expected one engine, or two to compare, got "
              << engines.size() << '\n';
    return kBadInput;
  }
  const mysim::Model model = mysim::buildModel(*scene);
  std::vector<RoundoffSensitivity> found;
  std::cout << scene->name << ": round-off sensitivity\n";
  for (const std::string& engine : engines) {
    auto s = measureRoundoff(*registry, engine, model, runConfig(*scene), o.ulps);
    if (!s) {
      std::cerr << "error: " << engine << ": " << s.error().message << '\n';
      return exitCodeFor(s.error());
    }
    printSensitivity(*s);
    found.push_back(std::move(*s));
  }
  nlohmann::json out{{"scene", scene->name}, {"engines", nlohmann::json::array()}};
  for (const RoundoffSensitivity& s : found) out["engines"].push_back(sensitivityJson(s));
  if (found.size() == 2) {
    const std::vector<double> difference = differenceOf(found[0], found[1]);
    const DifferenceVerdict v = classifyDifference(difference, found[0], found[1]);
    std::cout << "  " << engines[0] << " ~ " << engines[1] << ": " << v.verdict << " (largest "
              << formatNumber3(v.largest_difference) << " m; at worst "
              << formatNumber3(v.worst_ratio) << " of 10 x the drift, t = "
              << formatNumber3(v.worst_time) << " s)\n";
    out["pair"] = {{"verdict", v.verdict},       {"largest_difference_m", v.largest_difference},
                   {"worst_ratio", v.worst_ratio}, {"worst_time_s", v.worst_time},
                   {"difference_m", difference}};
  }
  if (!o.json_out.empty()) {
    auto written = writeFileAtomically(o.json_out, [&](std::ostream& s) { s << jsonText(out, 1); });
    if (!written) {
      std::cerr << "error: --json: " << written.error() << '\n';
      return kFailure;
    }
  }
  for (const RoundoffSensitivity& s : found) {
    if (s.run.blowup) return kBlowUp;
  }
  return kOk;
}

}  // namespace

void addRoundoffCommand(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<RoundoffOptions>();
  CLI::App* cmd = app.add_subcommand(
      "roundoff",
      "How far each engine's run drifts from its own run nudged by a few ulps, and whether two "
      "engines differ by round-off amplification or for real");
  cmd->add_option("scene", o->scene_path, "Scene file (JSON)")->required();
  cmd->add_option("--engines", o->engines, "One engine, or two to compare (comma-separated)")
      ->capture_default_str();
  addEnginesFileOption(cmd, o->engines_files);
  cmd->add_option("--ulps", o->ulps, "Units in the last place each start coordinate is moved")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  cmd->add_option("--duration", o->duration, "Duration in s (overrides the scene)")
      ->check(kPositive);
  cmd->add_option("--json", o->json_out, "Also write the drifts and the verdict to this file");
  cmd->callback([o, &exit_code] { exit_code = roundoff(*o); });
}

}  // namespace springcheck
