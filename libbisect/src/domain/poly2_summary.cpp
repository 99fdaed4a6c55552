// Areas and nesting of a 2D input's polygons (thesis 4.6.1): which polygon lies inside which, so
// that a region's net area leaves out its holes and sub-domains; and the check that no two
// polygons overlap in part.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/poly_input.hpp"
#include "domain/poly2_overlaps.hpp"
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


// ---- overlapping polygons ----

bool on_segment(const Vec2& a, const Vec2& b, const Vec2& p) {  // p collinear with ab assumed
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
         p.y() <= std::max(a.y(), b.y());
}

struct Pieces {
  bool in = false, out = false, all_on = true;
};

// Where polygon p's edges run with respect to polygon q, edge pieces cut at q's vertices: some
// piece strictly inside q, some strictly outside, or every piece on q's boundary. Sets *cross to a
// point where an edge of p properly crosses one of q's (false when none does).
Pieces pieces(const Poly2Input& in, const std::vector<Index>& p, const std::vector<Index>& q, bool* cross, Vec2* where) {
  Pieces r;
  const auto& X = in.nodes;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 &a = X[p[i]], &b = X[p[(i + 1) % p.size()]];
    std::vector<Vec2> cuts{a, b};
    for (std::size_t j = 0; j < q.size(); ++j) {
      const Vec2 &c = X[q[j]], &d = X[q[(j + 1) % q.size()]];
      const int oc = geom::orient2d(a, b, c), od = geom::orient2d(a, b, d);
      if (oc * od < 0 && geom::orient2d(c, d, a) * geom::orient2d(c, d, b) < 0) {
        *cross = true;
        const double t = std::abs((c - a).x() * (d - c).y() - (c - a).y() * (d - c).x()) /
                         std::max(std::abs((b - a).x() * (d - c).y() - (b - a).y() * (d - c).x()), 1e-300);
        *where = a + std::clamp(t, 0.0, 1.0) * (b - a);
        return r;
      }
      if (oc == 0 && c != a && c != b && on_segment(a, b, c)) cuts.push_back(c);
    }
    std::sort(cuts.begin() + 1, cuts.end(), [&](const Vec2& u, const Vec2& v) { return (u - a).squaredNorm() < (v - a).squaredNorm(); });
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const Vec2 &u = cuts[k], &v = cuts[k + 1];
      if (u == v) continue;
      bool on = false;  // the piece lies along an edge of q (decided exactly, from its ends)
      for (std::size_t j = 0; j < q.size() && !on; ++j) {
        const Vec2 &c = X[q[j]], &d = X[q[(j + 1) % q.size()]];
        on = geom::orient2d(c, d, u) == 0 && geom::orient2d(c, d, v) == 0 && on_segment(c, d, u) && on_segment(c, d, v);
      }
      if (on) continue;
      r.all_on = false;
      const Vec2 mid = 0.5 * (u + v);
      const int at = locate(in, q, mid);
      if (at > 0 && !r.in) r.in = true, *where = mid;
      if (at < 0) r.out = true;
    }
  }
  return r;
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

namespace bisect {

void reject_overlapping_polygons(const Poly2Input& in) {
  const std::size_t n = in.polygons.size();
  std::vector<Vec2> lo(n), hi(n);
  for (std::size_t i = 0; i < n; ++i) {
    lo[i] = hi[i] = in.nodes[in.polygons[i].nodes[0]];
    for (Index v : in.polygons[i].nodes) lo[i] = lo[i].cwiseMin(in.nodes[v]), hi[i] = hi[i].cwiseMax(in.nodes[v]);
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if ((lo[i].array() >= hi[j].array()).any() || (lo[j].array() >= hi[i].array()).any()) continue;  // apart
      const auto& P = in.polygons[i].nodes;
      const auto& Q = in.polygons[j].nodes;
      bool cross = false, cross_back = false;
      Vec2 where = Vec2::Zero(), where_back = Vec2::Zero();
      const Pieces pq = pieces(in, P, Q, &cross, &where);
      const Pieces qp = cross ? Pieces{} : pieces(in, Q, P, &cross_back, &where_back);
      std::string how;
      if (cross || cross_back) {
        how = "their edges cross";
        if (!cross) where = where_back;
      } else if (pq.in && pq.out) {
        how = "polygon " + std::to_string(i + 1) + " runs both inside and outside polygon " + std::to_string(j + 1);
      } else if (qp.in && qp.out) {
        how = "polygon " + std::to_string(j + 1) + " runs both inside and outside polygon " + std::to_string(i + 1);
        where = where_back;
      } else if (pq.all_on) {
        how = "they have the same outline";
        where = in.nodes[P[0]];
      } else {
        continue;  // one inside the other (a hole or a sub-domain), or side by side
      }
      std::ostringstream msg;
      msg.precision(9);
      msg << in.source << ": polygons " << i + 1 << " and " << j + 1 << " overlap (" << how << ", at (" << where.x() << ", "
          << where.y() << ")); polygons may share edges or lie one inside the other, but not overlap in part";
      throw InputError(msg.str());
    }
}

}  // namespace bisect
