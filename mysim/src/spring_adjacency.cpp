#include "mysim/spring_adjacency.h"

#include <map>
#include <tuple>

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
  a.parameter.resize(total);
  a.spring_end.resize(total);
  std::map<std::tuple<double, double, double>, int> ids;
  std::vector<int> fill(a.offsets.begin(), a.offsets.end() - 1);
  for (int k = 0; k < static_cast<int>(springs.size()); ++k) {
    const Spring& s = springs[k];
    auto [it, added] = ids.try_emplace({s.rest_length, s.stiffness, s.damping},
                                       static_cast<int>(a.parameters.size()));
    if (added) a.parameters.push_back({s.rest_length, s.stiffness, s.damping});
    for (auto [from, to, second] : {std::tuple{s.i, s.j, 0}, std::tuple{s.j, s.i, 1}}) {
      const int e = fill[from]++;
      a.other[e] = to;
      a.parameter[e] = it->second;
      a.spring_end[e] = 2 * k + second;
    }
  }
  return a;
}

}  // namespace mysim
