#include "pipeline/brep_surface_flips.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include "bisect/quality.hpp"
#include "optimize/sliver_repair.hpp"
#include "optimize/surface_angles.hpp"
#include "util/edge_key.hpp"

namespace bisect::pipeline {
namespace {

using EdgeKey = std::uint64_t;

// A face piece's triangle: pieces[piece].tris[k].
struct Slot {
  std::size_t piece, k;
};

double cross2(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 u = b - a, v = c - a;
  return u.x() * v.y() - u.y() * v.x();
}

// How far the straight edge (a, b) lies off the surface at its middle.
double sag(const ParametricSurface& surf, const Vec3& a, const Vec3& b, const Vec2& ua, const Vec2& ub) {
  return (0.5 * (a + b) - surf.point(0.5 * (ua + ub))).norm();
}

class Flipper {
 public:
  Flipper(const BrepInput& in, BrepGrids& g, tet::TetComplex& cx, const std::vector<Vec3>& X) : in_(in), g_(g), cx_(cx), X_(X), at_(X.size(), -1), pole_(pole_vertices(in)) {
    for (std::size_t t = 0; t < cx.tet.size(); ++t)
      if (cx.alive[t])
        for (Index v : cx.tet[t]) at_[v] = static_cast<Index>(t);
  }

  // The flip of the edge (a, b) between the two triangles (see flip_surface_edges); true when made.
  bool flip(const Slot& s1, const Slot& s2, Index a, Index b);

 private:
  // The live tetrahedra holding the triangle (a, b, c): round a, from a tetrahedron at it (found
  // again by a search where a flip took the one recorded out without making one at a: a cap
  // taken off the outer boundary).
  std::vector<Index> tets_with(Index a, Index b, Index c) {
    std::vector<Index> out;
    if (at_[a] < 0 || !cx_.alive[at_[a]] || cx_.corner_of(at_[a], a) < 0) {
      const std::vector<Index> at = cx_.tets_at(a);
      at_[a] = at.empty() ? -1 : at.front();
    }
    if (at_[a] < 0) return out;
    for (Index t : cx_.star(a, at_[a], kStarLimit))
      if (cx_.corner_of(t, b) >= 0 && cx_.corner_of(t, c) >= 0) out.push_back(t);
    return out;
  }
  static constexpr std::size_t kStarLimit = 4096;

  const BrepInput& in_;
  BrepGrids& g_;
  tet::TetComplex& cx_;
  const std::vector<Vec3>& X_;
  std::vector<Index> at_;  // a live tetrahedron at each node
  std::vector<char> pole_;  // per B-rep vertex: a pole

  bool at_pole(const PointOn& on) const { return on.kind == PointOn::kVertex && pole_[on.id]; }
};

bool Flipper::flip(const Slot& s1, const Slot& s2, Index a, Index b) {
  FacePiece &P1 = g_.pieces[s1.piece], &P2 = g_.pieces[s2.piece];
  if (P1.face != P2.face) return false;
  const auto t1 = P1.tris[s1.k], t2 = P2.tris[s2.k];
  const auto uv1 = P1.tri_uv[s1.k], uv2 = P2.tri_uv[s2.k];
  // T1 = (p, q, r) as piece 1 runs; T2 holds q, p and s
  int i = 0;
  while (i < 3 && !((t1[i] == a && t1[(i + 1) % 3] == b) || (t1[i] == b && t1[(i + 1) % 3] == a))) ++i;
  if (i == 3) return false;
  const Index p = t1[i], q = t1[(i + 1) % 3], r = t1[(i + 2) % 3];
  int jp = -1, jq = -1, js = -1;
  for (int j = 0; j < 3; ++j) {
    if (t2[j] == p) jp = j;
    else if (t2[j] == q) jq = j;
    else js = j;
  }
  if (jp < 0 || jq < 0 || js < 0) return false;
  const Index s = t2[js];
  if (s == r) return false;
  const bool reversed = (jp + 1) % 3 == jq;  // piece 2 runs the other way round: (p, q, s)
  // a mesh edge that may run along a B-rep edge is never flipped
  if (!common_brep_edges(in_, g_.nodes.on[p], g_.nodes.on[q]).empty()) return false;
  // a pole (one end at most, never a new diagonal's) has a (u, v) of its own in each triangle,
  // somewhere on its segment: the other end says what the charts' shift is
  const bool pole_p = at_pole(g_.nodes.on[p]), pole_q = at_pole(g_.nodes.on[q]);
  if ((pole_p && pole_q) || at_pole(g_.nodes.on[r]) || at_pole(g_.nodes.on[s])) return false;
  // the same (u, v) at both ends in both triangles, up to a shift of the chart (a seam gives a
  // node two)
  const Vec2 shift = pole_p ? Vec2(uv2[jq] - uv1[(i + 1) % 3]) : Vec2(uv2[jp] - uv1[i]);
  const double tol = 1e-6 * (uv1[(i + 1) % 3] - uv1[i]).norm();
  if (!pole_p && !pole_q && (uv2[jq] - uv1[(i + 1) % 3] - shift).norm() > tol) return false;
  if (s1.piece == s2.piece && shift.norm() > tol) return false;
  // the nodes' (u, v) where they are now (the volume passes may have moved them); a pole's along
  // its segment as each edge at it needs (the other end's coordinate there)
  const ParametricSurface& surf = *in_.faces[P1.face].surface;
  Vec2 up = surf.closest_point(X_[p], uv1[i]), uq = surf.closest_point(X_[q], uv1[(i + 1) % 3]);
  const Vec2 ur = surf.closest_point(X_[r], uv1[(i + 2) % 3]), us = surf.closest_point(X_[s], uv2[js] - shift);
  int axis = -1;  // the pole's segment's coordinate
  if (pole_p || pole_q) {
    const Vec2 d = pole_p ? Vec2(uv2[jp] - shift - uv1[i]) : Vec2(uv2[jq] - shift - uv1[(i + 1) % 3]);
    axis = std::abs(d.x()) >= std::abs(d.y()) ? 0 : 1;
    if (pole_p) up = uv1[i];
    else uq = uv1[(i + 1) % 3];
  }
  const auto toward = [axis](Vec2 pole, const Vec2& other) {
    pole[axis] = other[axis];
    return pole;
  };
  // the quadrilateral convex: in (u, v), or at a pole in the plane across the two triangles'
  // normals' sum
  if (axis < 0) {
    const double turn = cross2(up, uq, ur);
    if (!(turn * cross2(uq, up, us) > 0 && turn * cross2(ur, up, us) > 0 && turn * cross2(us, uq, ur) > 0)) return false;
  } else {
    const Vec3 n = (X_[q] - X_[p]).cross(X_[r] - X_[p]).normalized() + (X_[p] - X_[q]).cross(X_[s] - X_[q]).normalized();
    const auto turn3 = [&](Index a, Index b, Index c) { return n.dot((X_[b] - X_[a]).cross(X_[c] - X_[a])); };
    if (!(turn3(p, q, r) > 0 && turn3(q, p, s) > 0 && turn3(r, p, s) > 0 && turn3(s, q, r) > 0)) return false;
  }
  const double was = std::min(triangle_min_angle_deg(X_[p], X_[q], X_[r]), triangle_min_angle_deg(X_[q], X_[p], X_[s]));
  const double now = std::min(triangle_min_angle_deg(X_[r], X_[p], X_[s]), triangle_min_angle_deg(X_[s], X_[q], X_[r]));
  if (!(now >= was + 0.01)) return false;
  const auto edge_sag = [&](Index a, Vec2 ua, Index b, Vec2 ub) {
    if (axis >= 0 && ((a == p && pole_p) || (a == q && pole_q))) ua = toward(ua, ub);
    if (axis >= 0 && ((b == p && pole_p) || (b == q && pole_q))) ub = toward(ub, ua);
    return sag(surf, X_[a], X_[b], ua, ub);
  };
  const double off = std::max({edge_sag(p, up, q, uq), edge_sag(q, uq, r, ur), edge_sag(r, ur, p, up), edge_sag(p, up, s, us), edge_sag(s, us, q, uq)});
  if (sag(surf, X_[r], X_[s], ur, us) > off + 1e-9 * (X_[r] - X_[s]).norm()) return false;
  // on each side, the tetrahedra round the edge from the face (p, q, r) to (p, q, s) give way to
  // the polygon r, ..., s they share with it triangulated and joined to p and to q (two
  // tetrahedra on each side for two, the 2-2 transformation; more where the ring is longer)
  const std::vector<Index> with_r = tets_with(p, q, r);
  if (with_r.empty() || with_r.size() > 2) return false;
  const double floor_cos = std::cos((was < optimize::kSurfaceAimDeg ? optimize::surface_trade_floor_deg(was) : optimize::kSurfaceDihedralBarDeg) * M_PI / 180);
  const auto worst_cos = [this](const tet::Tet& u) { return optimize::worst_dihedral_cos(X_[u[0]], X_[u[1]], X_[u[2]], X_[u[3]]); };
  std::vector<Index> old;
  std::vector<tet::Tet> fresh;
  std::vector<Index> tags;
  int caps = 0;  // sides where t is (p, q, r, s), both triangles' one tetrahedron: it goes
  for (Index t : with_r) {
    std::vector<Index> chain{r}, ring{t};
    for (Index cur = t;;) {
      Index next = -1;
      for (Index v : cx_.tet[cur])
        if (v != p && v != q && v != chain.back()) next = v;
      chain.push_back(next);
      if (next == s) break;
      const int f = cx_.corner_of(cur, chain[chain.size() - 2]);  // the face (p, q, next)
      if (cx_.is_constrained(cur, f) || chain.size() >= tet::TetComplex::kMaxRing) return false;
      cur = cx_.neighbour(cur, f);
      ring.push_back(cur);
    }
    std::vector<tet::Tet> made;
    if (chain.size() == 2) {
      // its faces (p, r, s) and (q, r, s) become the surface: inside the mesh, not on it already
      if (cx_.is_constrained(t, cx_.corner_of(t, q)) || cx_.is_constrained(t, cx_.corner_of(t, p)) || ++caps > 1) return false;
    } else if (!cx_.ring_triangulation(p, q, chain.data(), chain.size(), 0, &made)) {
      return false;
    }
    double bar = floor_cos;
    for (Index u : ring) bar = std::max(bar, worst_cos(cx_.tet[u]));
    for (const tet::Tet& u : made)
      if (!tet::positive(X_, u) || worst_cos(u) > bar) return false;
    old.insert(old.end(), ring.begin(), ring.end());
    fresh.insert(fresh.end(), made.begin(), made.end());
    tags.insert(tags.end(), made.size(), cx_.tag[t]);
  }
  if (tets_with(p, q, s).size() != with_r.size()) return false;  // (never: each side's ring ends at (p, q, s))
  // the outer boundary's map of input faces follows (an interface is not in it)
  const auto tag_r = cx_.surface_tag.find(tet::face_key(p, q, r)), tag_s = cx_.surface_tag.find(tet::face_key(p, q, s));
  if (tag_r != cx_.surface_tag.end() && tag_s != cx_.surface_tag.end()) {
    const Index face = tag_r->second;
    cx_.surface_tag.erase(tag_r);
    cx_.surface_tag.erase(tag_s);
    cx_.surface_tag[tet::face_key(p, s, r)] = face;
    cx_.surface_tag[tet::face_key(s, q, r)] = face;
  }
  const std::vector<Index> ids = cx_.replace(old, fresh, true);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const Index id = ids[k];
    cx_.tag[id] = tags[k];
    for (Index v : cx_.tet[id]) at_[v] = id;
    // a new surface triangle (r, s and p or q): held, the face opposite the fourth node
    if (cx_.corner_of(id, r) < 0 || cx_.corner_of(id, s) < 0 || (cx_.corner_of(id, p) < 0) == (cx_.corner_of(id, q) < 0)) continue;
    for (int c = 0; c < 4; ++c)
      if (cx_.tet[id][c] != r && cx_.tet[id][c] != s && cx_.tet[id][c] != p && cx_.tet[id][c] != q) cx_.hold(id, c);
  }
  // the pieces' triangles, each in its own chart (stale (u, v) stay stale: the caller's
  // follow-up takes every moved node's from its position)
  // (a pole's at the middle of the other two's along its segment)
  const Vec2 ur1 = uv1[(i + 2) % 3], us2 = uv2[js];
  Vec2 up1 = uv1[i], uq2 = uv2[jq];
  if (pole_p) up1 = toward(up1, 0.5 * (ur1 + us2 - shift));
  if (pole_q) uq2 = toward(uq2, 0.5 * (ur1 + shift + us2));
  P1.tris[s1.k] = {r, p, s};
  P1.tri_uv[s1.k] = {ur1, up1, us2 - shift};
  if (!reversed) {
    P2.tris[s2.k] = {s, q, r};
    P2.tri_uv[s2.k] = {us2, uq2, ur1 + shift};
  } else {
    P2.tris[s2.k] = {s, r, q};
    P2.tri_uv[s2.k] = {us2, ur1 + shift, uq2};
  }
  return true;
}

}  // namespace

std::int64_t flip_surface_edges(const BrepInput& in, BrepGrids& g, tet::TetComplex& cx, const std::vector<Vec3>& X, int rounds) {
  Flipper flipper(in, g, cx, X);
  std::int64_t flips = 0;
  for (int round = 0; round < rounds; ++round) {
    // the edges of the triangles under the bar, the worst triangle's first
    std::vector<std::pair<double, EdgeKey>> work;
    std::unordered_map<EdgeKey, std::vector<Slot>> sides;
    for (const FacePiece& piece : g.pieces)
      for (const auto& t : piece.tris) {
        const double a = triangle_min_angle_deg(X[t[0]], X[t[1]], X[t[2]]);
        if (a >= optimize::kSurfaceWorkBelowDeg) continue;
        for (int e = 0; e < 3; ++e) {
          const EdgeKey key = edge_key(t[e], t[(e + 1) % 3]);
          work.push_back({a, key});
          sides[key];
        }
      }
    if (work.empty()) break;
    std::sort(work.begin(), work.end());
    for (std::size_t p = 0; p < g.pieces.size(); ++p)
      for (std::size_t k = 0; k < g.pieces[p].tris.size(); ++k) {
        const auto& t = g.pieces[p].tris[k];
        for (int e = 0; e < 3; ++e) {
          const auto it = sides.find(edge_key(t[e], t[(e + 1) % 3]));
          if (it != sides.end()) it->second.push_back({p, k});
        }
      }
    // a triangle flipped this round is not taken up again until the next (the edges' lists
    // above are this round's)
    std::vector<std::vector<char>> flipped(g.pieces.size());
    for (std::size_t p = 0; p < g.pieces.size(); ++p) flipped[p].assign(g.pieces[p].tris.size(), 0);
    std::int64_t made = 0;
    for (const auto& [angle, key] : work) {
      const std::vector<Slot>& two = sides[key];
      if (two.size() != 2 || flipped[two[0].piece][two[0].k] || flipped[two[1].piece][two[1].k]) continue;
      const auto a = static_cast<Index>(key >> 32), b = static_cast<Index>(key & 0xffffffffu);
      if (!flipper.flip(two[0], two[1], a, b)) continue;
      flipped[two[0].piece][two[0].k] = flipped[two[1].piece][two[1].k] = 1;
      ++made;
    }
    flips += made;
    if (made == 0) break;
  }
  return flips;
}

}  // namespace bisect::pipeline
