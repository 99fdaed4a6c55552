#include "mesh2d/swap.hpp"

#include <algorithm>
#include <cmath>

#include "geom/predicates.hpp"
#include "mesh2d/tri_adjacency.hpp"
#include "mesh2d/tri_quality.hpp"

namespace bisect::mesh2d {
namespace {

using geom::orient2d;

struct Candidate {
  int j = -1, kj = -1;  // the neighbour and its corner opposite the shared edge
  double gain_to = 0;   // the smaller angle of the swapped pair
};

}  // namespace

SwapStats swap_edges(TriMesh2& m, const SwapOptions& opt) {
  SwapStats st;
  std::vector<char> active(m.tris.size(), 1);
  double last_min = -1;
  for (int pass = 0; pass < opt.max_passes; ++pass) {
    const TriAcross nb = triangle_neighbours(m);
    std::vector<char> next(m.tris.size(), 0);
    // triangles a swap of this pass changed, or whose neighbour it changed: the table is stale
    // around them, so they wait for the next pass
    std::vector<char> touched(m.tris.size(), 0);
    std::int64_t swaps = 0;
    for (std::size_t i = 0; i < m.tris.size(); ++i) {
      if (!active[i] || touched[i]) continue;
      // the candidates: each neighbour of the same region across a convex quadrilateral
      Candidate best;
      double best_value = -1;
      int best_k = -1;
      for (int k = 0; k < 3; ++k) {
        const auto [j, kj] = nb[i][k];
        if (j < 0 || touched[j] || m.tri_region[j] != m.tri_region[i]) continue;
        const Index c = m.tris[i][k], a = m.tris[i][(k + 1) % 3], b = m.tris[i][(k + 2) % 3], d = m.tris[j][kj];
        // swapped: (c, a, d) and (d, b, c); both counter-clockwise only if the quad is convex
        if (orient2d(m.nodes[c], m.nodes[a], m.nodes[d]) <= 0 || orient2d(m.nodes[d], m.nodes[b], m.nodes[c]) <= 0) continue;
        const double now = std::min(min_angle_deg(m.nodes[a], m.nodes[b], m.nodes[c]), min_angle_deg(m.nodes[b], m.nodes[a], m.nodes[d]));
        const double then = std::min(min_angle_deg(m.nodes[c], m.nodes[a], m.nodes[d]), min_angle_deg(m.nodes[d], m.nodes[b], m.nodes[c]));
        if (then <= now + 1e-10) continue;
        if (then > best_value) best_value = then, best = {j, kj, then}, best_k = k;
        if (!opt.neighbour_first) break;  // plain Lawson: the first improving edge
      }
      if (best_k < 0) continue;
      const int k = best_k, j = best.j, kj = best.kj;
      const Index c = m.tris[i][k], a = m.tris[i][(k + 1) % 3], b = m.tris[i][(k + 2) % 3], d = m.tris[j][kj];
      m.tris[i] = {c, a, d};
      m.tris[j] = {d, b, c};
      ++swaps;
      next[i] = next[j] = touched[i] = touched[j] = 1;
      for (int q = 0; q < 3; ++q) {
        if (nb[i][q].first >= 0) next[nb[i][q].first] = touched[nb[i][q].first] = 1;
        if (nb[j][q].first >= 0) next[nb[j][q].first] = touched[nb[j][q].first] = 1;
      }
    }
    st.passes = pass + 1;
    st.swaps += swaps;
    if (swaps == 0) break;
    const double now_min = min_angle_deg(m);
    if (last_min >= 0 && std::abs(now_min - last_min) < 1e-12 && pass > 2) {
      st.oscillation_stopped = true;
      break;
    }
    last_min = now_min;
    active = std::move(next);
  }
  return st;
}

}  // namespace bisect::mesh2d
