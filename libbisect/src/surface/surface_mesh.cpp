#include "surface/surface_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"

namespace bisect::surface {
namespace {

using geom::incircle;
using geom::orient2d;

double corner_angle(const Vec3& p, const Vec3& q, const Vec3& r) {  // at p
  const Vec3 a = q - p, b = r - p;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

double min_angle(const SurfaceMesh& m, Index a, Index b, Index c) {
  const Vec3 &p = m.xyz[a], &q = m.xyz[b], &r = m.xyz[c];
  return std::min({corner_angle(p, q, r), corner_angle(q, r, p), corner_angle(r, p, q)});
}

// For each interior edge: the two triangles and their corners opposite it.
struct EdgeSide {
  int tri;
  int corner;  // index 0..2 of the corner opposite the edge
};
std::map<std::pair<Index, Index>, std::vector<EdgeSide>> edge_table(const SurfaceMesh& m) {
  std::map<std::pair<Index, Index>, std::vector<EdgeSide>> e;
  for (std::size_t t = 0; t < m.tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index a = m.tris[t][(k + 1) % 3], b = m.tris[t][(k + 2) % 3];
      e[{std::min(a, b), std::max(a, b)}].push_back({static_cast<int>(t), k});
    }
  return e;
}

// The quadrilateral of edge (a, b) with corners c (triangle a b c) and d (triangle b a d), when
// both triangles exist and the swapped pair (c d) is valid in parameter space.
struct Quad {
  int t1, t2;
  Index a, b, c, d;
};
bool quad_of(const SurfaceMesh& m, const std::vector<EdgeSide>& sides, Quad* q) {
  if (sides.size() != 2) return false;
  const auto& T1 = m.tris[sides[0].tri];
  const auto& T2 = m.tris[sides[1].tri];
  q->t1 = sides[0].tri, q->t2 = sides[1].tri;
  q->c = T1[sides[0].corner];
  q->a = T1[(sides[0].corner + 1) % 3], q->b = T1[(sides[0].corner + 2) % 3];
  q->d = T2[sides[1].corner];
  // swapped triangles (c, a, d) and (d, b, c) must stay counter-clockwise in parameter space
  return orient2d(m.uv[q->c], m.uv[q->a], m.uv[q->d]) > 0 && orient2d(m.uv[q->d], m.uv[q->b], m.uv[q->c]) > 0;
}

// The edge tables are made at a pass's start: whether the quad's triangles are still as they were.
bool still_there(const SurfaceMesh& m, const Quad& q) {
  auto has = [](const std::array<Index, 3>& t, Index v) { return std::find(t.begin(), t.end(), v) != t.end(); };
  return has(m.tris[q.t1], q.a) && has(m.tris[q.t1], q.b) && has(m.tris[q.t1], q.c) && has(m.tris[q.t2], q.a) &&
         has(m.tris[q.t2], q.b) && has(m.tris[q.t2], q.d);
}

void swap(SurfaceMesh& m, const Quad& q) {
  m.tris[q.t1] = {q.c, q.a, q.d};
  m.tris[q.t2] = {q.d, q.b, q.c};
}

// Whether d lies strictly inside the minimal circum-sphere of triangle abc.
bool in_minimal_sphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 ab = b - a, ac = c - a, n = ab.cross(ac);
  const double n2 = n.squaredNorm();
  if (n2 <= 0) return false;
  const Vec3 centre = a + (ac.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ac.cross(n)) / (2 * n2);
  const double r2 = (a - centre).squaredNorm();
  return (d - centre).squaredNorm() < r2 * (1 - 1e-12);
}

}  // namespace

SurfaceMesh grid_nodes(const ParametricSurface& s, int n) {
  SurfaceMesh m;
  const Vec2 lo = s.uv_min(), hi = s.uv_max();
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const Vec2 uv = lo + Vec2(static_cast<double>(i) / n, static_cast<double>(j) / n).cwiseProduct(hi - lo);
      m.uv.push_back(uv);
      m.xyz.push_back(s.point(uv));
      m.fixed.push_back(i == 0 || j == 0 || i == n || j == n);
    }
  return m;
}

void delaunay_in_parameters(SurfaceMesh& m) {
  const std::size_t n = m.uv.size();
  if (n < 3) throw MeshingError("surface Delaunay: fewer than three nodes");
  Vec2 lo = m.uv[0], hi = m.uv[0];
  for (const Vec2& p : m.uv) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Vec2 mid = 0.5 * (lo + hi);
  const double span = std::max((hi - lo).maxCoeff(), 1e-300) * 100;
  std::vector<Vec2> pts = m.uv;  // the three corners of a super triangle follow the nodes
  pts.push_back(mid + Vec2(-2 * span, -span));
  pts.push_back(mid + Vec2(2 * span, -span));
  pts.push_back(mid + Vec2(0, 2 * span));
  std::vector<std::array<Index, 3>> tris{{static_cast<Index>(n), static_cast<Index>(n + 1), static_cast<Index>(n + 2)}};
  for (std::size_t p = 0; p < n; ++p) {
    // the cavity: triangles whose circumcircle holds p; its boundary is joined to p
    std::map<std::pair<Index, Index>, int> boundary;
    std::vector<std::array<Index, 3>> keep;
    for (const auto& t : tris) {
      if (incircle(pts[t[0]], pts[t[1]], pts[t[2]], pts[p]) > 0) {
        for (int k = 0; k < 3; ++k) {
          const Index a = t[k], b = t[(k + 1) % 3];
          auto it = boundary.find({b, a});
          if (it != boundary.end()) boundary.erase(it);
          else boundary[{a, b}] = 1;
        }
      } else {
        keep.push_back(t);
      }
    }
    for (const auto& [e, one] : boundary) keep.push_back({e.first, e.second, static_cast<Index>(p)});
    tris = std::move(keep);
  }
  m.tris.clear();
  for (const auto& t : tris)
    if (t[0] < static_cast<Index>(n) && t[1] < static_cast<Index>(n) && t[2] < static_cast<Index>(n) &&
        orient2d(m.uv[t[0]], m.uv[t[1]], m.uv[t[2]]) > 0)
      m.tris.push_back(t);
}

std::size_t surface_delaunay_swaps(SurfaceMesh& m, int max_passes) {
  std::size_t swaps = 0;
  for (int pass = 0; pass < max_passes; ++pass) {
    std::size_t this_pass = 0;
    for (const auto& [e, sides] : edge_table(m)) {
      Quad q;
      if (!quad_of(m, sides, &q)) continue;
      if (!still_there(m, q)) continue;  // a swap earlier in this pass changed it
      const bool violated = in_minimal_sphere(m.xyz[q.a], m.xyz[q.b], m.xyz[q.c], m.xyz[q.d]) ||
                            in_minimal_sphere(m.xyz[q.b], m.xyz[q.a], m.xyz[q.d], m.xyz[q.c]);
      // swap only into a pair that does not violate in turn, so that swaps cannot cycle
      const bool fixed_after = !in_minimal_sphere(m.xyz[q.c], m.xyz[q.a], m.xyz[q.d], m.xyz[q.b]) &&
                               !in_minimal_sphere(m.xyz[q.d], m.xyz[q.b], m.xyz[q.c], m.xyz[q.a]);
      if (violated && fixed_after) {
        swap(m, q);
        ++this_pass;
      }
    }
    swaps += this_pass;
    if (this_pass == 0) break;
  }
  return swaps;
}

double mid_edge_error(const SurfaceMesh& m, const ParametricSurface& s, Index a, Index b) {
  const Vec3 mid = 0.5 * (m.xyz[a] + m.xyz[b]);
  const Vec2 uv = s.closest_point(mid, 0.5 * (m.uv[a] + m.uv[b]));
  return (s.point(uv) - mid).norm();
}

std::size_t surface_laplace_smooth(SurfaceMesh& m, const ParametricSurface& s, int passes) {
  std::vector<std::vector<Index>> nbr(m.uv.size()), around(m.uv.size());
  for (std::size_t t = 0; t < m.tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index a = m.tris[t][k];
      around[a].push_back(static_cast<Index>(t));
      for (int j = 1; j < 3; ++j) {
        const Index b = m.tris[t][(k + j) % 3];
        if (std::find(nbr[a].begin(), nbr[a].end(), b) == nbr[a].end()) nbr[a].push_back(b);
      }
    }
  auto local_min = [&](Index i) {
    double worst = M_PI;
    for (Index t : around[i]) worst = std::min(worst, min_angle(m, m.tris[t][0], m.tris[t][1], m.tris[t][2]));
    return worst;
  };
  std::size_t moves = 0;
  for (int pass = 0; pass < passes; ++pass)
    for (std::size_t i = 0; i < m.uv.size(); ++i) {
      if (m.fixed[i] || nbr[i].empty()) continue;
      Vec2 sum = Vec2::Zero();
      double weights = 0;
      for (Index j : nbr[i]) {
        const double pl = (m.uv[j] - m.uv[i]).norm();
        if (pl <= 0) continue;
        const double w = (m.xyz[j] - m.xyz[i]).norm() / pl;
        sum += w * m.uv[j], weights += w;
      }
      if (weights <= 0) continue;
      const Vec2 old_uv = m.uv[i];
      const Vec3 old_xyz = m.xyz[i];
      const double before = local_min(static_cast<Index>(i));
      m.uv[i] = sum / weights;
      m.xyz[i] = s.point(m.uv[i]);
      bool ok = local_min(static_cast<Index>(i)) >= before;
      for (Index t : around[i]) {
        const auto& T = m.tris[t];
        if (orient2d(m.uv[T[0]], m.uv[T[1]], m.uv[T[2]]) <= 0) ok = false;
        const Vec3 n = (m.xyz[T[1]] - m.xyz[T[0]]).cross(m.xyz[T[2]] - m.xyz[T[0]]);
        const Vec2 c = (m.uv[T[0]] + m.uv[T[1]] + m.uv[T[2]]) / 3;
        if (n.dot(s.normal(c)) <= 0) ok = false;
      }
      if (ok) {
        ++moves;
      } else {
        m.uv[i] = old_uv, m.xyz[i] = old_xyz;
      }
    }
  return moves;
}

std::size_t surface_angle_swaps(SurfaceMesh& m, const ParametricSurface& s, double angle_tol, int max_passes) {
  std::size_t swaps = 0;
  for (int pass = 0; pass < max_passes; ++pass) {
    std::size_t this_pass = 0;
    for (const auto& [e, sides] : edge_table(m)) {
      Quad q;
      if (!quad_of(m, sides, &q)) continue;
      if (!still_there(m, q)) continue;
      const double now = std::min(min_angle(m, q.a, q.b, q.c), min_angle(m, q.b, q.a, q.d));
      const double then = std::min(min_angle(m, q.c, q.a, q.d), min_angle(m, q.d, q.b, q.c));
      bool go = then > now + angle_tol;
      if (!go && std::abs(then - now) <= angle_tol)
        go = mid_edge_error(m, s, q.c, q.d) < mid_edge_error(m, s, q.a, q.b) * (1 - 1e-9);
      if (go) {
        swap(m, q);
        ++this_pass;
      }
    }
    swaps += this_pass;
    if (this_pass == 0) break;
  }
  return swaps;
}

SurfaceMeshQuality surface_quality(const SurfaceMesh& m, const ParametricSurface& s) {
  SurfaceMeshQuality q;
  q.min_angle = M_PI;
  for (const auto& t : m.tris)
    for (int k = 0; k < 3; ++k) {
      const double a = corner_angle(m.xyz[t[k]], m.xyz[t[(k + 1) % 3]], m.xyz[t[(k + 2) % 3]]);
      q.min_angle = std::min(q.min_angle, a), q.max_angle = std::max(q.max_angle, a);
    }
  std::map<std::pair<Index, Index>, char> edges;
  for (const auto& t : m.tris)
    for (int k = 0; k < 3; ++k) edges[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}] = 1;
  for (const auto& [e, one] : edges) {
    const double err = mid_edge_error(m, s, e.first, e.second);
    q.mean_edge_error += err, q.max_edge_error = std::max(q.max_edge_error, err);
  }
  q.mean_edge_error /= static_cast<double>(std::max<std::size_t>(edges.size(), 1));
  return q;
}

}  // namespace bisect::surface
