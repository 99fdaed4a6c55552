// Edge removal (thesis 7.5, generalised): the ring of tetrahedra around an interior edge replaced
// by the best triangulation of its polygon, found by dynamic programming.
#include "tet/tet_complex.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "bisect/errors.hpp"
#include "bisect/quality.hpp"
#include "geom/predicates.hpp"
#include "util/edge_key.hpp"

namespace bisect::tet {

using geom::orient3d;

int TetComplex::edge_ring(Index t, Index a, Index b, int cap, Index* ring, Index* apex, bool* closed, bool* held) const {
  *closed = *held = false;
  int k = 0;
  Index cur = t;
  int came_in = -1;  // the face of cur the walk came in by (-1 at t)
  while (k < cap) {
    ring[k++] = cur;
    // the two faces of cur through edge ab are those opposite its other two corners
    int next_face = -1;
    for (int f = 0; f < 4; ++f) {
      const Index opp = tet[cur][f];
      if (opp == a || opp == b || f == came_in) continue;
      next_face = f;
      if (came_in < 0) break;  // first step: either way round
    }
    if (next_face < 0) return k;
    if (is_constrained(cur, next_face)) {
      *held = true;
      return k;
    }
    // the face crossed holds a, b and cur's fourth corner
    for (Index x : tet[cur])
      if (x != a && x != b && x != tet[cur][next_face]) apex[k - 1] = x;
    const Index n = neighbour(cur, next_face);
    if (n == t) {
      *closed = true;
      return k;
    }
    came_in = neighbour_face(cur, next_face);
    cur = n;
  }
  return k + 1;  // longer than cap
}

bool TetComplex::try_edge_removal(Index t, Index a, Index b, std::vector<std::pair<Index, int>>& queue) {
  const std::uint64_t edge = edge_key(a, b);
  if (const Failure* seen = failed_.find(edge)) {
    const Failure& was = *seen;
    if (was.stamp == kForever) return false;
    bool same = true;
    for (int i = 0; i < was.k && same; ++i) same = alive[was.ring[i]] && born_[was.ring[i]] <= was.stamp;
    if (same) return false;  // the same ring failed before
  }
  std::array<Index, kMaxRing> ring, p;  // p[i]: the node ring[i] shares with ring[i + 1] (besides a and b)
  bool closed = false, held = false;
  const int n = edge_ring(t, a, b, static_cast<int>(kMaxRing), ring.data(), p.data(), &closed, &held);
  if (held) {  // a, b on a constrained face: that never goes, nor does the edge
    failed_.put(edge, Failure{kForever, 0, {}});
    return false;
  }
  if (!closed || n < 3) return false;
  const std::size_t k = static_cast<std::size_t>(n);
  auto fail = [&] {
    failed_.put(edge, Failure{clock_, n, ring});
    return false;
  };
  double before = 1e300;
  for (std::size_t i = 0; i < k; ++i) before = std::min(before, q[ring[i]]);
  std::vector<Tet>& fresh = fresh_;
  if (!ring_triangulation(a, b, p.data(), k, before * (1 + 1e-9), &fresh)) return fail();
  old_.assign(ring.begin(), ring.begin() + n);
  for (Index id : replace(old_, fresh))
    for (int g = 0; g < 4; ++g) queue.push_back({id, g});
  return true;
}

bool TetComplex::ring_triangulation(Index a, Index b, const Index* p, std::size_t k, double need, std::vector<Tet>* fresh) const {
  // best triangulation of the polygon (Klincsek's dynamic programme): each triangle (i, m, j)
  // makes two tetrahedra with a and b, valid when a lies on the side `sign` of it and b on the
  // other; the ring's order fixes which sign that is, so both are tried. Only triangulations
  // better than `need` matter, so a part no better than it counts as impossible: most
  // triangles are then rejected before their tetrahedra are graded.
  std::array<double, kMaxRing * kMaxRing> best;
  std::array<int, kMaxRing * kMaxRing> split;
  // The sign along the edge's direction is the triangles' orientation in the projection along
  // (a, b), so a polygon that winds once round the edge (every pair of consecutive corners, the
  // last and the first too, with a and b the same orientation) is triangulated with the other
  // sign alone: the triangles' signed areas add up to the polygon's, which that winding makes of
  // that sign. The other sign's search, which fails, was half the dynamic programme's cost. A
  // ring that winds both ways (a fold), or an open one whose closing chord turns back (the
  // surface's edge flips), is searched with both.
  const int w = orient3d(X[a], X[b], X[p[0]], X[p[1]]);
  bool one_way = w != 0;
  for (std::size_t i = 1; i < k && one_way; ++i) one_way = orient3d(X[a], X[b], X[p[i]], X[p[(i + 1) % k]]) == w;
  for (int sign : {1, -1}) {
    if (one_way && sign != -w) continue;
    best.fill(-1);  // best[i * k + j]: polygon i..j, -1 impossible
    for (std::size_t i = 0; i + 1 < k; ++i) best[i * k + i + 1] = 1e300;
    for (std::size_t len = 2; len < k; ++len)
      for (std::size_t i = 0; i + len < k; ++i) {
        const std::size_t j = i + len;
        for (std::size_t m = i + 1; m < j; ++m) {
          const double l = best[i * k + m], r = best[m * k + j];
          if (l < 0 || r < 0 || std::min(l, r) <= best[i * k + j]) continue;
          const Vec3 &A = X[p[i]], &B = X[p[m]], &C = X[p[j]];
          if (orient3d(A, B, C, X[a]) != sign || orient3d(A, B, C, X[b]) != -sign) continue;
          const double floor = std::max(need, best[i * k + j]);
          const double ka = min_solid_angle_tan_half(A, B, C, X[a]);
          if (!(ka > floor)) continue;
          const double worst = std::min({l, r, ka, min_solid_angle_tan_half(A, B, C, X[b])});
          if (worst > floor) best[i * k + j] = worst, split[i * k + j] = static_cast<int>(m);
        }
      }
    if (best[0 * k + k - 1] < 0) continue;
    fresh->clear();
    std::vector<std::pair<std::size_t, std::size_t>> todo{{0, k - 1}};
    while (!todo.empty()) {
      const auto [i, j] = todo.back();
      todo.pop_back();
      if (j < i + 2) continue;
      const std::size_t m = static_cast<std::size_t>(split[i * k + j]);
      fresh->push_back(sign > 0 ? Tet{p[i], p[m], p[j], a} : Tet{p[m], p[i], p[j], a});
      fresh->push_back(sign > 0 ? Tet{p[m], p[i], p[j], b} : Tet{p[i], p[m], p[j], b});
      todo.push_back({i, m});
      todo.push_back({m, j});
    }
    return true;
  }
  return false;
}

}  // namespace bisect::tet
