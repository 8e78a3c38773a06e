#pragma once
// A sweep's results table: one typed row per case (numbers stay numbers until written), the one
// list of its columns, and reading, writing and merging the CSV (docs/sweeps.md).
#include <expected>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compare/metrics/settled_quantities.h"

namespace springcheck {

// One run of the grid. `id` is its place in the full grid (stable across shards and resumes).
struct SweepCase {
  int id = 0;
  std::string scene;
  std::string engine;
  std::string integrator;  // mysim's; "-" for engines that take none
  double dt = 0.0;
  double stiffness_scale = 1.0;
  double tolerance = 0.0;  // adaptive integrators: abs and rel tolerance (0: the scene's)
};

// A finished case: its parameters, how the run went, its cost and its errors. Empty optionals
// are empty cells (a refusal has no time; a blown-up run no error).
struct SweepRow {
  SweepCase c;
  std::string status;  // ok, blowup, step-limit, solver-not-converged, refused, failed
  std::optional<double> blowup_time;  // s
  std::string blowup_check;
  std::optional<double> wall_seconds, wall_median_seconds;  // of stepping, fastest and median
  std::optional<double> realtime_factor;                    // simulated s per wall s
  std::optional<long> repeats, threads, jobs;               // the timing's conditions
  std::optional<double> load_average;                       // the machine's, 1 minute
  std::optional<long> steps, derivative_evaluations, accepted_steps, rejected_steps;
  std::optional<long> linear_iterations;
  std::optional<double> setup_seconds;  // one-time set-up inside the steps (a factorisation)
  std::string reference;                     // what `error` is measured against
  std::optional<double> error, final_error;  // m (or relative, for a closed form's quantity)
  std::optional<double> precision_floor;     // m: a float32 engine's least round-off (empty: double)
  std::optional<double> energy_drift_max, energy_rise, max_strain;
  std::optional<double> linear_momentum_drift, angular_momentum_drift;
  // The settled shape's quantities (settled_quantities.h), written "name=END:EARLIER;..." in the
  // `quantities` column: what `springcheck trade` holds against the physical reference.
  SettledQuantities quantities;
  std::string note;
};

// The table's columns, in order: the header.
const std::vector<std::string>& sweepColumns();
// The first columns: a case's parameters (case_id .. tolerance).
constexpr int kSweepParameterColumns = 7;

// A row as it is written, one text per column; and back (an error names the column).
std::vector<std::string> sweepRowFields(const SweepRow& row);
[[nodiscard]] std::expected<SweepRow, std::string> sweepRowFromFields(
    const std::vector<std::string>& fields);
// One column of a row as written ("" for an unknown column).
std::string sweepField(const SweepRow& row, std::string_view column);

// Reads a results table: header check, then rows. A last line without its line break was cut
// short by an interrupted writer and is dropped (its case runs again); any other bad row is an
// error naming the line and column.
[[nodiscard]] std::expected<std::vector<SweepRow>, std::string> readSweepTable(
    const std::string& path);
// The rows of a journal (rows appended as cases finish): whole, well-formed lines only.
std::vector<SweepRow> readSweepJournal(const std::string& path);
// Writes a whole table, rows sorted by case id.
[[nodiscard]] std::expected<void, std::string> writeSweepTable(const std::string& path,
                                                               std::vector<SweepRow> rows);
std::string sweepLine(const SweepRow& row);  // one CSV line, no line ending

// Joins shard tables into one, sorted by case id; duplicate ids must agree on their parameters.
[[nodiscard]] std::expected<int, std::string> mergeSweepTables(
    const std::vector<std::string>& inputs, const std::string& out_csv);

}  // namespace springcheck
