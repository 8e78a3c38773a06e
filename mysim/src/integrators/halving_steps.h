#pragma once
// A step an iterative solver (XPBD, local/global, VBD) cannot solve is redone as two half steps.
//
// Their passes converge at a rate set by h^2 k / m (Gauss-Seidel needs passes growing as it,
// Chebyshev as its square root), so a step past the pass cap at h is four times better
// conditioned at h / 2. An unsolved implicit step is not stable: its unbalanced forces do work,
// and the measured case (the shipped cantilever at 32 cells, 1/60 s, h^2 k / m ~ 1e5) gains energy
// until the health check stops it within 0.15 s in VBD, and XPBD and local/global run whole but
// off the physics (docs/performance.md "Halving unsolved steps"). Halving is what an adaptive
// integrator does with a step it rejects; here the rejection is the solver's, not an error
// estimate's.
//
// The level that worked is kept for the next steps (a failed attempt costs a whole pass cap) and
// one coarser level is tried again after kCalmSteps steps solved at it. A piece at the deepest
// level allowed (max_halvings) that still stops at the cap is kept and counted a solver failure,
// as before, and halving stops for the rest of the run: a scene no level solves (rigid
// constraints) would otherwise pay 2^(max_halvings + 1) - 1 tries a step for nothing (measured:
// the zero-compliance XPBD chain of the tests, 0.3 s -> 11.5 s). max_halvings = 0 is the plain
// solver (every step at h). A run whose steps all solve at h is the same bits either way.
#include <memory>

#include "mysim/integrator.h"

namespace mysim {

std::unique_ptr<Integrator> halvingUnsolvedSteps(std::unique_ptr<Integrator> solver, int max_halvings);

}  // namespace mysim
