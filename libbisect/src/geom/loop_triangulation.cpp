#include "geom/loop_triangulation.hpp"

#include <algorithm>
#include <limits>

#include "geom/predicates.hpp"

namespace bisect {
namespace {

using geom::orient2d;

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d), o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

// Joins a hole to the outer loop by a bridge from the hole's rightmost point to the nearest outer
// point that sees it (no loop edge crosses the bridge).
bool bridge(const std::vector<Vec2>& pts, std::vector<int>& outer, const std::vector<int>& hole,
            const std::vector<std::vector<int>>& all) {
  std::size_t hi = 0;
  for (std::size_t i = 1; i < hole.size(); ++i)
    if (pts[hole[i]].x() > pts[hole[hi]].x()) hi = i;
  const Vec2 h = pts[hole[hi]];
  std::vector<std::size_t> order(outer.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return (pts[outer[x]] - h).squaredNorm() < (pts[outer[y]] - h).squaredNorm();
  });
  for (std::size_t oi : order) {
    const Vec2 o = pts[outer[oi]];
    bool blocked = false;
    for (const auto& loop : all)
      for (std::size_t i = 0; i < loop.size() && !blocked; ++i) {
        const int a = loop[i], b = loop[(i + 1) % loop.size()];
        if (a == outer[oi] || b == outer[oi] || a == hole[hi] || b == hole[hi]) continue;
        blocked = segments_cross(h, o, pts[a], pts[b]);
      }
    // the bridge must leave the outer vertex into the polygon's interior
    const int prev = outer[(oi + outer.size() - 1) % outer.size()], next = outer[(oi + 1) % outer.size()];
    const bool convex = orient2d(pts[prev], o, pts[next]) >= 0;
    const bool inside = convex ? orient2d(pts[prev], o, h) > 0 && orient2d(o, pts[next], h) > 0
                               : !(orient2d(pts[prev], o, h) <= 0 && orient2d(o, pts[next], h) <= 0);
    if (blocked || !inside) continue;
    std::vector<int> joined(outer.begin(), outer.begin() + static_cast<std::ptrdiff_t>(oi) + 1);
    for (std::size_t k = 0; k <= hole.size(); ++k) joined.push_back(hole[(hi + k) % hole.size()]);
    joined.insert(joined.end(), outer.begin() + static_cast<std::ptrdiff_t>(oi), outer.end());
    outer = std::move(joined);
    return true;
  }
  return false;
}

}  // namespace

std::vector<std::array<int, 3>> triangulate_loops(const std::vector<Vec2>& pts, const std::vector<std::vector<int>>& loops) {
  std::vector<std::array<int, 3>> tris;
  if (loops.empty() || loops[0].size() < 3) return tris;
  std::vector<int> poly = loops[0];
  for (std::size_t h = 1; h < loops.size(); ++h)
    if (!bridge(pts, poly, loops[h], loops)) return {};
  // Ear clipping; an ear's triangle is counter-clockwise and holds no other reflex point.
  std::vector<int> v = poly;
  std::size_t guard = 0;
  while (v.size() > 3) {
    if (++guard > 4 * poly.size() * poly.size() + 16) return {};
    bool clipped = false;
    const std::size_t n = v.size();
    for (std::size_t i = 0; i < n && !clipped; ++i) {
      const int a = v[(i + n - 1) % n], b = v[i], c = v[(i + 1) % n];
      if (orient2d(pts[a], pts[b], pts[c]) <= 0) continue;
      bool empty = true;
      for (std::size_t k = 0; k < n && empty; ++k) {
        const int p = v[k];
        if (p == a || p == b || p == c) continue;
        if (pts[p] == pts[a] || pts[p] == pts[b] || pts[p] == pts[c]) continue;  // bridge copies
        empty = !(orient2d(pts[a], pts[b], pts[p]) >= 0 && orient2d(pts[b], pts[c], pts[p]) >= 0 &&
                  orient2d(pts[c], pts[a], pts[p]) >= 0);
      }
      if (!empty) continue;
      tris.push_back({a, b, c});
      v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) return {};
  }
  if (orient2d(pts[v[0]], pts[v[1]], pts[v[2]]) <= 0) return {};
  tris.push_back({v[0], v[1], v[2]});
  return tris;
}

}  // namespace bisect
