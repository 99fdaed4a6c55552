// Areas and nesting of a 2D input's polygons (thesis 4.6.1): which polygon lies inside which, so
// that a region's net area leaves out its holes and sub-domains.
#include <algorithm>
#include <cmath>

#include "bisect/poly_input.hpp"
#include "geom/predicates.hpp"

namespace bisect {
namespace {

double signed_area(const Poly2Input& in, const std::vector<Index>& poly) {
  double a = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& p = in.nodes[poly[i]];
    const Vec2& q = in.nodes[poly[(i + 1) % poly.size()]];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

// -1 outside, 0 on the boundary, +1 inside; exact, by crossing parity with orient2d deciding
// on which side of each crossed edge the point lies.
int locate(const Poly2Input& in, const std::vector<Index>& poly, const Vec2& p) {
  bool inside = false;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& a = in.nodes[poly[i]];
    const Vec2& b = in.nodes[poly[(i + 1) % poly.size()]];
    const int o = geom::orient2d(a, b, p);
    if (o == 0 && std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
        std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y()))
      return 0;
    // Half-open rule on y so that a vertex on the ray counts once.
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const int side = b.y() > a.y() ? o : -o;  // +1: p left of the upward edge
      if (side > 0) inside = !inside;
    }
  }
  return inside ? 1 : -1;
}

// Polygon `inner` lies inside `outer` when none of its nodes is outside and at least one is
// strictly inside (polygons of a valid input do not cross; they may share nodes and edges).
bool lies_inside(const Poly2Input& in, const std::vector<Index>& inner, const std::vector<Index>& outer) {
  bool strictly = false;
  for (Index v : inner) {
    const int where = locate(in, outer, in.nodes[v]);
    if (where < 0) return false;
    if (where > 0) strictly = true;
  }
  if (strictly) return true;
  // Every node on the outer boundary: decide by an edge midpoint of the inner polygon that is
  // not an edge of the outer one.
  for (std::size_t i = 0; i < inner.size(); ++i) {
    const Vec2 mid = 0.5 * (in.nodes[inner[i]] + in.nodes[inner[(i + 1) % inner.size()]]);
    const int where = locate(in, outer, mid);
    if (where != 0) return where > 0;
  }
  return false;  // the same polygon
}

}  // namespace

Poly2Summary summarize(const Poly2Input& in) {
  Poly2Summary s;
  s.nodes = in.nodes.size();
  if (!in.nodes.empty()) {
    s.bbox_min = s.bbox_max = in.nodes[0];
    for (const Vec2& p : in.nodes) {
      s.bbox_min = s.bbox_min.cwiseMin(p);
      s.bbox_max = s.bbox_max.cwiseMax(p);
    }
  }
  const std::size_t n = in.polygons.size();
  s.polygons.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.polygons[i].nodes = in.polygons[i].nodes.size();
    s.polygons[i].hole = in.polygons[i].hole;
    s.polygons[i].area = std::abs(signed_area(in, in.polygons[i].nodes));
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      // Holes count as containers too: an island in a hole lies in the hole, not in the region
      // around it.
      if (i == j || s.polygons[j].area <= s.polygons[i].area) continue;
      if (!lies_inside(in, in.polygons[i].nodes, in.polygons[j].nodes)) continue;
      Index& best = s.polygons[i].inside;
      if (best < 0 || s.polygons[j].area < s.polygons[best].area) best = Index(j);
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!s.polygons[i].hole) s.polygons[i].net_area = s.polygons[i].area;
  for (std::size_t i = 0; i < n; ++i) {
    const Index outer = s.polygons[i].inside;
    if (outer >= 0 && !s.polygons[outer].hole) s.polygons[outer].net_area -= s.polygons[i].area;
  }
  for (const auto& p : s.polygons) s.area += p.net_area;
  return s;
}

}  // namespace bisect
