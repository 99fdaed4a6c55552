// Exact tests on planar loops of node ids, shared by the planar mesher's stages.
#pragma once
#include <vector>

#include "bisect/types.hpp"
#include "geom/predicates.hpp"

namespace bisect::mesh2d {

// Whether p lies inside the loop, by crossing parity with orient2d deciding each crossing exactly
// (points on the loop give either answer).
inline bool inside_loop(const std::vector<Vec2>& X, const std::vector<Index>& loop, const Vec2& p) {
  bool in = false;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vec2 &u = X[loop[k]], &v = X[loop[(k + 1) % loop.size()]];
    if ((u.y() > p.y()) != (v.y() > p.y())) {
      const int o = geom::orient2d(u, v, p);
      if ((v.y() > u.y() ? o : -o) > 0) in = !in;
    }
  }
  return in;
}

}  // namespace bisect::mesh2d
