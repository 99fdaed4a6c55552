#include "domain/surface_intersections.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <vector>

#include "bisect/errors.hpp"
#include "geom/box_grid.hpp"
#include "geom/loop_triangulation.hpp"
#include "geom/predicates.hpp"
#include "geom/segment_triangle.hpp"

namespace bisect {
namespace {

using geom::orient2d;
using geom::orient3d;

struct Tri {
  std::array<Index, 3> v;
  Index face;
  Vec3 lo, hi;
};

// Triangles of every face (holes included) in the face's own plane.
std::vector<Tri> triangulate(const PolyInput& in) {
  std::vector<std::vector<Index>> holes(in.faces.size());
  for (std::size_t f = 0; f < in.faces.size(); ++f)
    if (in.faces[f].hole_of >= 0) holes[in.faces[f].hole_of].push_back(static_cast<Index>(f));
  std::vector<Tri> out;
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    const PolyFace& face = in.faces[f];
    if (face.hole_of >= 0) continue;
    std::vector<std::vector<Index>> loops{face.nodes};
    for (Index h : holes[f]) loops.push_back(in.faces[h].nodes);
    Vec3 n = Vec3::Zero();
    for (std::size_t i = 0; i < face.nodes.size(); ++i)
      n += in.nodes[face.nodes[i]].cross(in.nodes[face.nodes[(i + 1) % face.nodes.size()]]);
    const Vec3 a = std::abs(n.x()) < 0.6 * n.norm() ? Vec3::UnitX() : Vec3::UnitY();
    const Vec3 e1 = n.cross(a).normalized(), e2 = n.normalized().cross(e1);
    std::vector<Vec2> pts;
    std::vector<Index> node;
    std::vector<std::vector<int>> idx;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      std::vector<Index> loop = loops[l];
      // outer counter-clockwise about n, holes clockwise
      Vec3 ln = Vec3::Zero();
      for (std::size_t i = 0; i < loop.size(); ++i) ln += in.nodes[loop[i]].cross(in.nodes[loop[(i + 1) % loop.size()]]);
      if ((ln.dot(n) > 0) != (l == 0)) std::reverse(loop.begin(), loop.end());
      idx.emplace_back();
      for (Index v : loop) {
        idx.back().push_back(static_cast<int>(pts.size()));
        pts.push_back({in.nodes[v].dot(e1), in.nodes[v].dot(e2)});
        node.push_back(v);
      }
    }
    std::vector<std::array<int, 3>> t = triangulate_loops(pts, idx);
    if (t.empty() && loops.size() == 1)  // a fan still covers a face that ear clipping refused
      for (std::size_t i = 1; i + 1 < face.nodes.size(); ++i) t.push_back({0, static_cast<int>(i), static_cast<int>(i + 1)});
    for (const auto& tr : t) {
      Tri x{{node[tr[0]], node[tr[1]], node[tr[2]]}, static_cast<Index>(f), {}, {}};
      x.lo = in.nodes[x.v[0]].cwiseMin(in.nodes[x.v[1]]).cwiseMin(in.nodes[x.v[2]]);
      x.hi = in.nodes[x.v[0]].cwiseMax(in.nodes[x.v[1]]).cwiseMax(in.nodes[x.v[2]]);
      out.push_back(x);
    }
  }
  return out;
}

int dominant_axis(const Vec3& n) {
  const Vec3 a = n.cwiseAbs();
  return a.x() >= a.y() && a.x() >= a.z() ? 0 : (a.y() >= a.z() ? 1 : 2);
}
Vec2 drop(const Vec3& p, int axis) { return axis == 0 ? Vec2(p.y(), p.z()) : axis == 1 ? Vec2(p.z(), p.x()) : Vec2(p.x(), p.y()); }

// 2D: do segments pq and ab share a point? (closed segments)
bool segments_meet_2d(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b) {
  const int o1 = orient2d(p, q, a), o2 = orient2d(p, q, b), o3 = orient2d(a, b, p), o4 = orient2d(a, b, q);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  auto on = [](const Vec2& s, const Vec2& t, const Vec2& x) {
    return orient2d(s, t, x) == 0 && x.x() >= std::min(s.x(), t.x()) && x.x() <= std::max(s.x(), t.x()) &&
           x.y() >= std::min(s.y(), t.y()) && x.y() <= std::max(s.y(), t.y());
  };
  return on(p, q, a) || on(p, q, b) || on(a, b, p) || on(a, b, q);
}

bool point_in_tri_2d(const Vec2& x, const Vec2& a, const Vec2& b, const Vec2& c) {
  const int s = orient2d(a, b, c);
  return orient2d(a, b, x) * s >= 0 && orient2d(b, c, x) * s >= 0 && orient2d(c, a, x) * s >= 0;
}

// Does the closed segment pq meet the closed triangle abc? Sets *coplanar when it lies in its plane.
// *proper: it passes through the triangle's interior (a crossing, not a touch).
bool segment_meets_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c, bool* coplanar,
                            bool* proper, Vec3* where) {
  const int sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
  *coplanar = false;
  *proper = false;
  if (sp * sq > 0) return false;
  if (sp == 0 && sq == 0) {
    *coplanar = true;
    const int ax = dominant_axis((b - a).cross(c - a));
    const Vec2 P = drop(p, ax), Q = drop(q, ax), A = drop(a, ax), B = drop(b, ax), C = drop(c, ax);
    *where = p;
    if (point_in_tri_2d(P, A, B, C)) return true;
    *where = q;
    if (point_in_tri_2d(Q, A, B, C)) return true;
    *where = 0.5 * (p + q);
    return segments_meet_2d(P, Q, A, B) || segments_meet_2d(P, Q, B, C) || segments_meet_2d(P, Q, C, A);
  }
  const int edges = geom::line_through_triangle(p, q, a, b, c);
  if (edges < 0) return false;
  *proper = sp * sq < 0 && edges == 0;
  *where = geom::plane_meeting(p, q, a, b, c);
  return true;
}

// The meeting of two triangles of different faces, beyond the nodes they share.
bool triangles_meet(const PolyInput& in, const Tri& s, const Tri& t, FaceIntersection* hit) {
  std::array<Index, 3> shared{};
  int n_shared = 0;
  for (Index a : s.v)
    for (Index b : t.v)
      if (a == b) shared[n_shared++] = a;
  auto P = [&](Index v) { return in.nodes[v]; };
  bool coplanar = false, proper = false;
  Vec3 where;
  if (n_shared >= 2) {
    // a common edge: they overlap only when coplanar and on the same side of it
    const Index a = shared[0], b = shared[1];
    Index x = -1, y = -1;
    for (Index v : s.v)
      if (v != a && v != b) x = v;
    for (Index v : t.v)
      if (v != a && v != b) y = v;
    if (x < 0 || y < 0 || orient3d(P(a), P(b), P(x), P(y)) != 0) return false;
    const int ax = dominant_axis((P(b) - P(a)).cross(P(x) - P(a)));
    if (orient2d(drop(P(a), ax), drop(P(b), ax), drop(P(x), ax)) * orient2d(drop(P(a), ax), drop(P(b), ax), drop(P(y), ax)) > 0) {
      *hit = {s.face, t.face, (P(a) + P(b) + P(x) + P(y)) / 4, "coplanar_overlap"};
      return true;
    }
    return false;
  }
  // edges of one triangle against the other; with one shared node, only the edges away from it
  bool met = false;
  for (int pass = 0; pass < 2; ++pass) {
    const Tri& e = pass == 0 ? s : t;
    const Tri& f = pass == 0 ? t : s;
    for (int i = 0; i < 3; ++i) {
      const Index p = e.v[i], q = e.v[(i + 1) % 3];
      if (n_shared == 1 && (p == shared[0] || q == shared[0])) continue;
      if (segment_meets_triangle(P(p), P(q), P(f.v[0]), P(f.v[1]), P(f.v[2]), &coplanar, &proper, &where)) {
        // a crossing wins over a touch found first
        const char* kind = coplanar ? "coplanar_overlap" : (proper ? "crossing" : "touching");
        if (!met || std::string(kind) == "crossing") *hit = {s.face, t.face, where, kind};
        met = true;
      }
    }
  }
  return met;
}

}  // namespace

std::vector<FaceIntersection> find_surface_intersections(const PolyInput& in, std::size_t max_reports) {
  const std::vector<Tri> tris = triangulate(in);
  std::vector<FaceIntersection> out;
  if (tris.empty()) return out;
  Vec3 lo = tris[0].lo, hi = tris[0].hi;
  double mean = 0;
  for (const Tri& t : tris) lo = lo.cwiseMin(t.lo), hi = hi.cwiseMax(t.hi), mean += (t.hi - t.lo).maxCoeff();
  mean /= static_cast<double>(tris.size());
  const double cell = std::max(mean * 1.5, (hi - lo).maxCoeff() / 512 + 1e-300);
  geom::BoxGrid grid(lo, cell);
  for (std::size_t t = 0; t < tris.size(); ++t) grid.insert(t, tris[t].lo, tris[t].hi);
  grid.for_each_box([&](const geom::BoxGrid::Coord& at, const std::vector<std::size_t>& listed) {
    for (std::size_t x = 0; x < listed.size(); ++x)
      for (std::size_t y = x + 1; y < listed.size(); ++y) {
        const Tri &s = tris[listed[x]], &t = tris[listed[y]];
        if (s.face == t.face) continue;
        if ((s.hi.array() < t.lo.array()).any() || (t.hi.array() < s.lo.array()).any()) continue;
        // each pair once: in the box holding the low corner of the boxes' overlap
        if (grid.box_of(s.lo.cwiseMax(t.lo)) != at) continue;
        FaceIntersection hit;
        if (!triangles_meet(in, s, t, &hit)) continue;
        if (hit.face_a > hit.face_b) std::swap(hit.face_a, hit.face_b);
        bool dup = false;
        for (const auto& o : out) dup |= o.face_a == hit.face_a && o.face_b == hit.face_b;
        if (!dup && out.size() < max_reports) out.push_back(hit);
      }
  });
  return out;
}

void reject_surface_intersections(const PolyInput& in) {
  const std::vector<FaceIntersection> hits = find_surface_intersections(in, 100);
  if (hits.empty()) return;
  const FaceIntersection& h = hits.front();
  std::ostringstream m;
  m.precision(6);
  const std::string a = input_face_name(in, h.face_a), b = input_face_name(in, h.face_b);
  if (in.face_label.empty()) m << in.source << ": faces " << h.face_a + 1 << " and " << h.face_b + 1;
  else if (a == b) m << in.source << ": " << a << "'s tessellation folds: two of its facets";  // a B-rep proxy's
  else m << in.source << ": the tessellations of " << a << " and " << b;
  m << " intersect at (" << h.point.x() << ", " << h.point.y() << ", " << h.point.z() << ") (" << h.kind << ")";
  if (hits.size() > 1) m << "; " << hits.size() - 1 << (hits.size() >= 100 ? "+" : "") << " more pair(s)";
  throw InputError(m.str());
}

}  // namespace bisect
