#include "surface/region_mesher.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "bisect/errors.hpp"
#include "bisect/quality.hpp"
#include "geom/predicates.hpp"
#include "surface/projected_chart.hpp"
#include "surface/uv_triangulation.hpp"

namespace bisect::surface {
namespace {

using geom::orient2d;

constexpr double kPi = 3.14159265358979323846;
// Refinement: a triangle whose longest edge exceeds this many sizes is split; one with an angle
// under kMinAngle is split while its shortest edge exceeds kShortEdge sizes (smaller ones are left
// to the swaps and the smoothing, so that a small boundary angle cannot refine without end).
constexpr double kLongEdge = 1.35;
constexpr double kMinAngle = 30 * kPi / 180;
constexpr double kShortEdge = 0.55;
// A new node no nearer an existing one than this many sizes, nor nearer a boundary segment
// round the triangle it falls in than kNearSegment sizes (of the size or the segment's length).
constexpr double kNearest = 0.45;
constexpr double kNearSegment = 0.1;
// A boundary segment shorter than kShortEdge sizes (a cut line ending just beside a vertex of the
// face: flange at 10^5 had segments of 0.04 where the size is 0.17) would stand under a triangle
// of 12 degrees, as the refinement leaves small triangles alone. The size is taken down to the
// segment's length at its ends and grows from there by kShortGrowth per unit of distance, so
// that the triangles beside it are shaped like it; no lower than kShortFloor sizes.
constexpr double kShortGrowth = 1.0;
constexpr double kShortFloor = 0.1;

// The surface's first fundamental form J^T J at uv.
Eigen::Matrix2d first_fundamental_form(const ParametricSurface& s, const Vec2& uv) {
  Vec3 du, dv;
  s.derivatives(uv, &du, &dv);
  Eigen::Matrix2d M;
  M << du.dot(du), du.dot(dv), du.dot(dv), dv.dot(dv);
  return M;
}

// T with |T du|^2 = du^T M du, M made definite where it degenerates (a pole) by a small
// multiple of its trace.
Eigen::Matrix2d definite_root(Eigen::Matrix2d M) {
  const double tr = std::max(M.trace(), 1e-300);
  M += 1e-6 * tr * Eigen::Matrix2d::Identity();
  const Eigen::LLT<Eigen::Matrix2d> llt(M);
  return llt.matrixL().transpose();
}

// T with |T du|^2 = du^T (J^T J) du: the root of the first fundamental form at uv.
Eigen::Matrix2d metric_root(const ParametricSurface& s, const Vec2& uv) { return definite_root(first_fundamental_form(s, uv)); }

// The circumcentre of a, b, c under the linear map T, in the original coordinates.
bool metric_circumcentre(const Vec2& a, const Vec2& b, const Vec2& c, const Eigen::Matrix2d& T, Vec2* out) {
  const Vec2 B = T * (b - a), C = T * (c - a);
  const double d = 2 * (B.x() * C.y() - B.y() * C.x());
  if (!(std::abs(d) > 0)) return false;
  const double b2 = B.squaredNorm(), c2 = C.squaredNorm();
  const Vec2 centre((C.y() * b2 - B.y() * c2) / d, (B.x() * c2 - C.x() * b2) / d);
  *out = a + T.inverse() * centre;
  return out->allFinite();
}

class Mesher {
 public:
  Mesher(const ParametricSurface& s, const RegionBoundary& b, const RegionMeshOptions& o) : s_(s), b_(b), o_(o) {}

  RegionMesh run() {
    check();
    find_short_segments();
    triangulate_boundary();
    refine();
    unfold();
    if (o_.optimize)
      for (int pass = 0; pass < 8; ++pass) {
        const std::size_t swaps = swap_pass();
        const std::size_t moves = smooth_pass();
        if (swaps + moves == 0) break;
      }
    return output();
  }

 private:
  const ParametricSurface& s_;
  const RegionBoundary& b_;
  const RegionMeshOptions& o_;
  UvTriangulation tr_;
  std::vector<Vec3> xyz_;     // per triangulation point (the first three: the super triangle's, unused)
  std::vector<char> fixed_;   // boundary points
  std::size_t nb_ = 0;        // boundary nodes
  std::vector<std::pair<Vec3, double>> short_ends_;  // find_short_segments
  // The passes of swaps and smoothing keep each triangle's smallest angle (NaN: not known yet):
  // every swap tried and every node's fan asked for the angles of triangles that had not
  // changed since the pass before (their arc tangents were 8% of plate-hole's run at 10^5). A
  // swap sets its two triangles' (flip keeps their ids), a node's move its fan's.
  std::vector<double> angle_;
  std::vector<double> fan_angles_;  // smooth_pass's angles of a fan at a node's new place

  Index tp(Index boundary_node) const { return boundary_node + 3; }

  void check() {
    if (b_.uv.size() != b_.xyz.size()) throw MeshingError("surface region: " + std::to_string(b_.uv.size()) + " parameters for " + std::to_string(b_.xyz.size()) + " points");
    if (b_.loops.empty()) throw MeshingError("surface region: no boundary loop");
    for (std::size_t l = 0; l < b_.loops.size(); ++l) {
      if (b_.loops[l].size() < 2) throw MeshingError("surface region: loop " + std::to_string(l + 1) + " has fewer than two nodes");
      for (Index v : b_.loops[l])
        if (v < 0 || static_cast<std::size_t>(v) >= b_.uv.size())
          throw MeshingError("surface region: loop " + std::to_string(l + 1) + " refers to node " + std::to_string(v) + " of " + std::to_string(b_.uv.size()));
    }
    for (std::size_t i = 0; i < b_.uv.size(); ++i)
      if (!b_.uv[i].allFinite() || !b_.xyz[i].allFinite()) throw MeshingError("surface region: boundary node " + std::to_string(i + 1) + " is not a finite point");
    if (!o_.size) throw MeshingError("surface region: no size function");
  }

  double size_at(const Vec3& x) const {
    double h = o_.size(x);
    if (!(h > 0) || !std::isfinite(h)) throw MeshingError("surface region: the size function gave " + std::to_string(h));
    for (const auto& [p, length] : short_ends_) h = std::min(h, length + kShortGrowth * (x - p).norm());
    return h;
  }

  // the ends of the boundary's short segments, with the size there (see kShortGrowth)
  void find_short_segments() {
    for (const auto& loop : b_.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index a = loop[i], c = loop[(i + 1) % loop.size()];
        const double length = (b_.xyz[c] - b_.xyz[a]).norm();
        for (Index end : {a, c}) {
          const double h = o_.size(b_.xyz[end]);
          if (length < kShortEdge * h && length > 0) short_ends_.push_back({b_.xyz[end], std::max(length, kShortFloor * h)});
        }
      }
  }

  // RegionMeshOptions::boundary_in_surface_metric's metric: the root of the first fundamental
  // form summed over the boundary nodes (its scale does not matter to the Delaunay test).
  Eigen::Matrix2d boundary_metric() const {
    Eigen::Matrix2d sum = Eigen::Matrix2d::Zero();
    for (const Vec2& uv : b_.uv) {
      const Eigen::Matrix2d M = first_fundamental_form(s_, uv);
      if (M.allFinite()) sum += M;
    }
    return definite_root(sum);
  }

  void triangulate_boundary() {
    nb_ = b_.uv.size();
    Vec2 lo = b_.uv[0], hi = b_.uv[0];
    for (const Vec2& p : b_.uv) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    tr_.start(lo, hi);
    xyz_.assign(3, Vec3::Zero());
    fixed_.assign(3, 1);
    for (std::size_t i = 0; i < nb_; ++i) {
      tr_.uv.push_back(b_.uv[i]);
      xyz_.push_back(b_.xyz[i]);
      fixed_.push_back(1);
    }
    tr_.grow(tr_.uv.size());
    std::vector<char> done(nb_, 0);
    Index last = 0;
    const Eigen::Matrix2d metric = o_.boundary_in_surface_metric ? boundary_metric() : Eigen::Matrix2d(Eigen::Matrix2d::Identity());
    for (const auto& loop : b_.loops)
      for (Index v : loop) {
        if (done[v]) continue;
        done[v] = 1;
        const Index t = tr_.insert(tp(v), last, metric);
        if (t < 0)
          throw MeshingError("surface region: boundary node " + std::to_string(v + 1) + " at (u, v) = (" + std::to_string(b_.uv[v].x()) + ", " +
                             std::to_string(b_.uv[v].y()) + ") falls on another node or edge (loops that touch or cross)");
        last = t;
      }
    for (const auto& loop : b_.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index a = loop[i], c = loop[(i + 1) % loop.size()];
        if (a != c) tr_.constrain(tp(a), tp(c));
      }
    tr_.mark_inside();
  }

  bool degenerate(const UvTri& t) const {
    const Vec3 &a = xyz_[t.v[0]], &b = xyz_[t.v[1]], &c = xyz_[t.v[2]];
    return a == b || b == c || c == a;
  }

  // The length of the segment (a, b) as the surface measures it (the metric at its middle): a
  // chord would call a triangle spanning a full turn of a periodic surface (from u = 0 to 2 pi,
  // the same curve twice) small.
  double metric_length(Index a, Index b) const {
    const Vec2 d = tr_.uv[b] - tr_.uv[a];
    return (metric_root(s_, 0.5 * (tr_.uv[a] + tr_.uv[b])) * d).norm();
  }

  // Whether triangle t needs a node (and how: *large when it is too big), and the size there.
  bool bad(Index t, double* h, bool* large) const {
    const UvTri& T = tr_.tris[t];
    if (!T.alive || !T.inside || degenerate(T)) return false;
    const Vec3 &a = xyz_[T.v[0]], &b = xyz_[T.v[1]], &c = xyz_[T.v[2]];
    *h = size_at(s_.point((tr_.uv[T.v[0]] + tr_.uv[T.v[1]] + tr_.uv[T.v[2]]) / 3));
    const double l0 = metric_length(T.v[1], T.v[2]), l1 = metric_length(T.v[2], T.v[0]), l2 = metric_length(T.v[0], T.v[1]);
    const double longest = std::max({l0, l1, l2}), shortest = std::min({l0, l1, l2});
    *large = longest > kLongEdge * *h;
    if (*large) return true;
    return shortest > kShortEdge * *h && triangle_min_angle(a, b, c) < kMinAngle;
  }

  void refine() {
    std::deque<Index> queue;
    for (std::size_t t = 0; t < tr_.tris.size(); ++t)
      if (tr_.tris[t].alive && tr_.tris[t].inside) queue.push_back(static_cast<Index>(t));
    std::size_t inserted = 0, tried = 0;
    const std::size_t budget = 200 * (nb_ + 16) + 4 * queue.size();
    while (!queue.empty()) {
      if (++tried > 40 * budget) break;  // a safety net, far above any real need
      poll(tried);
      const Index t = queue.front();
      queue.pop_front();
      double h = 0;
      bool large = false;
      if (!bad(t, &h, &large)) continue;
      const UvTri T = tr_.tris[t];
      const Vec2 centroid = (tr_.uv[T.v[0]] + tr_.uv[T.v[1]] + tr_.uv[T.v[2]]) / 3;
      Vec2 c;
      Index at = -1;
      if (metric_circumcentre(tr_.uv[T.v[0]], tr_.uv[T.v[1]], tr_.uv[T.v[2]], metric_root(s_, centroid), &c)) at = tr_.locate(c, t);
      if (at < 0 || !tr_.tris[at].inside) {
        // outside the region, or beyond a boundary segment: the centroid instead, for a triangle
        // that is too large (a badly shaped one next to the boundary is left to the optimisation)
        if (!large) continue;
        c = centroid;
        at = t;
      }
      // a boundary segment of the triangle found, crossed on the way there, is not the region's
      // to split: the centre must see the located triangle's corners from inside the region
      const Vec3 x = s_.point(c);
      if (!x.allFinite()) continue;
      const double hx = std::min(h, size_at(x));
      bool near = false;
      const UvTri& A = tr_.tris[at];
      for (int k = 0; k < 3 && !near; ++k) near = (xyz_[A.v[k]] - x).norm() < kNearest * hx;
      // nearer a boundary segment of the located triangle than a third of a size: it would make
      // a needle there. Nearer one round its corners than kNearSegment sizes: a node came 10^-3
      // sizes off such a segment, which was not the located triangle's (corpus x_rod, a 0.14
      // degree triangle that no swap may mend, the segment being held)
      auto off = [&](const UvTri& U, int k) {
        const Vec3 &p = xyz_[U.v[(k + 1) % 3]], &q = xyz_[U.v[(k + 2) % 3]];
        const double f = std::clamp((x - p).dot(q - p) / std::max((q - p).squaredNorm(), 1e-300), 0.0, 1.0);
        return (p + f * (q - p) - x).norm() / std::max(hx, (q - p).norm());
      };
      for (int k = 0; k < 3 && !near; ++k) near = (A.held >> k & 1u) && off(A, k) < 0.35;
      for (int c = 0; c < 3 && !near; ++c)
        for (Index u : tr_.fan(A.v[c])) {
          for (int k = 0; k < 3 && !near; ++k) near = (tr_.tris[u].held >> k & 1u) && off(tr_.tris[u], k) < kNearSegment;
          if (near) break;
        }
      if (near) continue;
      tr_.uv.push_back(c);
      xyz_.push_back(x);
      fixed_.push_back(0);
      const Index v = static_cast<Index>(tr_.uv.size() - 1);
      if (tr_.insert(v, at, metric_root(s_, c)) < 0) {
        tr_.uv.pop_back(), xyz_.pop_back(), fixed_.pop_back();
        continue;
      }
      ++inserted;
      for (Index n : tr_.fan(v)) queue.push_back(n);
      if (bad(t, &h, &large)) queue.push_back(t);  // the slot may hold a new triangle
    }
  }

  // the triangle's 3D normal agrees with the surface's (the parametrisation's orientation)
  bool faces_up(const UvTri& T) const {
    if (degenerate(T)) return true;
    const Vec3 n = (xyz_[T.v[1]] - xyz_[T.v[0]]).cross(xyz_[T.v[2]] - xyz_[T.v[0]]);
    const Vec2 c = (tr_.uv[T.v[0]] + tr_.uv[T.v[1]] + tr_.uv[T.v[2]]) / 3;
    Vec3 du, dv;
    s_.derivatives(c, &du, &dv);
    return n.dot(du.cross(dv)) > 0;
  }

  double tri_min_angle(const UvTri& T) const {
    if (degenerate(T)) return kPi;  // a pole's triangle goes at the end
    return triangle_min_angle(xyz_[T.v[0]], xyz_[T.v[1]], xyz_[T.v[2]]);
  }
  // tri_min_angle of triangle t of the triangulation, from angle_ when known
  double kept_angle(Index t) {
    if (angle_.size() < tr_.tris.size()) angle_.resize(tr_.tris.size(), std::numeric_limits<double>::quiet_NaN());
    double& a = angle_[static_cast<std::size_t>(t)];
    if (std::isnan(a)) a = tri_min_angle(tr_.tris[t]);
    return a;
  }

  // Stop every 1,024 steps of the refinement and of the passes of swaps and smoothing too: those
  // passes over a large face ran a second and more between the refinement's polls
  // (tests/cpp/occ/test_brep_bounded_work.cpp: a cylinder at a chord deviation of 3e-4, Stop at
  // 1 s took effect at 1.8 s)
  void poll(std::size_t step) const {
    if ((step & 1023u) == 0 && o_.cancelled && o_.cancelled()) throw Cancelled();
  }

  // Angle-first swaps (5.5): an interior edge takes the quadrilateral's other diagonal when the
  // smaller angle of the two triangles grows, the new pair valid in (u, v) and facing up.
  std::size_t swap_pass() {
    std::size_t swaps = 0;
    for (std::size_t t = 0; t < tr_.tris.size(); ++t) {
      poll(t);
      const UvTri& T = tr_.tris[t];
      if (!T.alive || !T.inside) continue;
      for (int k = 0; k < 3; ++k) {
        const Index n = tr_.tris[t].nb[k];
        if (n < 0 || n < static_cast<Index>(t) || (tr_.tris[t].held >> k & 1u) || !tr_.tris[n].inside) continue;
        const UvTri& N = tr_.tris[n];
        const int j = tr_.side_towards(n, static_cast<Index>(t));
        const Index x = tr_.tris[t].v[k], y = tr_.tris[t].v[(k + 1) % 3], z = tr_.tris[t].v[(k + 2) % 3], w = N.v[j];
        if (orient2d(tr_.uv[x], tr_.uv[y], tr_.uv[w]) <= 0 || orient2d(tr_.uv[x], tr_.uv[w], tr_.uv[z]) <= 0) continue;
        const UvTri A{{x, y, w}, {-1, -1, -1}, 0, true, true}, B{{x, w, z}, {-1, -1, -1}, 0, true, true};
        if (degenerate(A) || degenerate(B) || !faces_up(A) || !faces_up(B)) continue;
        const double now = std::min(kept_angle(static_cast<Index>(t)), kept_angle(n));
        const double then_a = tri_min_angle(A), then_b = tri_min_angle(B);
        if (std::min(then_a, then_b) > now + 1e-3) {
          tr_.flip(static_cast<Index>(t), k);
          angle_[t] = then_a, angle_[static_cast<std::size_t>(n)] = then_b;
          ++swaps;
          break;
        }
      }
    }
    return swaps;
  }

  // Surface Laplace smoothing (5.4): a free node moves in (u, v) to its neighbours' mean weighted
  // by 3D length over parameter length, when the smallest angle round it does not fall and its
  // triangles stay positive in (u, v) and facing up.
  std::size_t smooth_pass() {
    std::size_t moves = 0;
    for (std::size_t v = 3 + nb_; v < tr_.uv.size(); ++v) {
      poll(v);
      const std::vector<Index> fan = tr_.fan(static_cast<Index>(v));
      if (fan.empty()) continue;
      Vec2 sum = Vec2::Zero();
      double weights = 0, before = kPi;
      bool interior = true;
      for (Index t : fan) {
        const UvTri& T = tr_.tris[t];
        if (!T.inside) interior = false;
        before = std::min(before, kept_angle(t));
        for (Index w : T.v) {
          if (w == static_cast<Index>(v)) continue;
          const double pl = (tr_.uv[w] - tr_.uv[v]).norm();
          if (!(pl > 0)) continue;
          const double wt = (xyz_[w] - xyz_[v]).norm() / pl;
          sum += wt * tr_.uv[w], weights += wt;
        }
      }
      if (!interior || !(weights > 0)) continue;
      const Vec2 old_uv = tr_.uv[v];
      const Vec3 old_x = xyz_[v];
      tr_.uv[v] = sum / weights;
      xyz_[v] = s_.point(tr_.uv[v]);
      bool ok = xyz_[v].allFinite();
      double after = kPi;
      fan_angles_.clear();
      for (Index t : fan) {
        if (!ok) break;
        const UvTri& T = tr_.tris[t];
        ok = orient2d(tr_.uv[T.v[0]], tr_.uv[T.v[1]], tr_.uv[T.v[2]]) > 0 && faces_up(T);
        fan_angles_.push_back(tri_min_angle(T));
        after = std::min(after, fan_angles_.back());
      }
      if (ok && after > before + 1e-9) {
        ++moves;
        for (std::size_t i = 0; i < fan.size(); ++i) angle_[static_cast<std::size_t>(fan[i])] = fan_angles_[i];
      } else {
        tr_.uv[v] = old_uv, xyz_[v] = old_x;
      }
    }
    return moves;
  }

  // Triangles counter-clockwise in (u, v) whose 3D normal is against the surface's: next to a
  // pole a triangle with a corner on the pole's segment far along it in u folds over in 3D. Each
  // is flipped with a neighbour when that leaves both facing up; any left fails the region (the
  // caller then meshes it over a plane).
  void unfold() {
    for (int pass = 0; pass < 8; ++pass) {
      std::size_t folded = 0, fixed = 0;
      for (std::size_t t = 0; t < tr_.tris.size(); ++t) {
        const UvTri& T = tr_.tris[t];
        if (!T.alive || !T.inside || faces_up(T)) continue;
        ++folded;
        for (int k = 0; k < 3; ++k) {
          const Index n = tr_.tris[t].nb[k];
          if (n < 0 || (tr_.tris[t].held >> k & 1u) || !tr_.tris[n].inside) continue;
          const int j = tr_.side_towards(n, static_cast<Index>(t));
          const Index x = tr_.tris[t].v[k], y = tr_.tris[t].v[(k + 1) % 3], z = tr_.tris[t].v[(k + 2) % 3], w = tr_.tris[n].v[j];
          if (orient2d(tr_.uv[x], tr_.uv[y], tr_.uv[w]) <= 0 || orient2d(tr_.uv[x], tr_.uv[w], tr_.uv[z]) <= 0) continue;
          const UvTri A{{x, y, w}, {-1, -1, -1}, 0, true, true}, B{{x, w, z}, {-1, -1, -1}, 0, true, true};
          if (degenerate(A) || degenerate(B) || !faces_up(A) || !faces_up(B)) continue;
          tr_.flip(static_cast<Index>(t), k);
          ++fixed;
          break;
        }
      }
      if (folded == 0) return;
      if (fixed == 0) break;
    }
    for (const UvTri& T : tr_.tris)
      if (T.alive && T.inside && !faces_up(T)) throw MeshingError("surface region: a triangle folds over in 3D (next to a pole?)");
  }

  RegionMesh output() {
    RegionMesh out;
    // a degenerate boundary segment's nodes are one point: the first of each run stands for all
    std::vector<Index> same(nb_);
    for (std::size_t i = 0; i < nb_; ++i) same[i] = static_cast<Index>(i);
    for (const auto& loop : b_.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index a = loop[i], c = loop[(i + 1) % loop.size()];
        if (a != c && b_.xyz[a] == b_.xyz[c] && same[c] == c) same[c] = same[a];
      }
    for (std::size_t i = 0; i < nb_; ++i) same[i] = same[same[i]];
    out.uv = b_.uv;
    out.xyz = b_.xyz;
    std::vector<Index> id(tr_.uv.size(), -1);
    for (std::size_t i = 0; i < nb_; ++i) id[tp(static_cast<Index>(i))] = same[i];
    for (std::size_t v = 3 + nb_; v < tr_.uv.size(); ++v) {
      id[v] = static_cast<Index>(out.uv.size());
      out.uv.push_back(tr_.uv[v]);
      out.xyz.push_back(xyz_[v]);
    }
    for (const UvTri& T : tr_.tris) {
      if (!T.alive || !T.inside) continue;
      const std::array<Index, 3> t{id[T.v[0]], id[T.v[1]], id[T.v[2]]};
      if (t[0] < 0 || t[1] < 0 || t[2] < 0) throw MeshingError("surface region: a triangle uses a point of the enclosing triangle");
      if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;  // on a pole's segment
      out.tris.push_back(t);
    }
    if (out.tris.empty()) throw MeshingError("surface region: no triangle inside the loops (are the outer loops counter-clockwise in (u, v)?)");
    return out;
  }
};

}  // namespace

RegionMesh mesh_region(const ParametricSurface& s, const RegionBoundary& b, const RegionMeshOptions& o) { return Mesher(s, b, o).run(); }

RegionMesh mesh_region_projected(const ParametricSurface& s, const RegionBoundary& b, const RegionMeshOptions& o) {
  // the plane: the mean of the surface's normals over the boundary (a thin region's own loop
  // has too little area to give a reliable normal)
  Vec3 n = Vec3::Zero();
  for (std::size_t i = 0; i < b.uv.size(); ++i) {
    Vec3 du, dv;
    s.derivatives(b.uv[i], &du, &dv);
    const Vec3 m = du.cross(dv);
    if (m.norm() > 1e-12 * (du.norm() * dv.norm() + 1e-300)) n += m.normalized();
  }
  if (!(n.norm() > 1e-6)) throw MeshingError("surface region: no plane its surface lies over");
  n.normalize();
  // the surface a graph over it: normals within 75 degrees, all on one side
  int side = 0;
  for (std::size_t i = 0; i < b.uv.size(); ++i) {
    Vec3 du, dv;
    s.derivatives(b.uv[i], &du, &dv);
    const Vec3 m = du.cross(dv);
    if (!(m.norm() > 1e-12 * (du.norm() * dv.norm() + 1e-300))) continue;  // a pole: no normal from (u, v)
    const double c = m.normalized().dot(n);
    if (std::abs(c) < 0.2588) throw MeshingError("surface region: too curved to be meshed over a plane");
    const int sg = c > 0 ? 1 : -1;
    if (side != 0 && sg != side) throw MeshingError("surface region: folds over its projection plane");
    side = sg;
  }
  const Vec3 e1 = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized(), e2 = n.cross(e1);
  ProjectedChart chart(s, b.xyz[b.loops[0][0]], e1, e2, b.uv[b.loops[0][0]]);
  // the boundary in the chart; a run of nodes at one point (a pole) is one node there
  RegionBoundary cb;
  std::vector<Index> back;  // chart node -> given node
  std::vector<Index> chart_id(b.uv.size(), -1);
  for (const auto& loop : b.loops) {
    std::vector<Index> cl;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Index v = loop[i];
      if (!cl.empty() && b.xyz[back[cl.back()]] == b.xyz[v]) continue;
      if (i + 1 == loop.size() && !cl.empty() && b.xyz[back[cl.front()]] == b.xyz[v]) continue;
      if (chart_id[v] < 0) {
        chart_id[v] = static_cast<Index>(cb.uv.size());
        cb.uv.push_back(chart.chart_of(b.xyz[v]));
        cb.xyz.push_back(b.xyz[v]);
        back.push_back(v);
        Vec3 du, dv;
        s.derivatives(b.uv[v], &du, &dv);
        if (du.cross(dv).norm() > 1e-12 * (du.norm() * dv.norm() + 1e-300)) chart.add_seed(b.uv[v]);
      }
      cl.push_back(chart_id[v]);
    }
    cb.loops.push_back(std::move(cl));
  }
  double area = 0;
  for (const auto& l : cb.loops)
    for (std::size_t i = 0; i < l.size(); ++i) {
      const Vec2 &p = cb.uv[l[i]], &q = cb.uv[l[(i + 1) % l.size()]];
      area += p.x() * q.y() - p.y() * q.x();
    }
  const bool reversed = area < 0;
  if (reversed)
    for (auto& l : cb.loops) std::reverse(l.begin(), l.end());
  const RegionMesh cm = Mesher(chart, cb, o).run();
  RegionMesh out;
  out.uv = b.uv;
  out.xyz = b.xyz;
  std::vector<Index> id(cm.uv.size());
  for (std::size_t i = 0; i < back.size(); ++i) id[i] = back[i];
  for (std::size_t v = back.size(); v < cm.uv.size(); ++v) {
    id[v] = static_cast<Index>(out.uv.size());
    out.uv.push_back(chart.surface_uv(cm.uv[v]));
    out.xyz.push_back(cm.xyz[v]);
  }
  for (const auto& t : cm.tris) {
    std::array<Index, 3> u{id[t[0]], id[t[1]], id[t[2]]};
    if (reversed) std::swap(u[1], u[2]);
    out.tris.push_back(u);
  }
  return out;
}

}  // namespace bisect::surface
