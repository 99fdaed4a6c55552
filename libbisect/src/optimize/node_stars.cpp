#include "optimize/node_stars.hpp"

#include <algorithm>

namespace bisect::optimize {

// The tetrahedra around each node.
std::vector<std::vector<Index>> incidence(std::size_t nodes, const std::vector<Tet>& tets, const std::vector<char>* alive) {
  std::vector<std::vector<Index>> around(nodes);
  for (std::size_t t = 0; t < tets.size(); ++t)
    if (!alive || (*alive)[t])
      for (Index v : tets[t]) around[v].push_back(static_cast<Index>(t));
  return around;
}

// The mean of the nodes sharing a tetrahedron with v.
Vec3 neighbour_mean(const std::vector<Vec3>& X, const std::vector<Tet>& tets, const std::vector<Index>& around, Index v) {
  Vec3 sum = Vec3::Zero();
  std::vector<Index> seen;
  for (Index t : around)
    for (Index w : tets[t])
      if (w != v && std::find(seen.begin(), seen.end(), w) == seen.end()) {
        seen.push_back(w);
        sum += X[w];
      }
  return sum / static_cast<double>(std::max<std::size_t>(seen.size(), 1));
}

}  // namespace bisect::optimize
