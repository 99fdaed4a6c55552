#include "optimize/surface_angles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "bisect/quality.hpp"
#include "optimize/node_stars.hpp"
#include "optimize/sliver_repair.hpp"

namespace bisect::optimize {

using tet::positive;

double smallest_boundary_angle(const tet::TetComplex& cx, const std::vector<Vec3>& X, Index node, const std::vector<Index>& around) {
  double worst = 180;
  for (Index t : around)
    for (int f = 0; f < 4; ++f) {
      if (cx.tet[t][f] == node || !cx.is_constrained(t, f)) continue;
      const std::array<Index, 3> v = cx.face(t, f);
      worst = std::min(worst, triangle_min_angle_deg(X[v[0]], X[v[1]], X[v[2]]));
    }
  return worst;
}

namespace {

// How node v may move for the surface: as slide_of says, or else along its B-rep edge.
Slide surface_slide_of(const FaceSlides& slides, const std::vector<char>& fixed, Index v) {
  const Slide slide = slide_of(slides, fixed, v);
  const auto i = static_cast<std::size_t>(v);
  if (slide == Slide::kNone && i < fixed.size() && fixed[i] && i < slides.edge.size() && slides.edge[i] && slides.along) return Slide::kEdge;
  return slide;
}

// The point p taken into node v's face (its plane through `old`, or the curved face itself), or
// onto its B-rep edge.
Vec3 into_face(const FaceSlides& slides, Slide slide, Index v, const Vec3& old, const Vec3& p) {
  if (slide == Slide::kCurved) return slides.onto(v, p, nullptr);
  if (slide == Slide::kEdge) return slides.along(v, p, nullptr);
  const Vec3& n = slides.plane[v];
  Vec3 q = p - n * n.dot(p - old);
  // a plane normal to an axis: that coordinate exactly as it was
  for (int k = 0; k < 3; ++k)
    if (n[k] == 1 || n[k] == -1) q[k] = old[k];
  return q;
}

// One node's move (see improve_surface_angles); true when made (X[v] then holds it).
bool move_for_the_surface(tet::TetComplex& cx, std::vector<Vec3>& X, const FaceSlides& slides, Slide slide, Index v,
                          const std::vector<Index>& around) {
  // the neighbours on its boundary triangles (an interface's triangle is seen from both sides)
  std::set<Index> ring;
  for (Index t : around)
    for (int f = 0; f < 4; ++f) {
      if (cx.tet[t][f] == v || !cx.is_constrained(t, f)) continue;
      for (Index w : cx.face(t, f))
        if (w != v) ring.insert(w);
    }
  if (ring.size() < 3) return false;
  const Vec3 old = X[v];
  Vec3 middle = Vec3::Zero();
  double scale = 0;
  for (Index w : ring) middle += X[w], scale += (X[w] - old).norm();
  middle /= static_cast<double>(ring.size());
  scale /= static_cast<double>(ring.size());
  const double before = smallest_boundary_angle(cx, X, v, around);
  // each tetrahedron's bar, as a cosine: its own smallest dihedral angle before, or, when that
  // is larger, the star's smallest or kSurfaceDihedralBarDeg, whichever is larger (a move may
  // trade a good tetrahedron's angle down to the bar, never a poor one's further down)
  std::vector<double> bar_cos(around.size());
  double star_cos = -1;
  for (std::size_t i = 0; i < around.size(); ++i) {
    const Tet& u = cx.tet[around[i]];
    bar_cos[i] = worst_dihedral_cos(X[u[0]], X[u[1]], X[u[2]], X[u[3]]);
    star_cos = std::max(star_cos, bar_cos[i]);
  }
  const double floor_cos = std::min(star_cos, std::cos(kSurfaceDihedralBarDeg * M_PI / 180));
  for (double& c : bar_cos) c = std::max(c, floor_cos);
  // the smallest angle at p, or -1 where a tetrahedron would fold or fall under its bar
  const auto angle_at = [&](const Vec3& p) {
    X[v] = p;
    double a = p.allFinite() ? smallest_boundary_angle(cx, X, v, around) : -1;
    for (std::size_t i = 0; i < around.size() && a >= 0; ++i) {
      const Tet& u = cx.tet[around[i]];
      if (!positive(X, u) || worst_dihedral_cos(X[u[0]], X[u[1]], X[u[2]], X[u[3]]) > bar_cos[i]) a = -1;
    }
    X[v] = old;
    return a;
  };
  // the candidates: towards the neighbours' middle, and up the smallest angle's gradient in the
  // face's tangent plane (forward differences), each at shrinking steps; on an edge, along its
  // tangent either way
  std::vector<Vec3> towards{middle - old};
  if (slide == Slide::kEdge) {
    Vec3 tangent;
    slides.along(v, old, &tangent);
    towards.clear();
    if (tangent.allFinite()) towards = {0.5 * scale * tangent, -0.5 * scale * tangent};
  } else {
    Vec3 normal;
    if (slide == Slide::kPlane) normal = slides.plane[v];
    else slides.onto(v, old, &normal);
    const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
    const double h = 1e-3 * scale;
    const auto f = [&](const Vec3& e) {
      X[v] = into_face(slides, slide, v, old, old + h * e);
      const double a = smallest_boundary_angle(cx, X, v, around);
      X[v] = old;
      return (a - before) / h;
    };
    const Vec3 g = f(e1) * e1 + f(e2) * e2;
    if (g.norm() > 0 && g.allFinite()) towards.push_back(0.5 * scale * g.normalized());
  }
  double best = before + 0.01;
  Vec3 chosen = old;
  for (const Vec3& d : towards)
    for (double s = 1; s > 0.1; s *= 0.5) {
      const Vec3 p = into_face(slides, slide, v, old, old + s * d);
      const double a = angle_at(p);
      if (a > best) best = a, chosen = p;
    }
  if (chosen == old) return false;
  X[v] = chosen;
  return true;
}

}  // namespace

std::int64_t improve_surface_angles(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, const FaceSlides& slides,
                                    int rounds) {
  std::int64_t moves = 0;
  for (int round = 0; round < rounds; ++round) {
    // a live tetrahedron at each node that may slide and has a boundary triangle under the bar
    std::vector<Index> at(X.size(), -1);
    for (std::size_t t = 0; t < cx.tet.size(); ++t) {
      cx.poll(t);
      if (!cx.alive[t]) continue;
      for (int f = 0; f < 4; ++f) {
        if (!cx.is_constrained(static_cast<Index>(t), f)) continue;
        const std::array<Index, 3> tri = cx.face(static_cast<Index>(t), f);
        if (triangle_min_angle_deg(X[tri[0]], X[tri[1]], X[tri[2]]) >= kSurfaceWorkBelowDeg) continue;
        for (Index w : tri)
          if (surface_slide_of(slides, fixed, w) != Slide::kNone) at[w] = static_cast<Index>(t);
      }
    }
    std::int64_t made = 0;
    for (std::size_t v = 0; v < at.size(); ++v) {
      if (at[v] < 0) continue;
      cx.poll(v);
      // the tetrahedron recorded at v is still live and at v: moves change positions only
      const std::vector<Index> around = star(cx, static_cast<Index>(v), at[v]);
      if (!move_for_the_surface(cx, X, slides, surface_slide_of(slides, fixed, static_cast<Index>(v)), static_cast<Index>(v), around)) continue;
      cx.moved(around);
      ++made;
    }
    moves += made;
    if (made == 0) break;
  }
  return moves;
}

}  // namespace bisect::optimize
