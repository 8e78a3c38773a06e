#pragma once
// Where mysim's loops over particles start using OpenMP threads.

namespace mysim {

// Below this many particles a force evaluation or a solver sweep takes a few microseconds:
// starting threads would cost more than it saves.
inline constexpr int kParallelParticles = 512;

}  // namespace mysim
