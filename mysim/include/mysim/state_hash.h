#pragma once
#include <cstdint>
#include <string>

#include "mysim/simulation.h"

namespace mysim {

// FNV-1a (64 bits) over the bytes of a state's rows, particle by particle (x y z vx vy vz), as 16
// hex digits: equal hashes mean bit-identical states, so two runs (two thread counts, two
// machines, two builds) can be compared with one string. summary.json carries the final one.
std::string hashRows(const ParticleRows& rows);

}  // namespace mysim
