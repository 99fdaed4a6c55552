#include "optimize/mean_shape.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "bisect/quality.hpp"
#include "optimize/node_stars.hpp"
#include "optimize/optimize_mesh.hpp"
#include "optimize/sliver_repair.hpp"
#include "optimize/surface_angles.hpp"
#include "util/ordered_parallel.hpp"

namespace bisect::optimize {

using tet::positive;
using tet::tet_angle_key;

namespace {

// α̂ of the tetrahedron (a, b, c, d) (alpha_from_edges, as tet_quality grades it).
double alpha(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, w = c - a, z = d - a;
  const double area = 0.5 * (u.cross(w).norm() + w.cross(z).norm() + z.cross(u).norm() + (w - u).cross(z - u).norm());
  return alpha_from_edges(u, w, z, area);
}

double alpha(const std::vector<Vec3>& X, const Tet& t) { return alpha(X[t[0]], X[t[1]], X[t[2]], X[t[3]]); }

// A star with node v at p: the sum of its α̂, and the node moves' objective, minus the sum of
// 1 / α̂, which weighs a poor tetrahedron far more than a good one (the sum of α̂ itself traded
// poor ones for good ones); -infinity when a tetrahedron is flat.
struct StarScore {
  double alpha_sum = 0;
  double objective = 0;
};

StarScore star_score(const std::vector<Vec3>& X, const std::vector<Tet>& tets, const std::vector<Index>& around, Index v, const Vec3& p) {
  StarScore s;
  for (Index t : around) {
    const Tet& u = tets[t];
    const auto at = [&](int i) -> const Vec3& { return u[i] == v ? p : X[u[i]]; };
    const double a = alpha(at(0), at(1), at(2), at(3));
    if (!(a > 1e-12)) return {s.alpha_sum, -std::numeric_limits<double>::infinity()};
    s.alpha_sum += a;
    s.objective -= 1 / a;
  }
  return s;
}

// The tetrahedra the passes work from: α̂ under this, and what touches them. Lower is cheaper:
// at 10^5 (lug, flange) two rounds from those under 0.22 cost 26% of the run's time and raised
// the mean α̂ by 0.005; under 0.18, 6% and 0.002; under 0.15, 2% and 0.001. At coarse counts
// 0.18 kept the smallest angles' gains of 0.22 (cantilever.stl at R = 1000: 12.1 to 16.2 degrees).
constexpr double kWorkBelow = 0.18;

// No change makes a dihedral angle under kSliverBelowDeg (with half a degree to spare) where
// there was none, and a tetrahedron that had one may not get worse: the min-max key alone let
// the other tetrahedra of a star fall to its smallest, and the passes, which come after the
// sliver repair, made new slivers (part.step at 10^5: 76 tetrahedra under 10 degrees where the
// repair had left 49; Angled.step 23 for 8).
const double kGuardCos = std::cos((kSliverBelowDeg + 0.5) * 3.14159265358979323846 / 180);

double dihedral_cos(const std::vector<Vec3>& X, const Tet& t) { return worst_dihedral_cos(X[t[0]], X[t[1]], X[t[2]], X[t[3]]); }

// The mesh's α̂, summed, and its count: the running mean the transformations must beat.
struct Running {
  double sum = 0;
  double count = 0;
  double mean() const { return count > 0 ? sum / count : 0; }
};

// 2-3 across face f of t when it raises the mean and keeps the smallest key.
bool flip23(tet::TetComplex& cx, Index t, int f, Running& run) {
  thread_local std::vector<Tet> fresh;  // kept from call to call: tried at every face of every poor tetrahedron
  if (!cx.flip23_unchecked(t, f, &fresh)) return false;  // positive_all last: the dearest test
  const Index n = cx.neighbour(t, f);
  const std::vector<Vec3>& X = cx.X;
  double sum = 0;
  const double need = std::min(cx.q[t], cx.q[n]);
  for (const Tet& m : fresh) {
    if (tet_angle_key(X, m) < need) return false;
    sum += alpha(X, m);
  }
  const double gain = sum - alpha(X, cx.tet[t]) - alpha(X, cx.tet[n]);
  if (!(gain > run.mean() + 1e-9)) return false;
  const double allowed = std::max({dihedral_cos(X, cx.tet[t]), dihedral_cos(X, cx.tet[n]), kGuardCos});
  for (const Tet& m : fresh)
    if (dihedral_cos(X, m) > allowed) return false;
  if (!cx.positive_all(fresh)) return false;
  cx.replace({t, n}, fresh);
  run.sum += gain, run.count += 1;
  return true;
}

// 3-2 on the edge (a, b) of t when it is interior and in three tetrahedra.
bool flip32(tet::TetComplex& cx, Index t, Index a, Index b, Running& run) {
  std::array<Index, 4> ring, apex;
  bool closed = false, held = false;
  if (cx.edge_ring(t, a, b, 3, ring.data(), apex.data(), &closed, &held) != 3 || !closed) return false;
  const std::vector<Vec3>& X = cx.X;
  // the triangle of the three apexes, with a on one side and b on the other
  Tet ta{apex[0], apex[1], apex[2], a}, tb{apex[1], apex[0], apex[2], b};
  if (!positive(X, ta)) std::swap(ta[0], ta[1]), std::swap(tb[0], tb[1]);
  if (!positive(X, ta) || !positive(X, tb)) return false;
  double need = std::numeric_limits<double>::max(), before = 0;
  for (int i = 0; i < 3; ++i) need = std::min(need, cx.q[ring[i]]), before += alpha(X, cx.tet[ring[i]]);
  if (tet_angle_key(X, ta) < need || tet_angle_key(X, tb) < need) return false;
  const double gain = alpha(X, ta) + alpha(X, tb) - before;
  if (!(gain > -run.mean() + 1e-9)) return false;
  double allowed = kGuardCos;
  for (int i = 0; i < 3; ++i) allowed = std::max(allowed, dihedral_cos(X, cx.tet[ring[i]]));
  if (dihedral_cos(X, ta) > allowed || dihedral_cos(X, tb) > allowed) return false;
  cx.replace({ring[0], ring[1], ring[2]}, {ta, tb});
  run.sum += gain, run.count -= 1;
  return true;
}

// A free node's move up the gradient of its star's objective (forward differences): the first
// of steps from a fifth of the star's size down that gains and keeps the star's smallest key and
// the dihedral guard. Reads the positions of the star's nodes and writes only X[v], which it
// leaves as it found it: nodes that share no tetrahedron are tried at once on several threads.
struct Move {
  bool made = false;
  Vec3 to = Vec3::Zero();
  double gain = 0;  // in the star's summed α̂
};

// Where a node that slides in its face may not take its boundary triangles' smallest angle.
constexpr double kSlideAngleFloorDeg = 30;

Move try_move(const tet::TetComplex& cx, std::vector<Vec3>& X, Index node, const std::vector<Index>& around, Slide slide,
              const FaceSlides& slides) {
  Move m;
  double key = std::numeric_limits<double>::max(), scale = 0;
  int count = 0;
  for (Index t : around) {
    key = std::min(key, cx.q[t]);
    for (Index w : cx.tet[t])
      if (w != node) scale += (X[w] - X[node]).norm(), ++count;
  }
  scale /= std::max(count, 1);
  if (!(scale > 0)) return m;
  const Vec3 old = X[node];
  const StarScore before = star_score(X, cx.tet, around, node, old);
  if (!std::isfinite(before.objective)) return m;
  std::vector<double> was_cos(around.size());
  double star_cos = -1;  // the star's smallest dihedral angle, as a cosine
  for (std::size_t i = 0; i < around.size(); ++i) was_cos[i] = dihedral_cos(X, cx.tet[around[i]]), star_cos = std::max(star_cos, was_cos[i]);
  const double h = 1e-4 * scale;
  Vec3 g;
  for (int k = 0; k < 3; ++k) {
    Vec3 e = Vec3::Zero();
    e[k] = h;
    g[k] = (star_score(X, cx.tet, around, node, old + e).objective - before.objective) / h;
  }
  // in the face's plane (exactly zero along an axis the plane is normal to), or its tangent plane
  double angle_floor = 0;
  if (slide != Slide::kNone) {
    Vec3 normal = slide == Slide::kPlane ? slides.plane[node] : Vec3::Zero();
    if (slide == Slide::kCurved) slides.onto(node, old, &normal);
    g -= normal * normal.dot(g);
    angle_floor = std::min(smallest_boundary_angle(cx, X, node, around), kSlideAngleFloorDeg);
  }
  const double glen = g.norm();
  if (!(glen > 0) || !std::isfinite(glen)) return m;
  for (double s = 0.2 * scale; s > 1e-3 * scale; s *= 0.5) {
    Vec3 p = old + (s / glen) * g;
    if (slide == Slide::kCurved) p = slides.onto(node, p, nullptr);  // back onto the face
    const StarScore after = star_score(X, cx.tet, around, node, p);
    if (!(after.objective > before.objective + 1e-9 * std::abs(before.objective))) continue;
    X[node] = p;
    bool ok = true;
    for (std::size_t i = 0; i < around.size() && ok; ++i) {
      const Tet& u = cx.tet[around[i]];
      // a node in a face: no smaller dihedral angle in its star than there was
      ok = positive(X, u) && tet_angle_key(X, u) >= key &&
           dihedral_cos(X, u) <= (slide != Slide::kNone ? star_cos : std::max(was_cos[i], kGuardCos));
    }
    if (ok && slide != Slide::kNone) ok = smallest_boundary_angle(cx, X, node, around) >= angle_floor;
    X[node] = old;
    if (!ok) continue;
    m.made = true, m.to = p, m.gain = after.alpha_sum - before.alpha_sum;
    break;
  }
  return m;
}

// One pass of node moves over the free nodes of the poor tetrahedra. The nodes are coloured
// greedily in id order so that no two of a colour share a tetrahedron; colour by colour, each
// node's move is tried on any thread (its star's tetrahedra and nodes are no other's of the
// colour) and made in id order on this one. The moves depend on the colouring alone, so the
// mesh is the same for every thread count (a serial sweep would let each node see every earlier
// one's move; here it sees those of the earlier colours).
std::int64_t move_nodes(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, const FaceSlides& slides,
                        const std::vector<char>& poor, Running& run, int threads) {
  std::vector<Index> at(X.size(), -1);  // a live poor tetrahedron at each node that may move
  for (std::size_t t = 0; t < poor.size(); ++t)
    if (cx.alive[t] && poor[t])
      for (Index v : cx.tet[t])
        // a node the sliver repair inserted has an id past `fixed`, and is free
        if (static_cast<std::size_t>(v) >= fixed.size() || !fixed[v] || slide_of(slides, fixed, v) != Slide::kNone) at[v] = static_cast<Index>(t);
  std::vector<Index> nodes;
  for (std::size_t v = 0; v < X.size(); ++v)
    if (at[v] >= 0) nodes.push_back(static_cast<Index>(v));
  const std::size_t n = nodes.size();
  const int workers = util::thread_count(threads);
  // the stars on this thread: the complex's walk marks what it has seen in the complex itself
  std::vector<std::vector<Index>> stars(n);
  for (std::size_t i = 0; i < n; ++i) {
    cx.poll(i);
    stars[i] = star(cx, nodes[i], at[nodes[i]]);
  }
  // greedy colours: the least not taken by a node already coloured that shares a tetrahedron
  std::vector<int> colour(X.size(), -1);
  std::vector<std::vector<std::size_t>> by_colour;
  std::vector<char> taken;
  for (std::size_t i = 0; i < n; ++i) {
    taken.assign(by_colour.size() + 1, 0);
    for (Index t : stars[i])
      for (Index w : cx.tet[t])
        if (colour[w] >= 0) taken[colour[w]] = 1;
    const int c = static_cast<int>(std::find(taken.begin(), taken.end(), 0) - taken.begin());
    colour[nodes[i]] = c;
    if (c == static_cast<int>(by_colour.size())) by_colour.emplace_back();
    by_colour[c].push_back(i);
  }
  std::int64_t moves = 0;
  std::vector<Move> tried;
  for (const std::vector<std::size_t>& group : by_colour) {
    tried.assign(group.size(), Move{});
    util::ordered_parallel(
        group.size(), workers, [&](std::size_t k) { tried[k] = try_move(cx, X, nodes[group[k]], stars[group[k]], slide_of(slides, fixed, nodes[group[k]]), slides); },
        [&](std::size_t k) {
          const std::size_t i = group[k];
          cx.poll(i);
          if (!tried[k].made) return;
          X[nodes[i]] = tried[k].to;
          cx.moved(stars[i]);
          run.sum += tried[k].gain;
          ++moves;
        });
  }
  return moves;
}

}  // namespace

Slide slide_of(const FaceSlides& slides, const std::vector<char>& fixed, Index v) {
  const auto i = static_cast<std::size_t>(v);
  if (i >= fixed.size() || !fixed[i]) return Slide::kNone;
  if (i < slides.plane.size() && slides.plane[i] != Vec3::Zero()) return Slide::kPlane;
  if (i < slides.curved.size() && slides.curved[i] && slides.onto) return Slide::kCurved;
  return Slide::kNone;
}

Vec3 slide_normal(const Vec3& n) {
  if (!(std::abs(n.norm() - 1) < 1e-6)) return Vec3::Zero();
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::abs(n[k]) - 1) < 1e-14) {
      Vec3 axis = Vec3::Zero();
      axis[k] = n[k] < 0 ? -1 : 1;
      return axis;
    }
  return n;
}

MeanCounts improve_mean(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, int rounds, int threads,
                        const FaceSlides& slides) {
  MeanCounts n;
  Running run;
  std::vector<char> poor(cx.tet.size(), 0);
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t]) {  // the first round's list from the same look at each tetrahedron
      const double a = alpha(X, cx.tet[t]);
      run.sum += a, run.count += 1;
      poor[t] = a < kWorkBelow;
    }
  for (int round = 0; round < rounds; ++round) {
    std::int64_t flips = 0;
    // the tetrahedra to work from, marked by id; one made in this round gets an id past the end
    // or a freed one, which then may be worked from too (the same tests hold for it)
    const std::size_t end = cx.tet.size();
    if (round > 0) {
      poor.assign(end, 0);
      for (std::size_t t = 0; t < end; ++t) poor[t] = cx.alive[t] && alpha(X, cx.tet[t]) < kWorkBelow;
    }
    for (std::size_t i = 0; i < end; ++i) {
      cx.poll(i);
      const Index t = static_cast<Index>(i);
      if (!poor[i]) continue;
      for (int f = 0; f < 4 && cx.alive[t]; ++f)
        if (flip23(cx, t, f, run)) ++flips;
      for (int e = 0; e < 6 && cx.alive[t]; ++e) {
        static constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
        const Index a = cx.tet[t][kEdge[e][0]], b = cx.tet[t][kEdge[e][1]];
        if (flip32(cx, t, a, b, run)) ++flips;
      }
    }
    const std::int64_t moves = move_nodes(cx, X, fixed, slides, poor, run, threads);
    n.flips += flips;
    n.moves += moves;
    if (flips == 0 && moves == 0) break;
  }
  return n;
}

}  // namespace bisect::optimize
