#include "optimize/node_stars.hpp"

#include <algorithm>
#include <unordered_set>

namespace bisect::optimize {

std::vector<Index> star(const tet::TetComplex& cx, Index v, Index t0, std::size_t limit) {
  // a node's star is a few dozen tetrahedra: a linear search of the list is the cheapest set;
  // past kLinear a hash set takes over (a helper node a thin cell kept is in thousands, and the
  // sliver repair asks for its star once per sliver: quadratic, 79 s of 80 on two bonded plates)
  constexpr std::size_t kLinear = 64;
  std::vector<Index> around{t0};
  std::unordered_set<Index> seen;
  for (std::size_t i = 0; i < around.size() && around.size() <= limit; ++i) {
    const Index t = around[i];
    for (int f = 0; f < 4; ++f) {
      if (cx.tet[t][f] == v) continue;  // face f is opposite corner f: the others hold v
      const Index n = cx.nb[t][f];
      if (n < 0) continue;
      if (around.size() < kLinear) {
        if (std::find(around.begin(), around.end(), n) == around.end()) around.push_back(n);
        continue;
      }
      if (seen.empty()) seen.insert(around.begin(), around.end());
      if (seen.insert(n).second) around.push_back(n);
    }
  }
  return around;
}

Vec3 neighbour_mean(const std::vector<Vec3>& X, const std::vector<Tet>& tets, const std::vector<Index>& around, Index v) {
  Vec3 sum = Vec3::Zero();
  std::vector<Index> seen;  // the star's other nodes, each once (sorted: a star may be large)
  for (Index t : around)
    for (Index w : tets[t])
      if (w != v) seen.push_back(w);
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  for (Index w : seen) sum += X[w];
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
