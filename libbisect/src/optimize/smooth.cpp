#include "optimize/smooth.hpp"

#include <limits>

#include "optimize/node_stars.hpp"

namespace bisect::optimize {

using tet::positive;
using tet::tet_angle_key;

std::size_t smooth_interior(std::vector<Vec3>& X, const std::vector<Tet>& tets, const std::vector<char>& fixed, int passes) {
  const std::vector<std::vector<Index>> around = incidence(X.size(), tets, nullptr);
  std::size_t moves = 0;
  for (int pass = 0; pass < passes; ++pass)
    for (std::size_t v = 0; v < X.size(); ++v) {
      if (fixed[v] || around[v].empty()) continue;
      const Vec3 old = X[v], target = neighbour_mean(X, tets, around[v], static_cast<Index>(v));
      double before = std::numeric_limits<double>::max();
      for (Index t : around[v]) before = std::min(before, tet_angle_key(X, tets[t]));
      X[v] = target;
      bool ok = true;
      double after = std::numeric_limits<double>::max();
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

}  // namespace bisect::optimize
