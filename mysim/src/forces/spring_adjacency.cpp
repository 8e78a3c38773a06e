#include "mysim/spring_adjacency.h"

namespace mysim {

SpringAdjacency SpringAdjacency::build(int particle_count, const std::vector<Spring>& springs) {
  SpringAdjacency a;
  a.offsets.assign(particle_count + 1, 0);
  for (const Spring& s : springs) {
    ++a.offsets[s.i + 1];
    ++a.offsets[s.j + 1];
  }
  for (int p = 0; p < particle_count; ++p) a.offsets[p + 1] += a.offsets[p];
  const std::size_t total = 2 * springs.size();
  a.other.resize(total);
  a.spring.resize(total);
  std::vector<int> fill(a.offsets.begin(), a.offsets.end() - 1);
  for (int k = 0; k < static_cast<int>(springs.size()); ++k) {
    const Spring& s = springs[k];
    for (auto [from, to] : {std::pair{s.i, s.j}, std::pair{s.j, s.i}}) {
      const int e = fill[from]++;
      a.other[e] = to;
      a.spring[e] = k;
    }
  }
  return a;
}

}  // namespace mysim
