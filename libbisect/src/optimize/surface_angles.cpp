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

// The move of v to p that some tetrahedron round v would pay for under its bar, with the
// transformations of 7.5 round v after it: a flip may win back what the move cost (sphere-in-box
// at its floor: a node 0.17 from the seam, where the grid's spacing is 0.5, kept a 17.3-degree
// triangle because the star's poorest tetrahedron, 11.5 degrees, would have fallen to 10.4).
// Kept when every tetrahedron of the star that is still there meets its bar (bar_cos: the
// trade's) and every one the flips made is no poorer than the star's poorest was or the trade's
// floor (new_cos); else undone.
bool move_with_flips(tet::TetComplex& cx, std::vector<Vec3>& X, Index v, const Vec3& old, const Vec3& p, const std::vector<Index>& around,
                     const std::vector<double>& bar_cos, double new_cos) {
  std::vector<Tet> was(around.size());
  for (std::size_t i = 0; i < around.size(); ++i) was[i] = cx.tet[around[i]];
  std::vector<tet::TetComplex::Replacement> journal;
  std::vector<Index> touched;
  // the complex's own logs back on every way out (Stop included); no 2-2 transformation on the
  // boundary meanwhile (its map of input faces is not in the journal)
  struct Logs {
    tet::TetComplex& cx;
    std::vector<tet::TetComplex::Replacement>* journal;
    std::vector<Index>* touched;
    bool boundary_flips;
    ~Logs() { cx.journal = journal, cx.touched = touched, cx.boundary_flips = boundary_flips; }
  } logs{cx, cx.journal, cx.touched, cx.boundary_flips};
  cx.journal = &journal, cx.touched = &touched, cx.boundary_flips = false;
  X[v] = p;
  cx.moved(around);
  cx.improve_around(around);
  cx.journal = logs.journal, cx.touched = logs.touched, cx.boundary_flips = logs.boundary_flips;
  const auto worst_cos = [&](Index t) {
    const Tet& u = cx.tet[t];
    return positive(X, u) ? worst_dihedral_cos(X[u[0]], X[u[1]], X[u[2]], X[u[3]]) : 2.0;
  };
  bool ok = true;
  for (std::size_t i = 0; i < around.size() && ok; ++i)
    if (cx.alive[around[i]] && cx.tet[around[i]] == was[i]) ok = worst_cos(around[i]) <= bar_cos[i];
  for (std::size_t k = 0; k < touched.size() && ok; ++k) {
    const Index t = touched[k];
    if (!cx.alive[t]) continue;
    const auto same = std::find(around.begin(), around.end(), t);
    if (same != around.end() && cx.tet[t] == was[static_cast<std::size_t>(same - around.begin())]) continue;  // checked above
    ok = worst_cos(t) <= new_cos;
  }
  if (ok) return true;
  X[v] = old;
  cx.undo(journal, &touched);
  return false;
}

// One node's move (see improve_surface_angles); true when made (X[v] then holds it, and the
// complex the keys of its star, or the flips that went with it).
bool move_for_the_surface(tet::TetComplex& cx, std::vector<Vec3>& X, const FaceSlides& slides, Slide slide, Index v,
                          const std::vector<Index>& around, bool trades) {
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
  // each tetrahedron's bars, as cosines: its own smallest dihedral angle before, or, when that is
  // larger, a floor (a move may trade a good tetrahedron's angle down to the floor, never a poor
  // one's further down). The strict floor: kSurfaceDihedralBarDeg or the star's smallest,
  // whichever is larger; for a triangle under kSurfaceAimDeg, the trade's floor too
  // (surface_trade_floor_deg), taken only where the strict one does not reach the aim
  std::vector<double> strict_cos(around.size()), trade_cos(around.size());
  double star_cos = -1;
  for (std::size_t i = 0; i < around.size(); ++i) {
    const Tet& u = cx.tet[around[i]];
    strict_cos[i] = worst_dihedral_cos(X[u[0]], X[u[1]], X[u[2]], X[u[3]]);
    star_cos = std::max(star_cos, strict_cos[i]);
  }
  const double strict_floor = std::min(star_cos, std::cos(kSurfaceDihedralBarDeg * M_PI / 180));
  const double trade_floor = trades && before < kSurfaceAimDeg ? std::cos(surface_trade_floor_deg(before) * M_PI / 180) : strict_floor;
  for (std::size_t i = 0; i < around.size(); ++i) {
    trade_cos[i] = std::max(strict_cos[i], trade_floor);
    strict_cos[i] = std::max(strict_cos[i], strict_floor);
  }
  // the smallest angle at p, or -1 where a tetrahedron would fold; *level: 0 every tetrahedron
  // at its strict bar, 1 at its trade's, 2 one under that
  const auto angle_at = [&](const Vec3& p, int* level) {
    *level = 0;
    X[v] = p;
    double a = p.allFinite() ? smallest_boundary_angle(cx, X, v, around) : -1;
    for (std::size_t i = 0; i < around.size() && a >= 0; ++i) {
      const Tet& u = cx.tet[around[i]];
      if (!positive(X, u)) {
        a = -1;
        continue;
      }
      const double c = worst_dihedral_cos(X[u[0]], X[u[1]], X[u[2]], X[u[3]]);
      if (c > trade_cos[i]) *level = 2;
      else if (c > strict_cos[i]) *level = std::max(*level, 1);
    }
    X[v] = old;
    return a;
  };
  // the candidates: towards the neighbours' middle, and up the smallest angle's gradient in the
  // face's tangent plane (forward differences), each at shrinking steps; on an edge, along its
  // tangent either way
  std::vector<Vec3> towards;
  if (slide == Slide::kEdge) {
    Vec3 tangent;
    slides.along(v, old, &tangent);
    if (tangent.allFinite()) towards = {0.5 * scale * tangent, -0.5 * scale * tangent};
  } else {
    towards.push_back(middle - old);
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
  // the best candidate at each level (a level's best counts for the levels above it)
  std::array<double, 3> best;
  best.fill(before + 0.01);
  std::array<Vec3, 3> chosen{old, old, old};
  for (const Vec3& d : towards)
    for (double s = 1; s > 0.1; s *= 0.5) {
      const Vec3 p = into_face(slides, slide, v, old, old + s * d);
      int level = 0;
      const double a = angle_at(p, &level);
      for (int k = level; k < 3; ++k)
        if (a > best[k]) best[k] = a, chosen[k] = p;
    }
  // the strict bars' best where it reaches the aim or the trade's is not a degree better; else
  // the trade's (corpus/Cone_1 at 2*10^4, whose apex keeps an 11-degree triangle: trades for
  // tenths of a degree there took its smallest dihedral angle from 15.0 to 13.5 degrees); where
  // neither is taken, the best candidate of all with flips round it, kept only when what they
  // leave meets the trade's bars (a flip there can win back what a trade would have cost:
  // letting only candidates the trade's bars stop try it, Angled.step's surface at 10^3 stayed
  // at 9.6 degrees against 12.0, x_as1_tu_203's at 2*10^4 at 14.8 against 16.6)
  const bool trade = chosen[1] != old && best[0] < kSurfaceAimDeg && best[1] >= best[0] + kSurfaceTradeGainDeg;
  const bool strict = !trade && chosen[0] != old;
  if (!strict && !trade) return trades && chosen[2] != old && move_with_flips(cx, X, v, old, chosen[2], around, trade_cos, std::max(star_cos, trade_floor));
  X[v] = strict ? chosen[0] : chosen[1];
  cx.moved(around);
  return true;
}

}  // namespace

std::int64_t improve_surface_angles(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, const FaceSlides& slides,
                                    int rounds, bool trades) {
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
      // the tetrahedron recorded at v may have gone in a move's flips: v waits for the next round
      if (!cx.alive[at[v]] || cx.corner_of(at[v], static_cast<Index>(v)) < 0) continue;
      const std::vector<Index> around = star(cx, static_cast<Index>(v), at[v]);
      if (!move_for_the_surface(cx, X, slides, surface_slide_of(slides, fixed, static_cast<Index>(v)), static_cast<Index>(v), around, trades)) continue;
      ++made;
    }
    moves += made;
    if (made == 0) break;
  }
  return moves;
}

}  // namespace bisect::optimize
