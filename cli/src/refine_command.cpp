// springcheck refine: one material scene at several resolutions in each engine, and how each
// quantity converges (compare/studies/refinement.h).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include "commands.h"
#include "compare/io/atomic_file.h"
#include "compare/io/invocation.h"
#include "compare/io/text_format.h"
#include "compare/io/whole_folder.h"
#include "compare/studies/refine_study.h"

namespace springcheck {
namespace {

struct RefineOptions {
  std::vector<std::string> scenes;
  std::vector<int> resolutions{8, 16, 32};
  std::string engines = "mysim";
  std::string out = "out/refine";
  std::vector<std::string> engines_files;
  Timing timing;
  int jobs = 0;
};

// Tables' number format (text_format.h); empty for a quantity the run does not have.
std::string number(double v) { return std::isfinite(v) ? formatNumber(v) : ""; }

// Sorts the resolutions; refuses one given twice, and says that fewer than three give no order.
bool sortedDistinct(std::vector<int>& resolutions) {
  std::sort(resolutions.begin(), resolutions.end());
  if (auto twice = std::adjacent_find(resolutions.begin(), resolutions.end());
      twice != resolutions.end()) {
    std::cerr << "error: --resolutions: " << *twice
              << " given twice; expected distinct resolutions (three or more for an order)\n";
    return false;
  }
  if (resolutions.size() < 3) {
    std::cerr << "note: --resolutions: " << resolutions.size()
              << " resolution(s): the quantities are measured, but an order and a limit need "
                 "three or more\n";
  }
  return true;
}

// Each run's line, in the table's order; a run that did not complete on stderr too.
int printRuns(const std::vector<RefineRow>& rows) {
  int failures = 0;
  for (const RefineRow& row : rows) {
    if (row.status != "ok") {
      std::cerr << row.scene << " at resolution " << row.resolution << ", " << row.engine << ": "
                << row.note << '\n';
      ++failures;
    }
    std::cout << row.scene << " (" << row.bending << ") at " << row.resolution << " cells, "
              << row.engine << ": " << row.status;
    for (const auto& [name, value] : row.values) std::cout << ", " << name << " " << number(value);
    std::cout << " (" << row.wall_seconds << " s)\n";
  }
  return failures;
}

void printEstimates(const std::vector<RefineEstimateRow>& estimates) {
  std::cout << "\nconvergence (a Richardson limit only where the evidence allows one: four or more "
               "resolutions whose last two triples agree, or three at the expected order):\n";
  for (const RefineEstimateRow& e : estimates) {
    const double vs_reference = e.finestVsReference();
    const bool quote = e.verdict.converged;
    std::cout << "  " << e.scene << " " << e.engine << " " << e.quantity << " [" << e.unit
              << "]: finest " << number(e.values.back()) << ", " << e.verdict.text
              << (quote && e.estimate.limit ? ", limit " + number(*e.estimate.limit) : "")
              << (std::isfinite(vs_reference)
                      ? ", finest vs closed form " + number(100.0 * vs_reference) + " %"
                      : "")
              << '\n';
  }
}

int refine(const RefineOptions& o) {
  const std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  RefineSettings settings;
  settings.scenes = o.scenes;
  settings.resolutions = o.resolutions;
  settings.engines = splitList(o.engines);
  settings.timing = o.timing;
  settings.jobs = o.jobs;
  // Each finished run on stderr: a refine of four scenes at 32 cells runs for minutes.
  settings.progress = [](int done, int total) { std::cerr << "refine: " << done << "/" << total << " runs done\n"; };
  if (!sortedDistinct(settings.resolutions)) return kBadInput;
  const auto rows = runRefinement(*registry, settings);
  if (!rows) {
    std::cerr << "error: " << rows.error() << '\n';
    return kBadInput;
  }
  const int failures = printRuns(*rows);
  const std::vector<RefineEstimateRow> estimates = refinementEstimates(*rows);
  printEstimates(estimates);
  static const FolderKind kind{"refinement folder",
                               {"refine.csv", "refine_estimates.csv", "refine.csv.command"}};
  auto written = writeFolderWhole(o.out, kind, [&](const std::string& staging)
                                                   -> std::expected<void, std::string> {
    for (const auto& [file, text] : {std::pair{"refine.csv", refineTableCsv(*rows)},
                                     std::pair{"refine_estimates.csv", refineEstimatesCsv(estimates)}}) {
      const std::string body = text;
      if (auto ok = writeFileAtomically(staging + "/" + file, [&](std::ostream& out) { out << body; });
          !ok) {
        return ok;
      }
    }
    return writeInvocationBeside(staging + "/refine.csv");
  });
  if (!written) {
    std::cerr << "error: " << written.error() << '\n';
    return kFailure;
  }
  std::cout << "results in " << o.out << " (refine.csv, refine_estimates.csv)\n";
  return failures > 0 ? kBlowUp : kOk;
}

}  // namespace

void addRefineCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<RefineOptions>();
  CLI::App* cmd = app.add_subcommand(
      "refine",
      "Run material scenes at several resolutions in each engine: each quantity's observed order "
      "of convergence and Richardson limit (docs/materials.md)");
  cmd->add_option("scenes", options->scenes, "Material scene files (system.material)")->required();
  cmd->add_option("--resolutions", options->resolutions,
                  "Cells across the width, three or more for an order (default 8,16,32)")
      ->delimiter(',')
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--engines", options->engines, "Engines, comma-separated")->capture_default_str();
  addEnginesFileOption(cmd, options->engines_files);
  cmd->add_option("--out", options->out, "Output directory")->capture_default_str();
  addTimingOptions(cmd, options->timing, 1);
  cmd->add_option("--jobs", options->jobs,
                  "Runs side by side (0, the default: every free core); wall times are kept with "
                  "the jobs they were measured beside, --jobs 1 times each run alone")
      ->check(CLI::Range(0, 1024));
  cmd->callback([options, &exit_code] { exit_code = refine(*options); });
}

}  // namespace springcheck
