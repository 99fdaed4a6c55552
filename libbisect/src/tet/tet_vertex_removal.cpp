// Removal of an interior node by flips (thesis 7.6: the helper vertex): edges at it taken out of
// their rings until a 4-1 flip merges its last four tetrahedra.
#include "tet/tet_complex.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "bisect/errors.hpp"
#include "bisect/quality.hpp"
#include "geom/predicates.hpp"

namespace bisect::tet {

using geom::orient3d;

bool TetComplex::remove_vertex(Index v) {
  for (;;) {
    const std::vector<Index> around = tets_at(v);
    if (around.size() < 4) return false;  // not an interior node
    for (Index t : around)  // a face at v that holds (the boundary): v is not inside
      for (int f = 0; f < 4; ++f)
        if (tet[t][f] != v && is_constrained(t, f)) return false;
    if (around.size() == 4) {  // 4-1: the four faces opposite v close up into one tetrahedron
      Tet m = tet[around[0]];
      const int c = corner_of(around[0], v);
      for (Index t : around)
        for (Index x : tet[t])
          if (x != v && std::find(m.begin(), m.end(), x) == m.end()) m[c] = x;
      if (!positive(X, m)) return false;
      replace(around, {m});
      return true;
    }
    // 3-2, 4-4 and larger: an edge (v, x) taken out of its ring, whichever triangulation of the
    // ring is best; v then lies in two tetrahedra fewer
    bool removed = false;
    for (std::size_t i = 0; i < around.size() && !removed; ++i)
      for (Index x : tet[around[i]]) {
        if (x == v) continue;
        std::array<Index, kMaxRing> ring, p;
        bool closed = false, held = false;
        const int n = edge_ring(around[i], v, x, static_cast<int>(kMaxRing), ring.data(), p.data(), &closed, &held);
        if (!closed || n < 3 || n > static_cast<int>(kMaxRing)) continue;
        std::vector<Tet> fresh;
        if (!ring_triangulation(v, x, p.data(), static_cast<std::size_t>(n), 0, &fresh)) continue;
        replace(std::vector<Index>(ring.begin(), ring.begin() + n), fresh);
        removed = true;
        break;
      }
    if (!removed) return false;
  }
}

}  // namespace bisect::tet
