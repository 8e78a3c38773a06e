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

}  // namespace

std::expected<ExternalResult, std::string> readExternalResult(const std::string& engine,
                                                              const std::string& out_dir,
                                                              int particles, const FramePlan& plan,
                                                              double dt) {
  const fs::path dir(out_dir);
  auto bad = [&](const std::string& file, const std::string& why) {
    return std::unexpected("engine '" + engine + "': " + file + ": " + why);
  };
  auto present = [&](const char* name) { return fs::is_regular_file(dir / name); };
  ExternalResult result;

  // summary.json first: it may declare a blow-up, which allows a shorter run.
  if (present("summary.json")) {
    std::ifstream in(dir / "summary.json");
    json s;
    try {
      s = json::parse(in);
    } catch (const json::exception& e) {
      return bad("summary.json", std::string("not valid JSON: ") + e.what());
    }
    if (!s.is_object()) return bad("summary.json", "expected an object");
    result.summary_present = true;
    if (s.contains("wall_seconds")) {
      if (!s["wall_seconds"].is_number() || !(s["wall_seconds"].get<double>() >= 0) ||
          !std::isfinite(s["wall_seconds"].get<double>())) {
        return bad("summary.json", "wall_seconds: expected a number of seconds >= 0");
      }
      result.wall_seconds = s["wall_seconds"].get<double>();
    }
    if (s.contains("derivative_evaluations")) {
      // A count: an integer from 0 to 2^53 (a double's exact integers; -5 or 2^64-1 is a bug).
      const json& d = s["derivative_evaluations"];
      constexpr long kLargest = 1L << 53;
      if (!d.is_number_integer() || (d.is_number_unsigned() && d.get<unsigned long>() > kLargest) ||
          (!d.is_number_unsigned() && (d.get<long>() < 0 || d.get<long>() > kLargest))) {
        return bad("summary.json", "derivative_evaluations: expected an integer from 0 to 2^53, got " +
                                       mysim::clip(d.dump(), 40));
      }
      result.derivative_evaluations = d.get<long>();
    }
    if (s.contains("blowup") && !s["blowup"].is_null()) {
      const json& b = s["blowup"];
      if (!b.is_object() || !b.contains("time") || !b["time"].is_number()) {
        return bad("summary.json", "blowup: expected null or {\"time\": s, \"reason\": text}");
      }
      // Within the run: from its start to its last frame time (the duration).
      const double t = b["time"].get<double>();
      if (!std::isfinite(t) || t < 0.0 || t > plan.times.back() + 1e-9 * std::max(1.0, plan.times.back())) {
        std::ostringstream m;
        m.precision(12);
        m << "blowup.time: expected a time within the run, 0 to " << plan.times.back() << " s, got " << t;
        return bad("summary.json", m.str());
      }
      result.blowup_time = t;
      if (b.contains("reason") && b["reason"].is_string()) {
        result.blowup_reason = b["reason"].get<std::string>();
      }
    }
  }

  // Times.
  if (present("times.npy")) {
    auto a = readNpy((dir / "times.npy").string());
    if (!a) return bad("times.npy", a.error().substr(a.error().find(": ") + 2));
    if (a->shape.size() != 1) return bad("times.npy", "expected shape (frames,)");
    result.times = a->data;
  } else if (present("times.csv")) {
    auto rows = readNumberCsv((dir / "times.csv").string(), 1);
    if (!rows) return bad("times.csv", rows.error().substr(rows.error().find(": ") + 2));
    for (const auto& row : *rows) result.times.push_back(row[0]);
  } else {
    return bad("times.npy", "missing (the engine wrote neither times.npy nor times.csv)");
  }

  // Frames.
  std::size_t frames = result.times.size();
  std::vector<double> data;
  std::string trajectory_file = "trajectory.npy";
  if (present("trajectory.npy")) {
    auto a = readNpy((dir / "trajectory.npy").string());
    if (!a) return bad("trajectory.npy", a.error().substr(a.error().find(": ") + 2));
    if (a->shape.size() != 3 || a->shape[2] != 6) {
      return bad("trajectory.npy", "expected shape (frames, particles, 6)");
    }
    if (a->shape[1] != particles) {
      return bad("trajectory.npy", std::to_string(a->shape[1]) + " particles, the model has " +
                                       std::to_string(particles));
    }
    if (static_cast<std::size_t>(a->shape[0]) != frames) {
      return bad("trajectory.npy",
                 std::to_string(a->shape[0]) + " frames, times has " + std::to_string(frames));
    }
    data = std::move(a->data);
  } else if (present("trajectory.csv")) {
    trajectory_file = "trajectory.csv";
    auto rows = readNumberCsv((dir / "trajectory.csv").string(), 8);
    if (!rows) return bad("trajectory.csv", rows.error().substr(rows.error().find(": ") + 2));
    if (rows->size() != frames * particles) {
      return bad("trajectory.csv", std::to_string(rows->size()) +
                                       " rows, expected frames x "
                                       "particles = " +
                                       std::to_string(frames * particles));
    }
    data.resize(rows->size() * 6);
    for (std::size_t r = 0; r < rows->size(); ++r) {
      const auto& row = (*rows)[r];
      if (row[0] != static_cast<double>(r / particles) ||
          row[1] != static_cast<double>(r % particles)) {
        return bad("trajectory.csv", "row " + std::to_string(r + 1) + ": expected frame " +
                                         std::to_string(r / particles) + ", particle " +
                                         std::to_string(r % particles) +
                                         " (rows in frame, then particle order)");
      }
      for (int k = 0; k < 6; ++k) data[r * 6 + k] = row[2 + k];
    }
  } else {
    return bad("trajectory.npy",
               "missing (the engine wrote neither trajectory.npy nor trajectory.csv)");
  }

  // Frame times: the ones asked for; fewer only up to a declared blow-up.
  if (frames == 0) return bad("times", "no frames");
  if (frames > plan.times.size()) {
    return bad("times", std::to_string(frames) + " frames, " + std::to_string(plan.times.size()) +
                            " were asked for");
  }
  for (std::size_t f = 0; f < frames; ++f) {
    if (!std::isfinite(result.times[f]) ||
        std::abs(result.times[f] - plan.times[f]) > 1e-6 * dt + 1e-12) {
      std::ostringstream m;
      m.precision(12);
      m << "frame " << f << " at t = " << result.times[f] << " s, expected " << plan.times[f]
        << " s (model.json frame_times)";
      return bad(present("times.npy") ? "times.npy" : "times.csv", m.str());
    }
  }
  if (frames == plan.times.size() && result.blowup_time) {
    return bad("summary.json", "declares a blow-up at t = " + std::to_string(*result.blowup_time) +
                                   " s but every frame was returned: either the run ended early "
                                   "(return the frames up to the blow-up) or it did not blow up "
                                   "(\"blowup\": null)");
  }
  if (frames < plan.times.size() && !result.blowup_time) {
    return bad("times", std::to_string(frames) + " of " + std::to_string(plan.times.size()) +
                            " frames, and summary.json declares no blow-up: the run is "
                            "incomplete");
  }
  if (auto why = nonFiniteFrames(result, data, frames, particles)) return bad(trajectory_file, *why);
  result.frames.resize(frames);
  for (std::size_t f = 0; f < frames; ++f) {
    result.frames[f] = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>>(
        data.data() + f * 6 * particles, particles, 6);
  }
  return result;
}

}  // namespace springcheck
