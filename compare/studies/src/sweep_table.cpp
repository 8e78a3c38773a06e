#include "compare/studies/sweep_table.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "compare/io/atomic_file.h"
#include "compare/io/invocation.h"
#include "compare/io/csv.h"
#include "compare/io/text_format.h"

namespace springcheck {
namespace {

// Ten significant digits: what every sweep table has been written with (a value read back and
// written again is the same text).
std::string cellNumber(double v) { return formatNumber(v, 10); }

template <typename T>
bool parseNumber(const std::string& text, T& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end;
}

// One column: its name, how it is written, and how it is read back (false: not of its type).
struct Column {
  std::string name;
  std::function<std::string(const SweepRow&)> write;
  std::function<bool(SweepRow&, const std::string&)> read;
};

Column text(const char* name, std::string SweepRow::*field) {
  return {name, [field](const SweepRow& r) { return r.*field; },
          [field](SweepRow& r, const std::string& s) {
            r.*field = s;
            return true;
          }};
}

template <typename T>
Column optional(const char* name, std::optional<T> SweepRow::*field) {
  return {name,
          [field](const SweepRow& r) {
            if (!(r.*field)) return std::string();
            if constexpr (std::is_same_v<T, double>) return cellNumber(*(r.*field));
            return std::to_string(*(r.*field));
          },
          [field](SweepRow& r, const std::string& s) {
            if (s.empty()) return (r.*field).reset(), true;
            T v{};
            if (!parseNumber(s, v)) return false;
            r.*field = v;
            return true;
          }};
}

// "name=END:EARLIER" per quantity, joined by ';' (no comma: one CSV field without quotes).
std::string quantitiesText(const SettledQuantities& quantities) {
  std::string out;
  for (const auto& [name, q] : quantities) {
    out += (out.empty() ? "" : ";") + name + "=" + cellNumber(q.end) + ":" + cellNumber(q.earlier);
  }
  return out;
}

bool readQuantities(const std::string& text, SettledQuantities& quantities) {
  quantities.clear();
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t stop = text.find(';', start);
    if (stop == std::string::npos) stop = text.size();
    const std::string item = text.substr(start, stop - start);
    const std::size_t eq = item.find('='), colon = item.find(':');
    if (eq == std::string::npos || eq == 0 || colon == std::string::npos || colon < eq) return false;
    SettledQuantity q;
    if (!parseNumber(item.substr(eq + 1, colon - eq - 1), q.end) ||
        !parseNumber(item.substr(colon + 1), q.earlier)) {
      return false;
    }
    quantities[item.substr(0, eq)] = q;
    start = stop + 1;
  }
  return true;
}

const std::vector<Column>& columns() {
  using R = SweepRow;
  static const std::vector<Column> table = {
      {"case_id", [](const R& r) { return std::to_string(r.c.id); },
       [](R& r, const std::string& s) { return parseNumber(s, r.c.id) && r.c.id >= 0; }},
      {"scene", [](const R& r) { return r.c.scene; },
       [](R& r, const std::string& s) { return r.c.scene = s, true; }},
      {"engine", [](const R& r) { return r.c.engine; },
       [](R& r, const std::string& s) { return r.c.engine = s, true; }},
      {"integrator", [](const R& r) { return r.c.integrator; },
       [](R& r, const std::string& s) { return r.c.integrator = s, true; }},
      {"dt", [](const R& r) { return cellNumber(r.c.dt); },
       [](R& r, const std::string& s) { return parseNumber(s, r.c.dt); }},
      {"stiffness_scale", [](const R& r) { return cellNumber(r.c.stiffness_scale); },
       [](R& r, const std::string& s) { return parseNumber(s, r.c.stiffness_scale); }},
      {"tolerance", [](const R& r) { return r.c.tolerance > 0 ? cellNumber(r.c.tolerance) : ""; },
       [](R& r, const std::string& s) {
         r.c.tolerance = 0.0;
         return s.empty() || parseNumber(s, r.c.tolerance);
       }},
      text("status", &R::status),
      optional("blowup_time", &R::blowup_time),
      text("blowup_check", &R::blowup_check),
      optional("wall_seconds", &R::wall_seconds),
      optional("wall_median_seconds", &R::wall_median_seconds),
      optional("realtime_factor", &R::realtime_factor),
      optional("repeats", &R::repeats),
      optional("threads", &R::threads),
      optional("jobs", &R::jobs),
      optional("load_average", &R::load_average),
      optional("steps", &R::steps),
      optional("derivative_evaluations", &R::derivative_evaluations),
      optional("accepted_steps", &R::accepted_steps),
      optional("rejected_steps", &R::rejected_steps),
      optional("linear_iterations", &R::linear_iterations),
      optional("setup_seconds", &R::setup_seconds),
      text("reference", &R::reference),
      optional("error", &R::error),
      optional("final_error", &R::final_error),
      optional("precision_floor", &R::precision_floor),
      optional("energy_drift_max", &R::energy_drift_max),
      optional("energy_rise", &R::energy_rise),
      optional("max_strain", &R::max_strain),
      optional("linear_momentum_drift", &R::linear_momentum_drift),
      optional("angular_momentum_drift", &R::angular_momentum_drift),
      {"quantities", [](const R& r) { return quantitiesText(r.quantities); },
       [](R& r, const std::string& s) { return readQuantities(s, r.quantities); }},
      text("note", &R::note),
  };
  return table;
}

std::string header() { return csvLine(sweepColumns()); }

}  // namespace

const std::vector<std::string>& sweepColumns() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const Column& c : columns()) n.push_back(c.name);
    return n;
  }();
  return names;
}

std::vector<std::string> sweepRowFields(const SweepRow& row) {
  std::vector<std::string> fields;
  for (const Column& c : columns()) fields.push_back(c.write(row));
  return fields;
}

std::expected<SweepRow, std::string> sweepRowFromFields(const std::vector<std::string>& fields) {
  if (fields.size() != columns().size()) {
    return std::unexpected(std::to_string(fields.size()) + " fields, expected " +
                           std::to_string(columns().size()));
  }
  SweepRow row;
  for (std::size_t k = 0; k < fields.size(); ++k) {
    if (!columns()[k].read(row, fields[k])) {
      return std::unexpected("column " + columns()[k].name + ": '" + fields[k].substr(0, 40) +
                             "' is not of its type");
    }
  }
  // Distances: an error below zero is no error at all (recommend once ranked -5 first).
  for (auto [name, value] : {std::pair{"error", row.error}, {"final_error", row.final_error}}) {
    if (value && !(*value >= 0.0)) {
      return std::unexpected(std::string("column ") + name + ": " + std::to_string(*value) +
                             " is not a distance (expected >= 0)");
    }
  }
  return row;
}

std::string sweepField(const SweepRow& row, std::string_view column) {
  for (const Column& c : columns()) {
    if (c.name == column) return c.write(row);
  }
  return "";
}

std::string sweepLine(const SweepRow& row) { return csvLine(sweepRowFields(row)); }

std::expected<std::vector<SweepRow>, std::string> readSweepTable(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {  // a FIFO would block the reader
    return std::unexpected(path + ": not a regular file (expected a sweep table, .csv)");
  }
  std::ifstream in(path);
  if (!in) return std::unexpected(path + ": cannot open");
  std::string line;
  if (!std::getline(in, line) || line != header()) {
    return std::unexpected(path + ": not a sweep table (header differs from: " + header() + ")");
  }
  std::vector<SweepRow> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    if (in.eof()) break;  // no line break after it: cut short
    auto fields = parseCsvLine(line);
    if (!fields)
      return std::unexpected(path + ": line " + std::to_string(number) + ": unbalanced quotes");
    auto row = sweepRowFromFields(*fields);
    if (!row)
      return std::unexpected(path + ": line " + std::to_string(number) + ": " + row.error());
    rows.push_back(std::move(*row));
  }
  return rows;
}

std::vector<SweepRow> readSweepJournal(const std::string& path) {
  std::ifstream in(path);
  std::vector<SweepRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (in.eof()) break;  // cut short
    auto fields = parseCsvLine(line);
    if (!fields) continue;
    if (auto row = sweepRowFromFields(*fields)) rows.push_back(std::move(*row));
  }
  return rows;
}

std::expected<void, std::string> writeSweepTable(const std::string& path,
                                                 std::vector<SweepRow> rows) {
  std::sort(rows.begin(), rows.end(),
            [](const SweepRow& a, const SweepRow& b) { return a.c.id < b.c.id; });
  auto written = writeFileAtomically(path, [&](std::ostream& out) {
    out << header() << '\n';
    for (const SweepRow& row : rows) out << sweepLine(row) << '\n';
  });
  if (!written) return written;
  return writeInvocationBeside(path);  // the report prints it under the table's figures
}

std::expected<int, std::string> mergeSweepTables(const std::vector<std::string>& inputs,
                                                 const std::string& out_csv) {
  std::map<int, SweepRow> rows;
  for (const std::string& input : inputs) {
    auto table = readSweepTable(input);
    if (!table) return std::unexpected(table.error());
    for (SweepRow& row : *table) {
      auto [it, inserted] = rows.emplace(row.c.id, row);
      const auto mine = sweepRowFields(row), theirs = sweepRowFields(it->second);
      if (!inserted &&
          !std::equal(mine.begin(), mine.begin() + kSweepParameterColumns, theirs.begin())) {
        return std::unexpected(
            input + ": case " + std::to_string(row.c.id) +
            " has other parameters than in an earlier table: not shards of one sweep");
      }
    }
  }
  std::vector<SweepRow> all;
  for (auto& [id, row] : rows) all.push_back(std::move(row));
  if (auto written = writeSweepTable(out_csv, all); !written)
    return std::unexpected(written.error());
  return static_cast<int>(all.size());
}

}  // namespace springcheck
