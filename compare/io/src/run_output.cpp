#include "compare/io/run_output.h"

#include <sys/resource.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "compare/io/atomic_file.h"
#include "compare/io/whole_folder.h"
#include "compare/io/npy.h"
#include "mysim/cloth_surface.h"
#include "mysim/state_hash.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The process's own high-water mark of resident memory (getrusage), bytes.
long peakResidentBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss * 1024L;
}

json energyJson(const mysim::EnergyTerms& e) {
  return {
      {"kinetic", e.kinetic}, {"gravity", e.gravity}, {"spring", e.spring}, {"total", e.total()}};
}

json summaryJson(const mysim::Model& model, const std::string& scene_name,
                 const std::string& scene_file, const mysim::RunRecord& r) {
  json s = {{"scene", scene_name},
            {"scene_file", scene_file},
            {"system", model.kind},
            {"engine", r.engine},
            {"integrator", r.integrator},
            {"dt", r.dt},
            {"duration", r.duration},
            {"steps", r.steps},
            {"time_reached", r.times.empty() ? 0.0 : r.times.back()},
            {"wall_seconds", r.wall_seconds},
            {"wall_median_seconds", r.wall_median_seconds},
            {"repeats", r.repeats},
            {"threads", r.threads > 0 ? json(r.threads) : json()},  // 0: unknown (external)
            {"realtime_factor", r.realtimeFactor()},
            {"accepted_steps", r.counts.accepted},
            {"rejected_steps", r.counts.rejected},
            {"derivative_evaluations", r.counts.derivative_evaluations >= 0
                                           ? json(r.counts.derivative_evaluations)
                                           : json()},  // unknown: null
            {"linear_iterations", r.counts.linear_iterations},
            {"solver_failures", r.counts.solver_failures},
            {"setup_seconds", r.counts.setup_seconds},
            {"particles", r.frames.empty() ? 0 : r.frames.front().rows()},
            {"frames", r.frames.size()},
            {"complete", !r.blowup.has_value()},
            {"status", r.status()},
            {"final_state_hash", r.frames.empty() ? "" : mysim::hashRows(r.frames.back())},
            {"notes", r.notes},
            {"peak_resident_bytes", peakResidentBytes()}};
  // Only for engines that declared single precision (docs/external-engines.md).
  s["precision_floor"] = r.precision_floor > 0 ? json(r.precision_floor) : json();
  s["energy_start"] = r.energies.empty() ? json() : energyJson(r.energies.front());
  s["energy_end"] = r.energies.empty() ? json() : energyJson(r.energies.back());
  if (r.blowup) {
    s["blowup"] = {{"time", r.blowup->time},
                   {"step", r.blowup->step},
                   {"check", r.blowup->check},
                   {"detail", r.blowup->detail}};
  } else {
    s["blowup"] = nullptr;
  }
  return s;
}

// Positions of one frame as mysim's flat vector.
mysim::Vector positions(const mysim::ParticleRows& frame) {
  mysim::Vector x(3 * frame.rows());
  for (int i = 0; i < frame.rows(); ++i) x.segment<3>(3 * i) = frame.block<1, 3>(i, 0).transpose();
  return x;
}

// One frame as OBJ: a grid cloth as its triangle mesh with vertex normals (mysim::writeObj, as
// final.obj); any other particle system as its vertices and each spring as a line element.
void writeFrameObj(std::ostream& out, const mysim::Model& model, const mysim::ParticleRows& f) {
  if (model.grid) {
    mysim::writeObj(out, {model.grid->rows, model.grid->cols}, positions(f));
    return;
  }
  if (!model.mesh_triangles.empty()) {
    mysim::writeObj(out, model.mesh_triangles, positions(f));
    return;
  }
  out.precision(9);
  out << "# springcheck particles " << f.rows() << ", springs as lines\n";
  for (int p = 0; p < f.rows(); ++p) out << "v " << f(p, 0) << ' ' << f(p, 1) << ' ' << f(p, 2) << '\n';
  for (const mysim::Spring& s : model.springs) out << "l " << s.i + 1 << ' ' << s.j + 1 << '\n';
}

// obj/frame_00000.obj ... and obj/times.csv (frame,t): numbered from 0 in frame order, five
// digits (a run has about 200 frames, every step with wind or driven pins: up to 99999).
std::expected<void, std::string> writeObjSequence(const std::string& folder,
                                                  const mysim::Model& model,
                                                  const mysim::RunRecord& r) {
  if (model.isCircle()) return {};  // one point: nothing to look at as a mesh
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) return std::unexpected("cannot create " + folder + ": " + ec.message());
  for (std::size_t f = 0; f < r.frames.size(); ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05zu.obj", f);
    auto done = writeFileAtomically((fs::path(folder) / name).string(), [&](std::ostream& out) {
      writeFrameObj(out, model, r.frames[f]);
    });
    if (!done) return done;
  }
  return writeFileAtomically((fs::path(folder) / "times.csv").string(), [&](std::ostream& out) {
    out.precision(17);
    out << "frame,t\n";
    for (std::size_t f = 0; f < r.times.size(); ++f) out << f << ',' << r.times[f] << '\n';
  });
}

// trajectory.npy (frames x particles x 6) and times.npy.
std::expected<void, std::string> writeTrajectory(const fs::path& dir, const mysim::RunRecord& r) {
  const long frames = static_cast<long>(r.frames.size()), particles = r.frames.back().rows();
  const std::string trajectory = (dir / "trajectory.npy").string();
  auto done = writeNpy(trajectory, {frames, particles, 6}, [&](std::ostream& out) {
    for (const mysim::ParticleRows& f : r.frames) {
      // Frames are column-major (N x 6); the file wants each particle's six values together.
      const Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor> rows = f;
      out.write(reinterpret_cast<const char*>(rows.data()),
                static_cast<std::streamsize>(rows.size() * sizeof(double)));
    }
  });
  if (!done) return done;
  return writeNpy((dir / "times.npy").string(), {frames}, r.times);
}

}  // namespace

std::expected<void, std::string> writeRunOutputs(const std::string& dir_name,
                                                 const mysim::Model& model,
                                                 const std::string& scene_name,
                                                 const std::string& scene_file,
                                                 const mysim::RunRecord& r,
                                                 const RunFileOptions& options) {
  if (r.frames.empty()) return std::unexpected("run recorded no frame");
  return writeFolderWhole(dir_name, runFolderKind(), [&](const std::string& staging) {
    return writeRunFiles(staging, model, scene_name, scene_file, r, options);
  });
}

std::expected<void, std::string> writeRunFiles(const std::string& dir_name,
                                               const mysim::Model& model,
                                               const std::string& scene_name,
                                               const std::string& scene_file,
                                               const mysim::RunRecord& r,
                                               const RunFileOptions& options) {
  const fs::path dir(dir_name);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return std::unexpected("cannot create " + dir.string() + ": " + ec.message());
  if (r.frames.empty()) return std::unexpected("run recorded no frame");

  const mysim::ParticleRows& last = r.frames.back();
  auto in = [&](const char* name) { return (dir / name).string(); };
  auto done = writeFileAtomically(in("final_state.csv"), [&](std::ostream& out) {
    out.precision(17);
    out << "particle,x,y,z,vx,vy,vz\n";
    for (int i = 0; i < last.rows(); ++i) {
      out << i;
      for (int k = 0; k < 6; ++k) out << ',' << last(i, k);
      out << '\n';
    }
  });
  if (!done) return done;

  done = writeTrajectory(dir, r);
  if (!done) return done;

  if (!r.energies.empty()) {
    done = writeFileAtomically(in("energy.csv"), [&](std::ostream& out) {
      out.precision(17);
      out << "t,kinetic,gravity,spring,total,external_work\n";
      for (std::size_t f = 0; f < r.energies.size(); ++f) {
        const mysim::EnergyTerms& e = r.energies[f];
        out << r.times[f] << ',' << e.kinetic << ',' << e.gravity << ',' << e.spring << ','
            << e.total() << ',' << e.external_work << '\n';
      }
    });
    if (!done) return done;
  }

  if (model.hasSurface()) {
    done = writeFileAtomically(in("final.obj"), [&](std::ostream& out) { writeFrameObj(out, model, last); });
    if (!done) return done;
  }

  if (options.obj_frames) {
    if (done = writeObjSequence((dir / "obj").string(), model, r); !done) return done;
  }

  return writeFileAtomically(in("summary.json"), [&](std::ostream& out) {
    out << jsonText(summaryJson(model, scene_name, scene_file, r), 2) << '\n';
  });
}

}  // namespace springcheck
