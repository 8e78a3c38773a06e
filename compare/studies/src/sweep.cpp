#include "compare/studies/sweep.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "compare/io/atomic_file.h"
#include "compare/io/csv.h"
#include "compare/metrics/closed_form.h"
#include "compare/metrics/run_metrics.h"
#include "mysim/json_input.h"
#include "mysim/thread_budget.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string number(double v) {
  std::ostringstream out;
  out.precision(10);
  out << v;
  return out.str();
}

// True when `interval` is a whole multiple of `dt` (to 1e-9 relative).
bool multipleOf(double interval, double dt) {
  const double ratio = interval / dt;
  return std::abs(ratio - std::round(ratio)) < 1e-9 * ratio;
}

constexpr const char* kSchema = "docs/sweeps.md";

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
    auto canonical = mysim::canonicalIntegratorName(name);
    if (!canonical) throw FieldError{"integrators", canonical.error()};
    s.integrators.push_back(*canonical);
  }
  s.dts = top.positiveList("dt");
  if (top.has("stiffness_scale")) s.stiffness_scales = top.positiveList("stiffness_scale");
  if (top.has("tolerance")) s.tolerances = top.positiveList("tolerance");
  if (top.has("duration")) s.duration = top.positive("duration");
  s.sample_interval =
      top.positive("sample_interval", *std::max_element(s.dts.begin(), s.dts.end()));
  for (std::size_t k = 0; k < s.dts.size(); ++k) {
    if (!multipleOf(s.sample_interval, s.dts[k])) {
      throw FieldError{"sample_interval", number(s.sample_interval) +
                                              " s is not a multiple of dt " + number(s.dts[k]) +
                                              " s (frames of all runs must line up)"};
    }
    // Every scene's run (or the spec's duration) must hold at least one step.
    for (const auto& [path, scene] : s.loaded) {
      const double duration = s.duration.value_or(scene.duration);
      if (s.dts[k] > duration) {
        throw FieldError{"dt[" + std::to_string(k) + "]",
                         "a step no longer than the duration (" + number(s.dts[k]) + " s > " +
                             number(duration) + " s of " + path + ")"};
      }
    }
  }
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
    r.refuseUnknown(kSchema);
  } else {
    mysim::failField("reference",
                     "\"closed_form\", \"self\", {\"integrator\": NAME, \"refine\": N} or "
                     "{\"self\": true, \"refine\": N}",
                     ref);
  }
  top.refuseUnknown(kSchema);
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
          const mysim::IntegratorInfo* info = mysim::findIntegrator(integrator);
          const std::vector<double> tolerances = info && info->adaptive() && !spec.tolerances.empty()
                                                     ? spec.tolerances
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

std::expected<CaseRun, std::string> caseRun(const SweepSpec& spec, const SweepCase& c) {
  const auto cached = spec.loaded.find(c.scene);
  if (cached == spec.loaded.end()) {
    return std::unexpected(spec.source + ": scene " + c.scene + " is not one of the spec's");
  }
  CaseRun run{cached->second, mysim::buildModel(cached->second), runConfig(cached->second)};
  if (c.integrator != "-") run.config.integrator.name = c.integrator;
  run.config.run.dt = c.dt;
  if (spec.duration) run.config.run.duration = *spec.duration;
  run.config.run.sample_interval = spec.sample_interval;
  if (c.tolerance > 0)
    run.config.integrator.abs_tolerance = run.config.integrator.rel_tolerance = c.tolerance;
  mysim::scaleStiffness(run.model, c.stiffness_scale);
  return run;
}

std::size_t sweepColumn(std::string_view name) {
  const auto& cols = sweepColumns();
  return static_cast<std::size_t>(std::find(cols.begin(), cols.end(), name) - cols.begin());
}

const std::vector<std::string>& sweepColumns() {
  static const std::vector<std::string> columns = {"case_id",
                                                   "scene",
                                                   "engine",
                                                   "integrator",
                                                   "dt",
                                                   "stiffness_scale",
                                                   "tolerance",
                                                   "status",
                                                   "blowup_time",
                                                   "blowup_check",
                                                   "wall_seconds",
                                                   "wall_median_seconds",
                                                   "realtime_factor",
                                                   "repeats",
                                                   "threads",
                                                   "jobs",
                                                   "load_average",
                                                   "steps",
                                                   "derivative_evaluations",
                                                   "accepted_steps",
                                                   "rejected_steps",
                                                   "linear_iterations",
                                                   "reference",
                                                   "error",
                                                   "final_error",
                                                   "energy_drift_max",
                                                   "energy_rise",
                                                   "max_strain",
                                                   "linear_momentum_drift",
                                                   "angular_momentum_drift",
                                                   "note"};
  return columns;
}

namespace {

constexpr int kParameterColumns = 7;  // case_id .. tolerance

// The run a case is measured against: the spec's converged run per scene and stiffness, or
// (reference_self) the case's own engine, integrator and tolerance at the finest step / refine.
SweepCase referenceCase(const SweepSpec& spec, const SweepCase& c) {
  const double step = *std::min_element(spec.dts.begin(), spec.dts.end()) / spec.reference_refine;
  if (spec.reference_self) {
    return {-1, c.scene, c.engine, c.integrator, step, c.stiffness_scale, c.tolerance};
  }
  return {-1, c.scene, "mysim", spec.reference_integrator, step, c.stiffness_scale, 0.0};
}

using ReferenceKey = std::tuple<std::string, double, std::string, std::string, double>;
ReferenceKey referenceKey(const SweepCase& reference) {
  return {reference.scene, reference.stiffness_scale, reference.engine, reference.integrator,
          reference.tolerance};
}

// The machine's 1-minute load average (0 where there is no /proc/loadavg).
double loadAverage() {
  std::ifstream in("/proc/loadavg");
  double load = 0.0;
  in >> load;
  return load;
}

SweepRow runCase(
    const EngineRegistry& registry, const SweepSpec& spec, const SweepCase& c,
    const std::map<ReferenceKey, std::expected<mysim::RunRecord, std::string>>& references,
    const SweepOptions& options) {
  SweepRow row = {std::to_string(c.id),
                  c.scene,
                  c.engine,
                  c.integrator,
                  number(c.dt),
                  number(c.stiffness_scale),
                  c.tolerance > 0 ? number(c.tolerance) : ""};
  row.resize(sweepColumns().size());
  auto set = [&](const std::string& column, const std::string& value) {
    row[sweepColumn(column)] = value;
  };
  auto run = caseRun(spec, c);
  if (!run) {
    set("status", "refused");
    set("note", (run.error()));
    return row;
  }
  // The first round: `jobs` cases at a time, each on its share of the cores.
  run->config.run.threads = std::max(1, mysim::availableCores() / std::max(1, options.jobs));
  run->config.run.follow_load = !options.fixed_threads;
  set("repeats", "1");  // the timing rounds replace this
  set("jobs", std::to_string(options.jobs));
  set("load_average", number(loadAverage()));
  auto record = registry.run(c.engine, run->model, run->config);
  if (!record) {
    set("status", record.error().kind == EngineError::Kind::Failed ? "failed" : "refused");
    set("note", (record.error().message));
    return row;
  }
  const mysim::RunRecord& r = *record;
  set("status", r.status());
  if (r.blowup) {
    set("blowup_time", number(r.blowup->time));
    set("blowup_check", r.blowup->check);
  }
  set("wall_seconds", number(r.wall_seconds));
  set("wall_median_seconds", number(r.wall_median_seconds));
  set("realtime_factor", number(r.realtimeFactor()));
  set("threads", std::to_string(r.threads));
  set("steps", std::to_string(r.steps));
  set("derivative_evaluations", std::to_string(r.counts.derivative_evaluations));
  set("accepted_steps", std::to_string(r.counts.accepted));
  set("rejected_steps", std::to_string(r.counts.rejected));
  set("linear_iterations", std::to_string(r.counts.linear_iterations));
  // The metrics of compare and the gate, computed where they are defined (run_metrics.h).
  const EngineMetrics metrics = engineMetrics(run->scene, run->model, {c.engine, r});
  auto setMetric = [&](const std::string& column, const char* metric) {
    if (auto v = metricValue(metrics, metric)) set(column, number(*v));
  };
  if (!r.energies.empty()) {
    setMetric("energy_drift_max", "energy_drift_max");
    setMetric("energy_rise", "energy_rise");
  }
  if (!run->model.isCircle()) setMetric("max_strain", "max_strain");
  setMetric("linear_momentum_drift", "linear_momentum_drift");
  setMetric("angular_momentum_drift", "angular_momentum_drift");
  set("note", ([&] {
        std::string notes;
        for (const std::string& n : r.notes) notes += (notes.empty() ? "" : "; ") + n;
        return notes;
      }()));
  if (r.blowup) return row;  // errors of a blown-up run mean nothing
  if (spec.reference_closed_form) {
    if (const auto& cf = metrics.closed_form) {
      set("reference", "closed_form: " + cf->quantity);
      set("error", number(cf->error));
      set("final_error", number(cf->error));
    }
  } else {
    const auto it = references.find(referenceKey(referenceCase(spec, c)));
    const std::string label =
        (spec.reference_self ? std::string("self") : spec.reference_integrator) + " at dt/" +
        std::to_string(spec.reference_refine);
    if (it != references.end() && !it->second) {
      set("note", row[sweepColumn("note")] + (row[sweepColumn("note")].empty() ? "" : "; ") +
                      "no " + label + " reference: " + it->second.error());
    } else if (it != references.end()) {
      if (auto d = trajectoryDistance(r, *it->second)) {
        set("reference", label);
        set("error", number(d->max_rms));
        set("final_error", number(d->last_rms));
      }
    }
  }
  return row;
}

std::string header() { return csvLine(sweepColumns()); }

void retimeRows(const EngineRegistry& registry, const SweepSpec& spec,
                const std::vector<SweepCase>& cases, const SweepOptions& options,
                std::vector<SweepRow>& rows) {
  // With jobs == 1 the first round was timed alone: it is one of the repeats.
  const bool first_round_counts = options.jobs <= 1;
  const int rounds = first_round_counts ? options.repeats - 1 : options.repeats;
  if (options.repeats <= 1) return;
  std::map<int, SweepRow*> row_of;
  for (SweepRow& row : rows) row_of[std::stoi(row[0])] = &row;
  std::vector<const SweepCase*> timed;  // the cases that ran (a refusal has no time)
  for (const SweepCase& c : cases) {
    if (!row_of.at(c.id)->at(sweepColumn("wall_seconds")).empty()) timed.push_back(&c);
  }
  std::vector<std::vector<double>> walls(timed.size());
  std::vector<int> threads(timed.size(), 1);
  for (std::size_t k = 0; first_round_counts && k < timed.size(); ++k) {
    walls[k].push_back(std::stod(row_of[timed[k]->id]->at(sweepColumn("wall_seconds"))));
    threads[k] = std::stoi(row_of[timed[k]->id]->at(sweepColumn("threads")));
  }
  const int total = rounds * static_cast<int>(timed.size());
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t k = 0; k < timed.size(); ++k) {
      auto run = caseRun(spec, *timed[k]);
      if (!run) continue;
      run->config.run.threads = options.threads;
      run->config.run.follow_load = !options.fixed_threads;
      auto record = registry.run(timed[k]->engine, run->model, run->config);
      if (record) {
        walls[k].push_back(record->wall_seconds);
        threads[k] = std::max(threads[k], record->threads);
      }
      if (options.timing_progress) {
        options.timing_progress(round * static_cast<int>(timed.size()) + static_cast<int>(k) + 1,
                                total);
      }
    }
  }
  for (std::size_t k = 0; k < timed.size(); ++k) {
    if (walls[k].empty()) continue;  // no timing run succeeded: the first round's time stays
    SweepRow& row = *row_of[timed[k]->id];
    const RepeatTimes times = repeatTimes(walls[k]);
    const double simulated = std::stod(row[sweepColumn("steps")]) * timed[k]->dt;
    row[sweepColumn("wall_seconds")] = number(times.fastest);
    row[sweepColumn("wall_median_seconds")] = number(times.median);
    row[sweepColumn("realtime_factor")] = number(simulated / times.fastest);
    row[sweepColumn("repeats")] = std::to_string(walls[k].size());
    row[sweepColumn("threads")] = std::to_string(threads[k]);
    row[sweepColumn("jobs")] = "1";  // timed one at a time
  }
}

std::expected<void, std::string> writeSorted(const std::string& path, std::vector<SweepRow> rows) {
  std::sort(rows.begin(), rows.end(),
            [](const SweepRow& a, const SweepRow& b) { return std::stoi(a[0]) < std::stoi(b[0]); });
  return writeFileAtomically(path, [&](std::ostream& out) {
    out << header() << '\n';
    for (const SweepRow& row : rows) out << csvLine(row) << '\n';
  });
}

// Rows of a table or a journal: whole lines only (a last line without its line break was cut
// short and is dropped, so its case runs again), with every column and a numeric case id.
std::vector<SweepRow> readRows(std::istream& in) {
  std::vector<SweepRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (in.eof()) break;  // no line break after it: cut short
    auto row = parseCsvLine(line);
    if (!row || row->size() != sweepColumns().size()) continue;
    if ((*row)[0].empty() || (*row)[0].find_first_not_of("0123456789") != std::string::npos) {
      continue;
    }
    rows.push_back(std::move(*row));
  }
  return rows;
}

// The journal beside a table: rows appended the moment their case is done, so an interrupted
// sweep loses only the runs in flight. The table itself is only ever replaced whole.
std::string journalOf(const std::string& table) { return table + ".partial"; }

}  // namespace

std::expected<std::vector<SweepRow>, std::string> readSweepTable(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::unexpected(path + ": cannot open");
  std::string line;
  if (!std::getline(in, line) || line != header()) {
    return std::unexpected(path + ": not a sweep table (header differs from: " + header() + ")");
  }
  return readRows(in);
}

std::expected<int, std::string> runSweep(const EngineRegistry& registry, const SweepSpec& spec,
                                         const std::string& out_csv, const SweepOptions& options) {
  // Rows so far: the table's, then the journal's (newer: a run interrupted after them), by id.
  const std::string journal = journalOf(out_csv);
  std::map<int, SweepRow> by_id;
  bool journal_rows = false;
  if (options.resume && fs::exists(out_csv)) {
    auto existing = readSweepTable(out_csv);
    if (!existing) return std::unexpected(existing.error());
    for (SweepRow& row : *existing) by_id[std::stoi(row[0])] = std::move(row);
  }
  if (options.resume && fs::exists(journal)) {
    std::ifstream in(journal);
    for (SweepRow& row : readRows(in)) {
      by_id[std::stoi(row[0])] = std::move(row);
      journal_rows = true;
    }
  }
  std::vector<SweepRow> kept;
  std::set<int> done;
  for (auto& [id, row] : by_id) {
    done.insert(id);
    kept.push_back(std::move(row));
  }
  std::vector<SweepCase> todo;
  for (const SweepCase& c : expandSweep(spec)) {
    if (c.id % options.shard_count != options.shard_index || done.count(c.id)) continue;
    todo.push_back(c);
  }
  // The journal's rows go into the table before the journal starts over, so none is lost; the
  // table is otherwise left as it is until the sweep ends (a --fresh sweep that is interrupted
  // leaves the previous table).
  if (journal_rows) {
    if (auto written = writeSorted(out_csv, kept); !written) {
      return std::unexpected(written.error());
    }
  }

  // The references, each run once, before the cases that need them.
  std::map<ReferenceKey, std::expected<mysim::RunRecord, std::string>> references;
  if (!spec.reference_closed_form) {
    std::map<ReferenceKey, SweepCase> wanted;
    for (const SweepCase& c : todo) {
      const SweepCase ref = referenceCase(spec, c);
      wanted.emplace(referenceKey(ref), ref);
    }
    std::vector<SweepCase> list;
    for (const auto& [key, ref] : wanted) list.push_back(ref);
    std::vector<std::expected<mysim::RunRecord, std::string>> results(list.size());
    std::atomic<std::size_t> next{0};
    auto work = [&] {
      for (std::size_t k; (k = next++) < list.size();) {
        auto run = caseRun(spec, list[k]);
        if (!run) {
          results[k] = std::unexpected(run.error());
          continue;
        }
        auto record = registry.run(list[k].engine, run->model, run->config);
        if (!record) {
          results[k] = std::unexpected(record.error().message);
        } else if (record->blowup) {
          results[k] = std::unexpected("it blew up (" + record->blowup->check + ")");
        } else {
          results[k] = std::move(*record);
        }
      }
    };
    std::vector<std::thread> threads;
    for (int t = 0; t < std::max(1, options.jobs); ++t) threads.emplace_back(work);
    for (std::thread& t : threads) t.join();
    for (std::size_t k = 0; k < list.size(); ++k) {
      // The spec's one converged reference must exist; an engine's own (self) may be missing,
      // which its rows then say.
      if (!results[k] && !spec.reference_self) {
        return std::unexpected("reference run of " + list[k].scene + ": " + results[k].error());
      }
      references.emplace(referenceKey(list[k]), std::move(results[k]));
    }
  }

  std::ofstream out(journal, std::ios::trunc);
  if (!out) return std::unexpected("cannot write " + journal);
  std::mutex mutex;
  std::atomic<std::size_t> next{0};
  int finished = 0;
  auto work = [&] {
    for (std::size_t k; (k = next++) < todo.size();) {
      SweepRow row = runCase(registry, spec, todo[k], references, options);
      std::lock_guard<std::mutex> lock(mutex);
      out << csvLine(row) << '\n' << std::flush;
      kept.push_back(std::move(row));
      ++finished;
      if (options.progress) options.progress(finished, static_cast<int>(todo.size()));
    }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < std::max(1, options.jobs); ++t) threads.emplace_back(work);
  for (std::thread& t : threads) t.join();
  out.close();
  // Timing rounds: the cases of this sweep again, one at a time, round after round rather than
  // back to back, so a slow spell of the machine (seconds long on a shared VM) costs one sample of
  // many cases instead of every sample of one.
  retimeRows(registry, spec, todo, options, kept);
  if (auto written = writeSorted(out_csv, kept); !written) return std::unexpected(written.error());
  std::error_code ec;
  fs::remove(journal, ec);
  return finished;
}

std::expected<int, std::string> mergeSweepTables(const std::vector<std::string>& inputs,
                                                 const std::string& out_csv) {
  std::map<int, SweepRow> rows;
  for (const std::string& input : inputs) {
    auto table = readSweepTable(input);
    if (!table) return std::unexpected(table.error());
    for (SweepRow& row : *table) {
      const int id = std::stoi(row[0]);
      auto [it, inserted] = rows.emplace(id, row);
      if (!inserted &&
          !std::equal(row.begin(), row.begin() + kParameterColumns, it->second.begin())) {
        return std::unexpected(
            input + ": case " + row[0] +
            " has other parameters than in an earlier table: not shards of one sweep");
      }
    }
  }
  std::vector<SweepRow> all;
  for (auto& [id, row] : rows) all.push_back(std::move(row));
  if (auto written = writeSorted(out_csv, all); !written) return std::unexpected(written.error());
  return static_cast<int>(all.size());
}

}  // namespace springcheck
