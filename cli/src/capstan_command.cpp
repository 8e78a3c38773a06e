// springcheck capstan: the largest load a capstan scene's chain holds over its friction
// collider, in each engine, against Euler-Eytelwein's e^(mu phi) (compare/studies/capstan_study.h).
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>
#include <sstream>

#include "commands.h"
#include "compare/io/atomic_file.h"
#include "compare/io/text_format.h"
#include "compare/studies/capstan_study.h"

namespace springcheck {
namespace {

struct CapstanOptions {
  std::vector<std::string> scenes;
  std::string engines = "mysim";
  std::string out = "out/capstan";
  std::vector<std::string> engines_files;
  double dt = 0.0;  // 0: the scene's
};

std::string capstanRow(const CapstanMeasurement& m) {
  std::ostringstream row;
  row.precision(10);
  row << m.scene << ',' << m.engine << ',' << m.capstan.wrap * 180.0 / std::numbers::pi << ',' << m.capstan.mu << ','
      << m.capstan.ratio() << ',' << m.hold_mass << ',' << m.predicted_load << ',' << m.measured_load << ','
      << m.slipped_load << ',' << m.measured_load / m.hold_mass << ',' << m.error() << ',' << m.runs << '\n';
  return row.str();
}

void printMeasurement(const CapstanMeasurement& m) {
  std::cout << m.scene << ", " << m.engine << ": wrap " << formatNumber(m.capstan.wrap * 180.0 / std::numbers::pi, 4)
            << " deg, mu " << m.capstan.mu << ", e^(mu phi) " << formatNumber(m.capstan.ratio(), 4)
            << ": holds " << formatNumber(m.measured_load, 4) << " kg (slips at " << formatNumber(m.slipped_load, 4)
            << "), closed form " << formatNumber(m.predicted_load, 4) << " kg: " << formatNumber(100.0 * m.error(), 3)
            << " % (" << m.runs << " runs)\n";
}

int capstan(const CapstanOptions& o) {
  const std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  std::string table =
      "scene,engine,wrap_deg,mu,e_mu_phi,hold_kg,predicted_load_kg,measured_load_kg,slipped_load_kg,"
      "measured_ratio,relative_error,runs\n";
  int failures = 0;
  for (const std::string& path : o.scenes) {
    auto scene = loadSceneOrSay(*registry, path, o.dt);
    if (!scene) return kBadInput;
    for (const std::string& engine : splitList(o.engines)) {
      auto m = measureCapstan(*registry, engine, *scene);
      if (!m) {
        std::cerr << "error: " << scene->name << ", " << engine << ": " << m.error() << '\n';
        ++failures;
        continue;
      }
      printMeasurement(*m);
      table += capstanRow(*m);
    }
  }
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  auto written = writeFileAtomically(o.out + "/capstan.csv", [&](std::ostream& s) { s << table; });
  if (!written) {
    std::cerr << "error: --out: " << written.error() << '\n';
    return kFailure;
  }
  std::cout << "results in " << o.out << "/capstan.csv\n";
  return failures ? kFailure : kOk;
}

}  // namespace

void addCapstanCommand(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<CapstanOptions>();
  CLI::App* cmd = app.add_subcommand(
      "capstan",
      "The largest load a capstan scene's chain holds over its friction collider, in each engine, against "
      "Euler-Eytelwein's e^(mu phi) (docs/contact.md)");
  cmd->add_option("scenes", o->scenes, "Capstan scene files (JSON)")->required();
  cmd->add_option("--engines", o->engines, "Comma-separated engines")->capture_default_str();
  addEnginesFileOption(cmd, o->engines_files);
  cmd->add_option("--dt", o->dt, "Step in s for every engine (overrides the scene: Bullet needs 0.2 ms on the "
                                 "shipped capstans' stiff light chains)")
      ->check(kPositive);
  cmd->add_option("--out", o->out, "Output folder (capstan.csv)")->capture_default_str();
  cmd->callback([o, &exit_code] { exit_code = capstan(*o); });
}

}  // namespace springcheck
