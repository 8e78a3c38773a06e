// springcheck engine init DIR [--name N]: a runnable skeleton of an external engine a user edits
// (docs/external-engines.md): an engines file, a Python engine (the example's symplectic Euler)
// and a tolerances file that gates it against the shipped matched scenes by name, so the gate
// passes as written, from any folder, wherever springcheck is installed.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>
#include <sstream>

#include "commands.h"
#include "compare/engines/external_engine.h"
#include "compare/io/atomic_file.h"
#include "data_dir.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json enginesFile(const std::string& name) {
  return {{"$comment",
           "Your engine, as springcheck runs it: {python} is a python3 with numpy, {dir} this "
           "folder, {model} the model file it writes, {out} the folder to write results into "
           "(docs/external-engines.md in springcheck's documentation)."},
          {"engines",
           {{{"name", name},
             {"description", "my simulator (symplectic Euler to start from; edit " + name + ".py)"},
             {"command", {"{python}", "{dir}/" + name + ".py", "{model}", "{out}"}},
             {"time_limit", 600}}}}};
}

json check(const std::string& scene, std::vector<std::string> engines, const std::string& metric,
           double bound, const std::string& why) {
  return {{"scene", scene}, {"engines", engines}, {"metric", metric}, {"bound", bound}, {"why", why}};
}

// The example engine's own gate (examples/external/tolerances.json), its scenes by name.
json tolerancesFile(const std::string& name) {
  return {{"$comment",
           "Gates for " + name + ": springcheck gate --tolerances tolerances.json, or springcheck "
           "suite SHIPPED/scenes/matched --engines-file engines.json --tolerances tolerances.json "
           "(README.md names the folder). Scenes named without a "
           "folder are the matched scenes springcheck ships. Change a bound only with its reason."},
          {"engines_file", "engines.json"},
          {"checks",
           {check("chain_hanging", {name}, "closed_form_error", 1e-4,
                  "the vertical chain's closed-form sag; after 20 s of drag at 1 /s the slowest "
                  "mode keeps e^-10 of the 0.35 m start displacement (1.6e-5 m)"),
            check("cloth_hanging", {name, "mysim:symplectic-euler"}, "drape_max", 1e-9,
                  "as written, mysim's symplectic Euler operation by operation: 0 m (the bound "
                  "leaves room for another numpy's round-off). Once you change the method, hold "
                  "it to bullet-deformable or a converged reference instead"),
            check("cloth_hanging", {name, "bullet-deformable"}, "drape_max", 1e-5,
                  "Bullet's explicit mode settles to the one rest shape of the same forces "
                  "(3.7e-7 m apart)"),
            check("chain_swing", {name}, "energy_drift_max", 0.1,
                  "undamped swinging chain: symplectic Euler keeps the energy bounded, not exact "
                  "(0.0165 at the scene's 1 ms step); a leak or a pump past 10 % is a bug")}}};
}

// The engines the gate's checks name, in their order, once each: the README's suite command runs
// only these (every built-in engine on every matched scene took 38 s of a 2-core machine's time,
// for checks that read three of them).
std::string checkedEngines(const std::string& name) {
  std::vector<std::string> engines;
  const json tolerances = tolerancesFile(name);
  for (const json& c : tolerances["checks"]) {
    for (const std::string engine : c["engines"]) {
      if (std::find(engines.begin(), engines.end(), engine) == engines.end()) engines.push_back(engine);
    }
  }
  std::string list;
  for (const std::string& engine : engines) list += (list.empty() ? "" : ",") + engine;
  return list;
}

// The suite command the README and the "next:" line suggest (one spelling for both).
std::string suiteCommand(const std::string& dir, const std::string& name) {
  return "springcheck suite " + dataFile("scenes/matched") + " --engines " + checkedEngines(name) +
         " --engines-file " + dir + "/engines.json --tolerances " + dir + "/tolerances.json";
}

std::string readme(const std::string& dir, const std::string& name) {
  std::ostringstream s;
  s << "# " << name << ": an external engine for springcheck\n\n"
    << "Made by `springcheck engine init`. It runs and passes its gate as it is:\n\n"
    << "```sh\n"
    << "springcheck gate --tolerances " << dir << "/tolerances.json\n"
    << suiteCommand(dir, name) << "   # every matched scene, in the engines the checks name\n"
    << "```\n\n"
    << "- `" << name << ".py`: the simulator, symplectic Euler with numpy. Replace its stepping "
    << "with yours; keep reading the model file and writing `times.npy`, `trajectory.npy` and "
    << "`summary.json`.\n"
    << "- `engines.json`: how springcheck runs it (the command and its placeholders).\n"
    << "- `tolerances.json`: the checks your CI gates on, each with the reason for its bound.\n\n"
    << "The protocol, every mysim integrator's exact update rule and the metrics: "
    << "`docs/external-engines.md` in springcheck's documentation; `springcheck list` names the "
    << "engines, integrators, metrics and scenes.\n";
  return s.str();
}

int init(const std::string& dir, const std::string& name) {
  // The name as an engines file takes it (letters, digits, ._-), and not a built-in engine's.
  if (auto parsed = parseEnginesFile(enginesFile(name).dump(), "--name"); !parsed) {
    std::cerr << "error: " << parsed.error() << '\n';
    return kBadInput;
  }
  if (EngineRegistry().find(name)) {
    std::cerr << "error: --name: '" << name << "' is a built-in engine; choose another name\n";
    return kBadInput;
  }
  std::error_code ec;
  if (fs::exists(dir, ec) && !(fs::is_directory(dir, ec) && fs::is_empty(dir, ec))) {
    std::cerr << "error: " << dir
              << ": exists and is not an empty folder; engine init writes only into a new or "
                 "empty one (nothing was changed)\n";
    return kBadInput;
  }
  const std::string example = dataFile("examples/external/pysim.py");
  std::ifstream in(example);
  if (!in) {
    std::cerr << "error: the example engine " << example
              << " is missing (set SPRINGCHECK_DATA_DIR to the folder holding examples/)\n";
    return kFailure;
  }
  std::ostringstream engine;
  engine << in.rdbuf();
  fs::create_directories(dir, ec);
  if (ec) {
    std::cerr << "error: cannot create " << dir << ": " << ec.message() << '\n';
    return kFailure;
  }
  const std::vector<std::pair<std::string, std::string>> files = {
      {name + ".py", engine.str()},
      {"engines.json", jsonText(enginesFile(name), 2) + "\n"},
      {"tolerances.json", jsonText(tolerancesFile(name), 2) + "\n"},
      {"README.md", readme(dir, name)}};
  for (const auto& [file, text] : files) {
    const std::string path = (fs::path(dir) / file).string();
    if (auto written = writeFileAtomically(path, [&](std::ostream& out) { out << text; });
        !written) {
      std::cerr << "error: " << written.error() << '\n';
      return kFailure;
    }
  }
  fs::permissions(fs::path(dir) / (name + ".py"), fs::perms::owner_exec | fs::perms::group_exec |
                                                      fs::perms::others_exec,
                  fs::perm_options::add, ec);
  std::cout << "engine '" << name << "' written to " << dir << ": " << name
            << ".py, engines.json, tolerances.json, README.md\n"
            << "next: springcheck gate --tolerances " << dir << "/tolerances.json\n"
            << "      " << suiteCommand(dir, name) << '\n';
  return kOk;
}

}  // namespace

void addEngineCommand(CLI::App& app, int& exit_code) {
  CLI::App* engine = app.add_subcommand("engine", "Your own simulator as an engine: engine init");
  engine->require_subcommand(1);
  auto dir = std::make_shared<std::string>();
  auto name = std::make_shared<std::string>("myengine");
  CLI::App* cmd = engine->add_subcommand(
      "init", "Write a runnable engine skeleton (Python, symplectic Euler), its engines file and "
              "a tolerances file it passes, into a new folder");
  cmd->add_option("dir", *dir, "The folder to create (new or empty)")->required();
  cmd->add_option("--name", *name, "The engine's name: lower-case letters, digits, '.', '_', '-'")
      ->capture_default_str();
  cmd->callback([dir, name, &exit_code] { exit_code = init(*dir, *name); });
}

}  // namespace springcheck
