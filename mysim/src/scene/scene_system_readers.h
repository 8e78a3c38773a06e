#pragma once
// The readers of each system kind (scene_system_readers.cpp), for scene_file.cpp: internal to
// mysim, beside their source.
#include "mysim/json_input.h"
#include "mysim/scene.h"

namespace mysim {

void readCircle(FieldReader& system, Scene& scene);
void readChain(FieldReader& system, Scene& scene);  // a chain, or a material chain (cable)
void readCloth(FieldReader& system, Scene& scene);  // a grid, a material grid or a mesh cloth
void readParticles(FieldReader& system, Scene& scene);

}  // namespace mysim
