// Reading back what an external engine wrote, checked whole before anything uses it.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "compare/engines/external_engine.h"
#include "compare/io/npy.h"

namespace springcheck {

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

// A CSV of numbers: an optional header line, then `columns` numbers a row.
std::expected<std::vector<std::vector<double>>, std::string> readNumberCsv(const std::string& path,
                                                                           std::size_t columns) {
  std::ifstream in(path);
  if (!in) return std::unexpected(path + ": cannot open");
  std::vector<std::vector<double>> rows;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<double> row;
    std::stringstream fields(line);
    bool numeric = true;
    for (std::string field; std::getline(fields, field, ',');) {
      char* end = nullptr;
      const double v = std::strtod(field.c_str(), &end);
      if (end == field.c_str() || *end != '\0') numeric = false;
      row.push_back(v);
    }
    if (!numeric) {
      if (line_number == 1) continue;  // the header
      return std::unexpected(path + ": line " + std::to_string(line_number) +
                             ": expected numbers, got '" + line.substr(0, 80) + "'");
    }
    if (row.size() != columns) {
      return std::unexpected(path + ": line " + std::to_string(line_number) + ": " +
                             std::to_string(row.size()) + " columns, expected " +
                             std::to_string(columns));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

namespace {

// Every value finite, but for a declared blow-up's last frame: an engine that stops when its
// state turns non-finite may return that frame, which is then dropped and named in the reason
// (so the record says "non-finite", at the time the engine declared). A non-finite value anywhere
// else refuses the result, naming frame and particle.
std::optional<std::string> nonFiniteFrames(ExternalResult& result, const std::vector<double>& data,
                                           std::size_t& frames, std::size_t particles) {
  for (std::size_t k = 0; k < data.size(); ++k) {
    if (std::isfinite(data[k])) continue;
    const std::size_t f = k / (6 * particles), p = (k / 6) % particles;
    if (result.blowup_time && f + 1 == frames && frames > 1) {
      result.blowup_reason += std::string(result.blowup_reason.empty() ? "" : "; ") +
                              "its last frame (t = " + std::to_string(result.times[f]) +
                              " s) held non-finite values (dropped)";
      frames -= 1;
      result.times.resize(frames);
      return std::nullopt;
    }
    return "non-finite value in frame " + std::to_string(f) + " (t = " +
           std::to_string(result.times[f]) + " s), particle " + std::to_string(p) +
           (result.blowup_time ? " before the last frame of a declared blow-up"
                               : " (an engine that blows up stops and declares it in "
                                 "summary.json)");
  }
  return std::nullopt;
}

// What is wrong with an engine's output, and in which file.
struct Wrong {
  std::string file, why;
};
std::unexpected<Wrong> wrong(std::string file, std::string why) {
  return std::unexpected(Wrong{std::move(file), std::move(why)});
}
std::string afterPath(const std::string& error) { return error.substr(error.find(": ") + 2); }

// summary.json's optional counts: wall_seconds and derivative_evaluations.
std::optional<std::string> readSummaryCounts(const json& s, ExternalResult& result) {
  if (s.contains("wall_seconds")) {
    if (!s["wall_seconds"].is_number() || !(s["wall_seconds"].get<double>() >= 0) ||
        !std::isfinite(s["wall_seconds"].get<double>())) {
      return "wall_seconds: expected a number of seconds >= 0";
    }
    result.wall_seconds = s["wall_seconds"].get<double>();
  }
  if (s.contains("derivative_evaluations")) {
    // A count: an integer from 0 to 2^53 (a double's exact integers; -5 or 2^64-1 is a bug).
    const json& d = s["derivative_evaluations"];
    constexpr long kLargest = 1L << 53;
    if (!d.is_number_integer() || (d.is_number_unsigned() && d.get<unsigned long>() > kLargest) ||
        (!d.is_number_unsigned() && (d.get<long>() < 0 || d.get<long>() > kLargest))) {
      return "derivative_evaluations: expected an integer from 0 to 2^53, got " +
             mysim::clip(d.dump(), 40);
    }
    result.derivative_evaluations = d.get<long>();
  }
  return std::nullopt;
}

// summary.json's blowup: null or {"time": s within the run, "reason": text}.
std::optional<std::string> readSummaryBlowup(const json& s, const FramePlan& plan,
                                             ExternalResult& result) {
  if (!s.contains("blowup") || s["blowup"].is_null()) return std::nullopt;
  const json& b = s["blowup"];
  if (!b.is_object() || !b.contains("time") || !b["time"].is_number()) {
    return "blowup: expected null or {\"time\": s, \"reason\": text}";
  }
  // Within the run: from its start to its last frame time (the duration).
  const double t = b["time"].get<double>();
  if (!std::isfinite(t) || t < 0.0 || t > plan.times.back() + 1e-9 * std::max(1.0, plan.times.back())) {
    std::ostringstream m;
    m.precision(12);
    m << "blowup.time: expected a time within the run, 0 to " << plan.times.back() << " s, got " << t;
    return m.str();
  }
  result.blowup_time = t;
  if (b.contains("reason") && b["reason"].is_string()) {
    result.blowup_reason = b["reason"].get<std::string>();
  }
  return std::nullopt;
}

// summary.json, when present, first: it may declare a blow-up, which allows a shorter run.
std::optional<std::string> readSummary(const fs::path& file, const FramePlan& plan,
                                       ExternalResult& result) {
  std::ifstream in(file);
  json s;
  try {
    s = json::parse(in);
  } catch (const json::exception& e) {
    return std::string("not valid JSON: ") + e.what();
  }
  if (!s.is_object()) return "expected an object";
  result.summary_present = true;
  if (auto why = readSummaryCounts(s, result)) return why;
  return readSummaryBlowup(s, plan, result);
}

std::expected<std::vector<double>, Wrong> readTimes(const fs::path& dir) {
  std::vector<double> times;
  if (fs::is_regular_file(dir / "times.npy")) {
    auto a = readNpy((dir / "times.npy").string());
    if (!a) return wrong("times.npy", afterPath(a.error()));
    if (a->shape.size() != 1) return wrong("times.npy", "expected shape (frames,)");
    return a->data;
  }
  if (fs::is_regular_file(dir / "times.csv")) {
    auto rows = readNumberCsv((dir / "times.csv").string(), 1);
    if (!rows) return wrong("times.csv", afterPath(rows.error()));
    for (const auto& row : *rows) times.push_back(row[0]);
    return times;
  }
  return wrong("times.npy", "missing (the engine wrote neither times.npy nor times.csv)");
}

std::expected<std::vector<double>, Wrong> readTrajectoryNpy(const fs::path& file, int particles,
                                                           std::size_t frames) {
  auto a = readNpy(file.string());
  if (!a) return wrong("trajectory.npy", afterPath(a.error()));
  if (a->shape.size() != 3 || a->shape[2] != 6) {
    return wrong("trajectory.npy", "expected shape (frames, particles, 6)");
  }
  if (a->shape[1] != particles) {
    return wrong("trajectory.npy", std::to_string(a->shape[1]) + " particles, the model has " +
                                       std::to_string(particles));
  }
  if (static_cast<std::size_t>(a->shape[0]) != frames) {
    return wrong("trajectory.npy",
                 std::to_string(a->shape[0]) + " frames, times has " + std::to_string(frames));
  }
  return std::move(a->data);
}

std::expected<std::vector<double>, Wrong> readTrajectoryCsv(const fs::path& file, int particles,
                                                           std::size_t frames) {
  auto rows = readNumberCsv(file.string(), 8);
  if (!rows) return wrong("trajectory.csv", afterPath(rows.error()));
  if (rows->size() != frames * particles) {
    return wrong("trajectory.csv", std::to_string(rows->size()) +
                                       " rows, expected frames x particles = " +
                                       std::to_string(frames * particles));
  }
  std::vector<double> data(rows->size() * 6);
  for (std::size_t r = 0; r < rows->size(); ++r) {
    const auto& row = (*rows)[r];
    if (row[0] != static_cast<double>(r / particles) ||
        row[1] != static_cast<double>(r % particles)) {
      return wrong("trajectory.csv", "row " + std::to_string(r + 1) + ": expected frame " +
                                         std::to_string(r / particles) + ", particle " +
                                         std::to_string(r % particles) +
                                         " (rows in frame, then particle order)");
    }
    for (int k = 0; k < 6; ++k) data[r * 6 + k] = row[2 + k];
  }
  return data;
}

// Frame times: the ones asked for; fewer only up to a declared blow-up.
std::optional<Wrong> checkFrameTimes(const ExternalResult& result, const FramePlan& plan,
                                     double dt, const std::string& times_file) {
  const std::size_t frames = result.times.size();
  if (frames == 0) return Wrong{"times", "no frames"};
  if (frames > plan.times.size()) {
    return Wrong{"times", std::to_string(frames) + " frames, " + std::to_string(plan.times.size()) +
                              " were asked for"};
  }
  for (std::size_t f = 0; f < frames; ++f) {
    if (!std::isfinite(result.times[f]) ||
        std::abs(result.times[f] - plan.times[f]) > 1e-6 * dt + 1e-12) {
      std::ostringstream m;
      m.precision(12);
      m << "frame " << f << " at t = " << result.times[f] << " s, expected " << plan.times[f]
        << " s (model.json frame_times)";
      return Wrong{times_file, m.str()};
    }
  }
  if (frames == plan.times.size() && result.blowup_time) {
    return Wrong{"summary.json", "declares a blow-up at t = " + std::to_string(*result.blowup_time) +
                                     " s but every frame was returned: either the run ended early "
                                     "(return the frames up to the blow-up) or it did not blow up "
                                     "(\"blowup\": null)"};
  }
  if (frames < plan.times.size() && !result.blowup_time) {
    return Wrong{"times", std::to_string(frames) + " of " + std::to_string(plan.times.size()) +
                              " frames, and summary.json declares no blow-up: the run is "
                              "incomplete"};
  }
  return std::nullopt;
}

// Times, then every frame, checked whole; on return, result's times and frames are the run's.
std::optional<Wrong> readFrames(const fs::path& dir, int particles, const FramePlan& plan,
                                double dt, ExternalResult& result) {
  auto times = readTimes(dir);
  if (!times) return times.error();
  result.times = std::move(*times);
  std::size_t frames = result.times.size();
  const bool npy = fs::is_regular_file(dir / "trajectory.npy");
  if (!npy && !fs::is_regular_file(dir / "trajectory.csv")) {
    return Wrong{"trajectory.npy", "missing (the engine wrote neither trajectory.npy nor trajectory.csv)"};
  }
  const std::string trajectory_file = npy ? "trajectory.npy" : "trajectory.csv";
  auto data = npy ? readTrajectoryNpy(dir / trajectory_file, particles, frames)
                  : readTrajectoryCsv(dir / trajectory_file, particles, frames);
  if (!data) return data.error();
  const bool times_npy = fs::is_regular_file(dir / "times.npy");
  if (auto why = checkFrameTimes(result, plan, dt, times_npy ? "times.npy" : "times.csv")) return why;
  if (auto why = nonFiniteFrames(result, *data, frames, particles)) return Wrong{trajectory_file, *why};
  result.frames.resize(frames);
  for (std::size_t f = 0; f < frames; ++f) {
    result.frames[f] = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>>(
        data->data() + f * 6 * particles, particles, 6);
  }
  return std::nullopt;
}

}  // namespace

std::expected<ExternalResult, std::string> readExternalResult(const std::string& engine,
                                                              const std::string& out_dir,
                                                              int particles, const FramePlan& plan,
                                                              double dt) {
  const fs::path dir(out_dir);
  auto bad = [&](const std::string& file, const std::string& why) {
    return std::unexpected("engine '" + engine + "': " + file + ": " + why);
  };
  ExternalResult result;
  if (fs::is_regular_file(dir / "summary.json")) {
    if (auto why = readSummary(dir / "summary.json", plan, result)) return bad("summary.json", *why);
  }
  if (auto why = readFrames(dir, particles, plan, dt, result)) return bad(why->file, why->why);
  return result;
}

}  // namespace springcheck
