#include "size/wall_thickness.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace bisect::size {
namespace {

constexpr int kLeaf = 4;            // triangles per leaf of the ray tree
constexpr int kMaxSubdivide = 64;   // subdivisions of a triangle's longest edge, at most
constexpr double kPerThickness = 3;  // samples per thickness along a triangle: the field between them within 10% (grading 0.3)
constexpr double kInset = 0.05;     // probes near the corners: this far (barycentric) towards the centre

struct Triangle {
  Vec3 a, b, c;
  Vec3 outward;  // unit normal out of the material (zero: an interface triangle, either way)
  Index face;
  bool folded;   // its corners turn against its surface's normal: no rays start from it
  const ParametricSurface* curved = nullptr;  // its face's surface, when the face is not planar
  std::array<Vec2, 3> uv{};                   // its corners' (u, v) there
};

// Where a ray meets a triangle: its parameter along the ray and the triangle's barycentric
// coordinates of b and c there.
struct Hit {
  double t = std::numeric_limits<double>::infinity();
  int tri = -1;
  double u = 0, v = 0;
};

// The triangle's point a + u (b - a) + v (c - a) taken onto its own surface: where the line
// through it along the unit direction d meets the surface, by Newton steps along the line (each
// to the tangent plane at the surface's point nearest the last), from the (u, v) interpolated
// there; the point itself on a planar face's triangle. Along the line, not to the nearest
// point: a facet of a coarse tessellation can lie where another face's material is (a chord
// across a slot cut near a cylinder's wall), and its nearest surface point is then no point of
// the wall.
Vec3 on_surface(const Triangle& t, double u, double v, const Vec3& d) {
  const Vec3 p = t.a + u * (t.b - t.a) + v * (t.c - t.a);
  if (!t.curved) return p;
  const ParametricSurface& s = *t.curved;
  Vec2 uv = t.uv[0] + u * (t.uv[1] - t.uv[0]) + v * (t.uv[2] - t.uv[0]);
  Vec3 x = p;
  for (int step = 0; step < 8; ++step) {
    uv = s.closest_point(x, uv);
    const Vec3 q = s.point(uv), n = s.normal(uv);
    if (!q.allFinite() || !n.allFinite()) return p;
    const double along = d.dot(n);
    // a line nearly in the tangent plane: the nearest point (the best there is); a ray at 6
    // degrees to the surface converges in a few steps (one along a slot's side wall, whose
    // material ends at the cylinder 0.55 on: 0.0002 on the 60 degree facets)
    if (std::abs(along) < 0.05) return q;
    const Vec3 next = x + ((q - x).dot(n) / along) * d;
    if ((next - x).norm() <= 1e-12 * (1 + x.norm())) return next;
    x = next;
  }
  return x;
}

// The unit normal of a face's surface at a tessellation triangle's centre in (u, v), along
// du x dv; zero where the tessellation has no (u, v) or the surface has no normal there.
Vec3 surface_normal_at(const BrepFace& face, const BrepTessellation::Face& tf, std::size_t t) {
  if (!face.surface || t >= tf.uv.size()) return Vec3::Zero();
  const Vec3 n = face.surface->normal((tf.uv[t][0] + tf.uv[t][1] + tf.uv[t][2]) / 3);
  return n.allFinite() ? n : Vec3::Zero();
}

// A bounding-volume tree over triangles, for the nearest hit along a ray.
class RayTree {
 public:
  explicit RayTree(std::vector<Triangle> tris) : tris_(std::move(tris)) {
    order_.resize(tris_.size());
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
    if (!tris_.empty()) build(0, static_cast<int>(tris_.size()));
  }

  const Triangle& triangle(int k) const { return tris_[k]; }

  // The first triangle the ray from o along the unit direction d crosses farther than `skip`, at
  // most `limit`, on a face `near` does not hold; t infinite when none.
  Hit first_hit(const Vec3& o, const Vec3& d, double skip, double limit, const std::vector<char>& near) const {
    Hit out;
    double best = limit;
    if (nodes_.empty()) return out;
    const Vec3 inv(1 / d.x(), 1 / d.y(), 1 / d.z());
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    bool found = false;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (!box_hit(n, o, inv, best)) continue;
      if (n.left < 0) {
        for (int k = n.first; k < n.first + n.count; ++k) {
          if (near[tris_[order_[k]].face]) continue;
          double u = 0, v = 0;
          const double t = hit(tris_[order_[k]], o, d, &u, &v);
          if (t > skip && t < best) best = t, found = true, out.tri = order_[k], out.u = u, out.v = v;
        }
        continue;
      }
      if (top + 2 <= 128) stack[top++] = n.left, stack[top++] = n.right;
    }
    if (found) out.t = best;
    return out;
  }

 private:
  struct Node {
    Vec3 lo, hi;
    int first = 0, count = 0, left = -1, right = -1;
  };

  int build(int first, int count) {
    Node n;
    n.lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    n.hi = -n.lo;
    for (int k = first; k < first + count; ++k) {
      const Triangle& t = tris_[order_[k]];
      for (const Vec3* p : {&t.a, &t.b, &t.c}) n.lo = n.lo.cwiseMin(*p), n.hi = n.hi.cwiseMax(*p);
    }
    n.first = first, n.count = count;
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back(n);
    if (count <= kLeaf) return id;
    int axis = 0;
    (n.hi - n.lo).maxCoeff(&axis);
    auto centre = [&](int i) { return tris_[i].a[axis] + tris_[i].b[axis] + tris_[i].c[axis]; };
    const int mid = first + count / 2;
    std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + first + count,
                     [&](int x, int y) { return centre(x) < centre(y); });
    const int left = build(first, mid - first);
    const int right = build(mid, first + count - mid);
    nodes_[id].left = left, nodes_[id].right = right;
    return id;
  }

  static bool box_hit(const Node& n, const Vec3& o, const Vec3& inv, double limit) {
    double t0 = 0, t1 = limit;
    for (int a = 0; a < 3; ++a) {
      double lo = (n.lo[a] - o[a]) * inv[a], hi = (n.hi[a] - o[a]) * inv[a];
      if (std::isnan(lo) || std::isnan(hi)) {  // the ray runs in the slab's plane
        if (o[a] < n.lo[a] || o[a] > n.hi[a]) return false;
        continue;
      }
      if (lo > hi) std::swap(lo, hi);
      t0 = std::max(t0, lo), t1 = std::min(t1, hi);
      if (t0 > t1) return false;
    }
    return true;
  }

  // The ray's parameter where it crosses the triangle (Moller-Trumbore), -1 when it does not.
  // A triangle whose outward normal faces the ray (the ray would enter the material there) is
  // no exit and is passed.
  static double hit(const Triangle& t, const Vec3& o, const Vec3& d, double* bu, double* bv) {
    if (t.outward.dot(d) < -1e-9) return -1;
    const Vec3 e1 = t.b - t.a, e2 = t.c - t.a, q = d.cross(e2);
    const double det = e1.dot(q);
    if (std::abs(det) < 1e-300) return -1;
    const double inv = 1 / det;
    const Vec3 s = o - t.a;
    const double u = s.dot(q) * inv;
    if (u < 0 || u > 1) return -1;
    const Vec3 r = s.cross(e1);
    const double v = d.dot(r) * inv;
    if (v < 0 || u + v > 1) return -1;
    *bu = u, *bv = v;
    return e2.dot(r) * inv;
  }

  std::vector<Triangle> tris_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace

std::vector<WallSample> wall_thickness(const BrepInput& in, const BrepTessellation& tess, double limit) {
  std::vector<WallSample> out;
  if (!(limit > 0)) return out;
  // per face: how many solids list it (2: an interface, material on both sides)
  std::vector<int> users(in.faces.size(), 0);
  for (const BrepSolid& s : in.solids)
    for (Index f : s.faces)
      if (f >= 0 && static_cast<std::size_t>(f) < users.size()) ++users[f];
  std::vector<Triangle> tris;
  std::vector<std::size_t> first(in.faces.size() + 1, 0);  // per face: its triangles in `tris`
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    first[f] = tris.size();
    if (f >= tess.faces.size() || users[f] == 0) continue;
    const BrepTessellation::Face& tf = tess.faces[f];
    for (std::size_t k = 0; k < tf.tris.size(); ++k) {
      const auto& t = tf.tris[k];
      Triangle tri{tess.nodes[t[0]], tess.nodes[t[1]], tess.nodes[t[2]], Vec3::Zero(), static_cast<Index>(f), false};
      if (!in.faces[f].planar && in.faces[f].surface && k < tf.uv.size()) tri.curved = in.faces[f].surface.get(), tri.uv = tf.uv[k];
      Vec3 n = (tri.b - tri.a).cross(tri.c - tri.a);  // along du x dv: the corners turn counter-clockwise in (u, v)
      if (!(n.norm() > 0)) continue;
      n.normalize();
      // A sliver of the tessellation along a curved edge can turn over in space (corpus
      // Zylkopf, toroid Face7: facets whose normal points into the material). A ray from it
      // would start outwards and meet its neighbours a few thousandths away, a wall that is not
      // there. Such a facet sends no ray, and faces out of the material by its surface's normal.
      const Vec3 ns = surface_normal_at(in.faces[f], tf, k);
      if (ns.dot(n) < 0) tri.folded = true, n = ns;
      if (users[f] == 1) tri.outward = (in.faces[f].reversed ? -1.0 : 1.0) * n;
      tris.push_back(tri);
    }
  }
  first[in.faces.size()] = tris.size();
  Vec3 lo = in.bbox_min, hi = in.bbox_max;
  const double skip = 1e-9 * std::max((hi - lo).norm(), 1e-300);
  const RayTree tree(tris);
  // per face: the B-rep vertices of its boundary. A ray is not stopped by a face that shares a
  // vertex with the face it starts from: near an edge where two faces meet at an acute angle
  // that distance goes to nought, and it is no wall (elements there are bound by the edge's
  // angle, and no size mends that)
  std::vector<std::vector<Index>> corners(in.faces.size()), faces_at(in.vertices.size());
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    for (const auto& wire : in.faces[f].wires)
      for (const BrepEdgeUse& use : wire) {
        if (use.edge < 0 || static_cast<std::size_t>(use.edge) >= in.edges.size()) continue;
        for (Index v : {in.edges[use.edge].v0, in.edges[use.edge].v1})
          if (v >= 0 && static_cast<std::size_t>(v) < in.vertices.size()) corners[f].push_back(v);
      }
    std::sort(corners[f].begin(), corners[f].end());
    corners[f].erase(std::unique(corners[f].begin(), corners[f].end()), corners[f].end());
    for (Index v : corners[f]) faces_at[v].push_back(static_cast<Index>(f));
  }
  std::vector<char> near(in.faces.size(), 0);
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    if (first[f] == first[f + 1]) continue;
    for (Index v : corners[f])
      for (Index g : faces_at[v]) near[g] = 1;
    near[f] = 0;
    for (std::size_t k = first[f]; k < first[f + 1]; ++k) {
      const Triangle& t = tris[k];
      if (t.folded) continue;
      const Vec3 n = (t.b - t.a).cross(t.c - t.a).normalized();
      // the inward directions: one for a face of one solid, both for an interface
      std::vector<Vec3> inward;
      if (t.outward.squaredNorm() > 0) inward.push_back(-t.outward);
      else inward = {n, -n};
      for (const Vec3& d : inward) {
        // Measured on the facets, then between the true surfaces where that is near the limit:
        // a facet stands off its curved face by up to the tessellation's deflection, which can
        // be most of a thin wall (a slot cut 0.05 from a cylinder's wall of radius 10, on
        // facets 0.02 inside it: 0.0022 on the facets)
        auto thickness = [&](double ba, double bb) {
          const Vec3 p = t.a + ba * (t.b - t.a) + bb * (t.c - t.a);
          const Hit h = tree.first_hit(p, d, skip, std::numeric_limits<double>::infinity(), near);
          double w = h.t;
          if (w < 2 * limit && (t.curved || tree.triangle(h.tri).curved)) {
            const double along = (on_surface(tree.triangle(h.tri), h.u, h.v, d) - on_surface(t, ba, bb, d)).dot(d);
            if (along > skip) w = along;
          }
          return std::pair<Vec3, double>(p, w);
        };
        const double third = 1.0 / 3.0, across = 1 - 2 * kInset;
        double thinnest = std::numeric_limits<double>::infinity();
        for (const auto& [ba, bb] : {std::pair<double, double>{third, third}, {kInset, kInset}, {across, kInset}, {kInset, across}})
          thinnest = std::min(thinnest, thickness(ba, bb).second);
        if (!(thinnest < limit)) continue;
        const double longest = std::max({(t.b - t.a).norm(), (t.c - t.b).norm(), (t.a - t.c).norm()});
        const int m = static_cast<int>(std::clamp(std::ceil(kPerThickness * longest / thinnest), 1.0, static_cast<double>(kMaxSubdivide)));
        // the sub-triangles' centres (barycentric), inside the triangle and off its edges
        for (int i = 0; i < m; ++i)
          for (int j = 0; i + j < m; ++j)
            for (int up = 0; up < (i + j + 1 < m ? 2 : 1); ++up) {
              const double ba = (i + (up ? 2.0 : 1.0) / 3) / m, bb = (j + (up ? 2.0 : 1.0) / 3) / m;
              const auto [p, w] = thickness(ba, bb);
              if (w < limit) out.push_back({p, w});
            }
      }
    }
    for (Index v : corners[f])
      for (Index g : faces_at[v]) near[g] = 0;
  }
  return out;
}

}  // namespace bisect::size
