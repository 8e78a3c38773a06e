#include "mysim/graph_coloring.h"

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

}  // namespace mysim
