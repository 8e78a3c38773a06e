#include "solvers/graph_coloring.h"

#include <algorithm>

namespace mysim {

std::vector<std::vector<int>> colorSprings(int particles, const SpringList& springs) {
  // used[p]: the colours of the springs already coloured at particle p.
  std::vector<std::vector<int>> used(particles);
  std::vector<std::vector<int>> colors;
  for (int k = 0; k < static_cast<int>(springs.size()); ++k) {
    const Spring& s = springs[k];
    int color = 0;
    auto taken = [&](int c) {
      return std::find(used[s.i].begin(), used[s.i].end(), c) != used[s.i].end() ||
             std::find(used[s.j].begin(), used[s.j].end(), c) != used[s.j].end();
    };
    while (taken(color)) ++color;
    if (color == static_cast<int>(colors.size())) colors.emplace_back();
    colors[color].push_back(k);
    used[s.i].push_back(color);
    used[s.j].push_back(color);
  }
  return colors;
}

std::vector<std::vector<int>> colorParticles(const SpringAdjacency& adjacency) {
  const int particles = static_cast<int>(adjacency.offsets.size()) - 1;
  std::vector<int> color_of(particles, -1);
  std::vector<std::vector<int>> colors;
  std::vector<char> taken;
  for (int p = 0; p < particles; ++p) {
    taken.assign(colors.size() + 1, 0);
    for (int e = adjacency.offsets[p]; e < adjacency.offsets[p + 1]; ++e) {
      const int c = color_of[adjacency.other[e]];
      if (c >= 0) taken[c] = 1;
    }
    const int color = static_cast<int>(std::find(taken.begin(), taken.end(), 0) - taken.begin());
    if (color == static_cast<int>(colors.size())) colors.emplace_back();
    colors[color].push_back(p);
    color_of[p] = color;
  }
  return colors;
}

}  // namespace mysim
