#include "fill/smooth3d.hpp"

#include <algorithm>

namespace bisect::fill {

std::size_t smooth_interior(std::vector<Vec3>& X, const std::vector<Tet>& tets, std::size_t first_free, int passes) {
  // tetrahedra around each free node, and its neighbours
  std::vector<std::vector<Index>> around(X.size());
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (Index v : tets[t])
      if (static_cast<std::size_t>(v) >= first_free) around[v].push_back(static_cast<Index>(t));
  std::size_t moves = 0;
  for (int pass = 0; pass < passes; ++pass)
    for (std::size_t v = first_free; v < X.size(); ++v) {
      if (around[v].empty()) continue;
      Vec3 sum = Vec3::Zero();
      std::vector<Index> seen;
      for (Index t : around[v])
        for (Index w : tets[t])
          if (w != static_cast<Index>(v) && std::find(seen.begin(), seen.end(), w) == seen.end()) {
            seen.push_back(w);
            sum += X[w];
          }
      const Vec3 old = X[v], target = sum / static_cast<double>(seen.size());
      double before = 1e300;
      for (Index t : around[v]) before = std::min(before, tet_angle_key(X, tets[t]));
      X[v] = target;
      bool ok = true;
      double after = 1e300;
      for (Index t : around[v]) {
        if (!positive(X, tets[t])) {
          ok = false;
          break;
        }
        after = std::min(after, tet_angle_key(X, tets[t]));
      }
      if (ok && after >= before) ++moves;
      else X[v] = old;
    }
  return moves;
}

}  // namespace bisect::fill
