#include "tet/boundary_crossing.hpp"

#include <algorithm>

#include "geom/box_grid.hpp"
#include "geom/segment_triangle.hpp"

namespace bisect::tet {

std::optional<BoundaryCrossing> boundary_crossing(const std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary) {
  if (boundary.empty()) return std::nullopt;
  // the grid's box: about the mean edge's length, so that a triangle covers a few boxes
  Vec3 lo = X[boundary[0][0]], hi = lo;
  double total = 0;
  for (const auto& t : boundary)
    for (int i = 0; i < 3; ++i) {
      lo = lo.cwiseMin(X[t[i]]), hi = hi.cwiseMax(X[t[i]]);
      total += (X[t[i]] - X[t[(i + 1) % 3]]).norm();
    }
  const double h = std::max(total / (3.0 * static_cast<double>(boundary.size())), 1e-12 * std::max(1.0, (hi - lo).norm()));
  geom::BoxGrid grid(lo, h);
  for (std::size_t t = 0; t < boundary.size(); ++t) {
    const auto& c = boundary[t];
    grid.insert(t, X[c[0]].cwiseMin(X[c[1]]).cwiseMin(X[c[2]]), X[c[0]].cwiseMax(X[c[1]]).cwiseMax(X[c[2]]));
  }
  std::vector<std::size_t> seen(boundary.size(), 0);  // stamp per triangle: once per edge
  std::size_t stamp = 0;
  for (std::size_t e = 0; e < boundary.size(); ++e)
    for (int s = 0; s < 3; ++s) {
      const Index p = boundary[e][s], q = boundary[e][(s + 1) % 3];
      if (p > q) continue;  // each edge once: a closed boundary has it going up in one of its two triangles
      ++stamp;
      std::optional<BoundaryCrossing> found;
      grid.visit(X[p].cwiseMin(X[q]), X[p].cwiseMax(X[q]), [&](std::size_t t) {
        if (found || seen[t] == stamp) return;
        seen[t] = stamp;
        const auto& c = boundary[t];
        if (std::count(c.begin(), c.end(), p) || std::count(c.begin(), c.end(), q)) return;
        if (geom::segment_through_triangle(X[p], X[q], X[c[0]], X[c[1]], X[c[2]]) < 0) return;
        found = BoundaryCrossing{e, t, geom::plane_meeting(X[p], X[q], X[c[0]], X[c[1]], X[c[2]])};
      });
      if (found) return found;
    }
  return std::nullopt;
}

}  // namespace bisect::tet
