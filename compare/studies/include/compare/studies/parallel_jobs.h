#pragma once
// Runs side by side: the one rule for how many, and the one pool every study runs them on.
#include <cstddef>
#include <functional>

namespace springcheck {

// The runs a study makes at once: `requested` (a --jobs option; 0 for the default, every core
// the process may use and the rest of the machine leaves free), never more than there are runs
// and at least one.
int jobCount(int requested, std::size_t runs);

// f(k) for every k in [0, n), on `jobs` threads that each take the next k; returns when all are
// done. f must not throw.
void forEachInParallel(std::size_t n, int jobs, const std::function<void(std::size_t)>& f);

}  // namespace springcheck
