#include "optimize/node_stars.hpp"

#include <algorithm>

namespace bisect::optimize {

std::vector<Index> star(const tet::TetComplex& cx, Index v, Index t0) {
  // a node's star is a few dozen tetrahedra: a linear search of the list is the cheapest set
  std::vector<Index> around{t0};
  for (std::size_t i = 0; i < around.size(); ++i) {
    const Index t = around[i];
    for (int f = 0; f < 4; ++f) {
      if (cx.tet[t][f] == v) continue;  // face f is opposite corner f: the others hold v
      const Index n = cx.nb[t][f];
      if (n >= 0 && std::find(around.begin(), around.end(), n) == around.end()) around.push_back(n);
    }
  }
  return around;
}

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

std::vector<Index> below_key(const tet::TetComplex& cx, std::vector<Index> ids, double key) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  ids.erase(std::remove_if(ids.begin(), ids.end(), [&](Index t) { return !cx.alive[t] || !(cx.q[t] < key); }), ids.end());
  return ids;
}

std::vector<Index> all_below_key(const tet::TetComplex& cx, double key) {
  std::vector<Index> out;
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t] && cx.q[t] < key) out.push_back(static_cast<Index>(t));
  return out;
}

}  // namespace bisect::optimize
