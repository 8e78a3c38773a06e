#include "compare/studies/sweep.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>

#include "compare/metrics/run_metrics.h"
#include "compare/studies/parallel_jobs.h"
#include "mysim/thread_budget.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;

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
using References = std::map<ReferenceKey, std::expected<mysim::RunRecord, std::string>>;

// The machine's 1-minute load average (0 where there is no /proc/loadavg).
double loadAverage() {
  std::ifstream in("/proc/loadavg");
  double load = 0.0;
  in >> load;
  return load;
}

// Every reference the cases need, each run once, before them.
std::expected<References, std::string> runReferences(const EngineRegistry& registry,
                                                     const SweepSpec& spec,
                                                     const std::vector<SweepCase>& todo, int jobs) {
  References references;
  if (spec.reference_closed_form) return references;
  std::map<ReferenceKey, SweepCase> wanted;
  for (const SweepCase& c : todo) {
    const SweepCase ref = referenceCase(spec, c);
    wanted.emplace(referenceKey(ref), ref);
  }
  std::vector<SweepCase> list;
  for (const auto& [key, ref] : wanted) list.push_back(ref);
  std::vector<std::expected<mysim::RunRecord, std::string>> results(list.size());
  forEachInParallel(list.size(), jobs, [&](std::size_t k) {
    auto run = caseRun(spec, list[k]);
    if (!run) {
      results[k] = std::unexpected(run.error());
      return;
    }
    auto record = registry.run(list[k].engine, run->model, run->config);
    if (!record) {
      results[k] = std::unexpected(record.error().message);
    } else if (record->blowup) {
      results[k] = std::unexpected("it blew up (" + record->blowup->check + ")");
    } else {
      results[k] = std::move(*record);
    }
  });
  for (std::size_t k = 0; k < list.size(); ++k) {
    // The spec's one converged reference must exist; an engine's own (self) may be missing,
    // which its rows then say.
    if (!results[k] && !spec.reference_self) {
      return std::unexpected("reference run of " + list[k].scene + ": " + results[k].error());
    }
    references.emplace(referenceKey(list[k]), std::move(results[k]));
  }
  return references;
}

void addNote(SweepRow& row, const std::string& note) {
  row.note += (row.note.empty() ? "" : "; ") + note;
}

// The run's status, cost and the metrics of compare and the gate (run_metrics.h), each once.
EngineMetrics recordRun(SweepRow& row, const mysim::Model& model, const mysim::RunRecord& r) {
  row.status = r.status();
  if (r.blowup) {
    row.blowup_time = r.blowup->time;
    row.blowup_check = r.blowup->check;
  }
  row.wall_seconds = r.wall_seconds;
  row.wall_median_seconds = r.wall_median_seconds;
  row.realtime_factor = r.realtimeFactor();
  if (r.threads > 0) row.threads = r.threads;  // 0: unknown (an external engine)
  row.steps = r.steps;
  if (r.counts.derivative_evaluations >= 0) row.derivative_evaluations = r.counts.derivative_evaluations;
  row.accepted_steps = r.counts.accepted;
  row.rejected_steps = r.counts.rejected;
  row.linear_iterations = r.counts.linear_iterations;
  row.setup_seconds = r.counts.setup_seconds;
  if (r.precision_floor > 0) row.precision_floor = r.precision_floor;
  EngineMetrics metrics = engineMetrics(model, {row.c.engine, r});
  if (!r.energies.empty()) {
    row.energy_drift_max = metricValue(metrics, "energy_drift_max");
    row.energy_rise = metricValue(metrics, "energy_rise");
  }
  if (!model.isCircle()) row.max_strain = metricValue(metrics, "max_strain");
  row.linear_momentum_drift = metricValue(metrics, "linear_momentum_drift");
  row.angular_momentum_drift = metricValue(metrics, "angular_momentum_drift");
  row.quantities = settledQuantities(model, {row.c.engine, r}, metrics);
  for (const std::string& n : r.notes) addNote(row, n);
  return metrics;
}

// A float32 engine's error within ten times its floor is its round-off (grown over the steps),
// not integration error: say so where the number is read.
void notePrecisionFloor(SweepRow& row) {
  if (row.error && row.precision_floor && *row.error < 10 * *row.precision_floor) {
    addNote(row, "error within 10x the float32 precision floor: round-off, not integration error");
  }
}

// The case's error against the spec's reference: the closed form, or its reference run.
void measureError(SweepRow& row, const SweepSpec& spec, const EngineMetrics& metrics,
                  const mysim::RunRecord& r, const References& references) {
  if (spec.reference_closed_form) {
    if (const auto& cf = metrics.closed_form) {
      row.reference = "closed_form: " + cf->quantity;
      row.error = row.final_error = cf->error;
    }
    return;
  }
  const auto it = references.find(referenceKey(referenceCase(spec, row.c)));
  const std::string label =
      (spec.reference_self ? std::string("self") : spec.reference_integrator) + " at dt/" +
      std::to_string(spec.reference_refine);
  if (it == references.end()) return;
  if (!it->second) {
    addNote(row, "no " + label + " reference: " + it->second.error());
  } else if (auto d = trajectoryDistance(r, *it->second)) {
    row.reference = label;
    row.error = d->max_rms;
    row.final_error = d->last_rms;
  }
}

// One case, in the first round: `jobs` cases at a time, each on its share of the cores. Keeps
// the case's run (its model) for the timing rounds.
SweepRow runCase(const EngineRegistry& registry, const SweepSpec& spec, const SweepCase& c,
                 const References& references, const SweepOptions& options, int jobs,
                 std::optional<CaseRun>& kept) {
  SweepRow row;
  row.c = c;
  auto run = caseRun(spec, c);
  if (!run) {
    row.status = "refused";
    row.note = run.error();
    return row;
  }
  run->config.run.threads = std::max(1, mysim::availableCores() / jobs);
  run->config.run.follow_load = !options.fixed_threads;
  row.repeats = 1;  // the timing rounds replace this
  row.jobs = jobs;
  row.load_average = loadAverage();
  auto record = registry.run(c.engine, run->model, run->config);
  if (!record) {
    row.status = record.error().kind == EngineError::Kind::Failed ? "failed" : "refused";
    row.note = record.error().message;
    return row;
  }
  const EngineMetrics metrics = recordRun(row, run->model, *record);
  if (!record->blowup) measureError(row, spec, metrics, *record, references);  // else meaningless
  notePrecisionFloor(row);
  if (options.repeats > 1) kept = std::move(*run);  // for the timing rounds
  return row;
}

// Timing rounds: the cases of this sweep again, one at a time, round after round rather than
// back to back, so a slow spell of the machine (seconds long on a shared VM) costs one sample of
// many cases instead of every sample of one. Each case's model was built once, in runCase.
void retimeRows(const EngineRegistry& registry, std::vector<std::optional<CaseRun>>& runs,
                const SweepOptions& options, int jobs, std::vector<SweepRow*>& rows) {
  if (options.repeats <= 1) return;
  // With one job the first round was timed alone: it is one of the repeats.
  const bool first_round_counts = jobs <= 1;
  const int rounds = first_round_counts ? options.repeats - 1 : options.repeats;
  std::vector<std::size_t> timed;  // the cases that ran (a refusal has no time)
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (runs[k] && rows[k]->wall_seconds) timed.push_back(k);
  }
  std::vector<std::vector<double>> walls(rows.size());
  std::vector<long> threads(rows.size(), 1);
  for (std::size_t k : timed) {
    if (first_round_counts) walls[k].push_back(*rows[k]->wall_seconds);
    if (first_round_counts) threads[k] = *rows[k]->threads;
    runs[k]->config.run.threads = options.threads;
    runs[k]->config.run.follow_load = !options.fixed_threads;
  }
  const int total = rounds * static_cast<int>(timed.size());
  int done = 0;
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t k : timed) {
      auto record = registry.run(rows[k]->c.engine, runs[k]->model, runs[k]->config);
      if (record) {
        walls[k].push_back(record->wall_seconds);
        threads[k] = std::max<long>(threads[k], record->threads);
      }
      if (options.timing_progress) options.timing_progress(++done, total);
    }
  }
  for (std::size_t k : timed) {
    if (walls[k].empty()) continue;  // no timing run succeeded: the first round's time stays
    SweepRow& row = *rows[k];
    const RepeatTimes times = repeatTimes(walls[k]);
    row.wall_seconds = times.fastest;
    row.wall_median_seconds = times.median;
    row.realtime_factor = static_cast<double>(*row.steps) * row.c.dt / times.fastest;
    row.repeats = static_cast<long>(walls[k].size());
    if (threads[k] > 0) row.threads = threads[k];
    row.jobs = 1;  // timed one at a time
  }
}

// The journal beside a table: rows appended the moment their case is done, so an interrupted
// sweep loses only the runs in flight. The table itself is only ever replaced whole.
std::string journalOf(const std::string& table) { return table + ".partial"; }

// Rows so far: the table's, then the journal's (newer: a run interrupted after them), by id.
// The journal's go into the table before the journal starts over, so none is lost.
std::expected<std::map<int, SweepRow>, std::string> rowsSoFar(const std::string& out_csv,
                                                              bool resume) {
  std::map<int, SweepRow> by_id;
  for (const std::string& path : {out_csv, journalOf(out_csv)}) {  // a FIFO would block
    std::error_code ec;
    if (fs::exists(path, ec) && !fs::is_regular_file(path, ec)) {
      return std::unexpected(path + ": not a regular file (expected a sweep table, .csv)");
    }
  }
  if (!resume) return by_id;
  if (fs::exists(out_csv)) {
    auto existing = readSweepTable(out_csv);
    if (!existing) return std::unexpected(existing.error());
    for (SweepRow& row : *existing) by_id[row.c.id] = std::move(row);
  }
  const std::vector<SweepRow> journal = readSweepJournal(journalOf(out_csv));
  for (const SweepRow& row : journal) by_id[row.c.id] = row;
  if (!journal.empty()) {
    std::vector<SweepRow> all;
    for (const auto& [id, row] : by_id) all.push_back(row);
    if (auto written = writeSweepTable(out_csv, all); !written) {
      return std::unexpected(written.error());
    }
  }
  return by_id;
}

// This shard's cases that have no row yet. A row is its case's only if every parameter column
// agrees (the table, or its journal, may come from another spec): else the table is not this
// sweep's, and that is the error.
std::expected<std::vector<SweepCase>, std::string> casesToRun(const SweepSpec& spec,
                                                              const std::map<int, SweepRow>& so_far,
                                                              const std::string& out_csv,
                                                              const SweepOptions& options) {
  std::vector<SweepCase> todo;
  for (const SweepCase& c : expandSweep(spec)) {
    if (c.id % options.shard_count != options.shard_index) continue;
    auto done = so_far.find(c.id);
    if (done == so_far.end()) {
      todo.push_back(c);
      continue;
    }
    SweepRow wanted;
    wanted.c = c;
    const auto mine = sweepRowFields(wanted), theirs = sweepRowFields(done->second);
    for (int k = 0; k < kSweepParameterColumns; ++k) {
      if (mine[k] != theirs[k]) {
        return std::unexpected(out_csv + ": case " + std::to_string(c.id) + " has " +
                               sweepColumns()[k] + " " + theirs[k] + " in the table but " +
                               mine[k] + " in " + spec.source +
                               ": the table is another sweep's (--fresh starts it over, or "
                               "give another --out)");
      }
    }
  }
  return todo;
}

}  // namespace

// One sweep writes a table at a time: a second one would read the first's journal as its own
// rows and each would write the table over the other's. An advisory lock on TABLE.lock, held for
// the sweep's life and released by the kernel however it ends; the file itself stays (removing it
// would let a third sweep lock a new file while the second holds the old one).
class TableLock {
 public:
  explicit TableLock(const std::string& table)
      : fd_(::open((table + ".lock").c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644)) {}
  ~TableLock() {
    if (fd_ >= 0) ::close(fd_);
  }
  TableLock(const TableLock&) = delete;
  TableLock& operator=(const TableLock&) = delete;
  bool acquire() { return fd_ >= 0 && ::flock(fd_, LOCK_EX | LOCK_NB) == 0; }

 private:
  int fd_;
};

std::expected<int, std::string> runSweep(const EngineRegistry& registry, const SweepSpec& spec,
                                         const std::string& out_csv, const SweepOptions& options) {
  TableLock lock(out_csv);
  if (!lock.acquire()) {
    return std::unexpected(out_csv + ": another sweep is writing this table now (it holds " +
                           out_csv + ".lock); wait for it to finish, or give another --out");
  }
  auto so_far = rowsSoFar(out_csv, options.resume);
  if (!so_far) return std::unexpected(so_far.error());
  auto cases = casesToRun(spec, *so_far, out_csv, options);
  if (!cases) return std::unexpected(cases.error());
  const std::vector<SweepCase>& todo = *cases;
  std::vector<SweepRow> kept;
  for (auto& [id, row] : *so_far) kept.push_back(std::move(row));
  const int jobs = jobCount(options.jobs, todo.size());
  auto references = runReferences(registry, spec, todo, jobs);
  if (!references) return std::unexpected(references.error());

  const std::string journal = journalOf(out_csv);
  std::ofstream out(journal, std::ios::trunc);
  if (!out) return std::unexpected("cannot write " + journal);
  std::vector<SweepRow> rows(todo.size());
  std::vector<std::optional<CaseRun>> runs(todo.size());
  std::mutex mutex;
  int finished = 0;
  const int case_jobs = options.repeats > 1 ? 1 : jobs;  // timed: the first round is a repeat
  forEachInParallel(todo.size(), case_jobs, [&](std::size_t k) {
    rows[k] = runCase(registry, spec, todo[k], *references, options, case_jobs, runs[k]);
    std::lock_guard<std::mutex> lock(mutex);
    out << sweepLine(rows[k]) << '\n' << std::flush;
    ++finished;
    if (options.progress) options.progress(finished, static_cast<int>(todo.size()));
  });
  out.close();
  std::vector<SweepRow*> row_pointers;
  for (SweepRow& row : rows) row_pointers.push_back(&row);
  retimeRows(registry, runs, options, case_jobs, row_pointers);
  for (SweepRow& row : rows) kept.push_back(std::move(row));
  if (auto written = writeSweepTable(out_csv, kept); !written) {
    return std::unexpected(written.error());
  }
  std::error_code ec;
  fs::remove(journal, ec);
  return finished;
}

}  // namespace springcheck
