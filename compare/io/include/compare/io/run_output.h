#pragma once
#include <expected>
#include <string>

#include "mysim/model.h"
#include "mysim/simulation.h"

namespace springcheck {

// What a run folder holds beyond its fixed files.
struct RunFileOptions {
  bool obj_frames = false;  // every sampled frame as a numbered OBJ (Blender, MeshLab, ParaView)
};

// Writes a run into `dir` (created if missing), the same files for every engine:
//   summary.json      engine, integrator, dt, steps, wall time, energies at start and end,
//                     blow-up (time, step, check) or null, and "complete"
//   final_state.csv   particle,x,y,z,vx,vy,vz: the last sampled state
//   trajectory.npy    float64 (frames, particles, 6): x y z vx vy vz per sampled frame
//   times.npy         float64 (frames,): the time of each frame, s
//   energy.csv        t,kinetic,gravity,spring,total per frame (systems with energy)
//   final.obj         the last cloth frame as a mesh with normals (cloth scenes)
//   obj/frame_NNNNN.obj  with obj_frames: every sampled frame, numbered from 0 (cloths as meshes
//                     with vertex normals, other particle systems as springs drawn as lines),
//                     and obj/times.csv (frame,t) for the time of each
// The folder is written whole (whole_folder.h): every file into a staging folder that then takes
// the folder's place, so it holds this run or the previous one, never a mix of both.
// `scene_name` and `scene_file` name where the model came from (a RunConfig's scene_name and
// source).
[[nodiscard]] std::expected<void, std::string> writeRunOutputs(const std::string& dir,
                                                               const mysim::Model& model,
                                                               const std::string& scene_name,
                                                               const std::string& scene_file,
                                                               const mysim::RunRecord& record,
                                                               const RunFileOptions& options = {});
// The same files into `dir` directly (a folder being staged: a comparison's engine folders).
[[nodiscard]] std::expected<void, std::string> writeRunFiles(const std::string& dir,
                                                               const mysim::Model& model,
                                                               const std::string& scene_name,
                                                               const std::string& scene_file,
                                                               const mysim::RunRecord& record,
                                                               const RunFileOptions& options = {});

}  // namespace springcheck
