#include "optimize/sliver_repair.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "geom/predicates.hpp"
#include "optimize/node_stars.hpp"

namespace bisect::optimize {

using tet::positive;
using tet::tet_angle_key;
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kLargestStar = 200;  // tetrahedra round a node the repair still moves

double tet_worst(const std::vector<Vec3>& X, const Tet& u) { return worst_dihedral_cos(X[u[0]], X[u[1]], X[u[2]], X[u[3]]); }

double star_worst(const std::vector<Vec3>& X, const std::vector<Tet>& tets, const std::vector<Index>& around) {
  double worst = -1;
  for (Index t : around) {
    worst = std::max(worst, tet_worst(X, tets[t]));
    if (worst >= 2) break;
  }
  return worst;
}

// The mean edge length: the scale of a tetrahedron's repair steps.
double mean_edge(const std::vector<Vec3>& X, const Tet& u) {
  double edge = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) edge += (X[u[i]] - X[u[j]]).norm() / 6;
  return edge;
}

// Whether the tetrahedra `fresh` have the same outside faces as `region`'s (ids into tets) and
// meet each other in pairs across every other face.
bool same_outside(const std::vector<Tet>& tets, const std::vector<Index>& region, const std::vector<Tet>& fresh) {
  const auto faces = [](const Tet& m) {
    return std::array<tet::FaceKey, 4>{tet::face_key(m[1], m[2], m[3]), tet::face_key(m[0], m[2], m[3]),
                                       tet::face_key(m[0], m[1], m[3]), tet::face_key(m[0], m[1], m[2])};
  };
  std::unordered_map<tet::FaceKey, int, tet::FaceKeyHash> count;
  for (Index r : region)
    for (const tet::FaceKey& k : faces(tets[r])) ++count[k];
  for (auto it = count.begin(); it != count.end();) it = it->second == 2 ? count.erase(it) : std::next(it);
  for (auto& entry : count) entry.second = -entry.second;  // the outside: -1 each
  for (const Tet& m : fresh)
    for (const tet::FaceKey& k : faces(m)) ++count[k];
  for (const auto& entry : count)
    if (entry.second != 0 && entry.second != 2) return false;
  return true;
}

// A stuck tetrahedron with two free nodes close together (two interior nodes placed too near
// each other, opposite a short boundary edge: lug's worst at 10^5, 8.5 degrees, had a free edge
// of 0.044 beside edges of 0.15; plate-hole's, 4.0 degrees, 1.0 beside 2.5) loses one of them:
// the free edge collapses, one end kept where it is or moved to the edge's middle or to the mean
// of the merged star's other nodes (plate-hole's needed the mean), the other's tetrahedra given
// the kept one in its place and those with both gone. Every way is graded
// before anything changes; the best is made when its worst dihedral angle beats the worst of
// the two nodes' stars. Returns the tetrahedra made (none when no way is better).
std::vector<Index> collapse_free_edge(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, Index t) {
  const Tet u = cx.tet[t];
  double best = 2;
  Index best_keep = -1;
  Vec3 best_place;
  std::vector<Index> best_region;
  std::vector<Tet> best_fresh;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const Index v = u[i], w = u[j];
      if (fixed[v] || fixed[w]) continue;
      std::vector<Index> region = star(cx, v, t, kLargestStar);
      const std::vector<Index> other = star(cx, w, t, kLargestStar);
      if (region.size() > kLargestStar || other.size() > kLargestStar) continue;
      region.insert(region.end(), other.begin(), other.end());
      std::sort(region.begin(), region.end());
      region.erase(std::unique(region.begin(), region.end()), region.end());
      const double before = std::min(best, star_worst(X, cx.tet, region));
      for (const Index keep : {v, w}) {
        const Index gone = keep == v ? w : v;
        std::vector<Tet> fresh;
        for (Index r : region) {
          Tet m = cx.tet[r];
          if (std::find(m.begin(), m.end(), keep) != m.end() && std::find(m.begin(), m.end(), gone) != m.end()) continue;
          for (Index& x : m)
            if (x == gone) x = keep;
          fresh.push_back(m);
        }
        // the collapse must leave the region's outside as it is and close every face inside:
        // where the two nodes share a neighbour that is not on their edge's ring, it would not
        // (two tetrahedra on one face), and the replacement would be refused
        if (!same_outside(cx.tet, region, fresh)) continue;
        const Vec3 old = X[keep];
        // where it is, the edge's middle, and the mean of the merged star's other nodes
        Vec3 mean = Vec3::Zero();
        int count = 0;
        for (const Tet& m : fresh)
          for (Index x : m)
            if (x != keep) mean += X[x], ++count;
        if (count > 0) mean /= count;
        for (const Vec3& p : {old, Vec3(0.5 * (X[v] + X[w])), mean}) {
          X[keep] = p;
          double worst = -1;
          for (const Tet& m : fresh) worst = std::max(worst, worst_dihedral_cos(X[m[0]], X[m[1]], X[m[2]], X[m[3]]));
          if (worst < before - 1e-12 && worst < best) best = worst, best_keep = keep, best_place = p, best_region = region, best_fresh = fresh;
        }
        X[keep] = old;
      }
    }
  if (best_keep < 0) return {};
  X[best_keep] = best_place;
  return cx.replace(best_region, best_fresh);
}

}  // namespace

double worst_dihedral_cos(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (geom::orient3d(a, b, c, d) <= 0) return 2;
  const Vec3* p[4] = {&a, &b, &c, &d};
  Vec3 n[4];
  for (int i = 0; i < 4; ++i) {  // face i opposite corner i, its normal turned away from it
    const Vec3 &u = *p[(i + 1) % 4], &v = *p[(i + 2) % 4], &w = *p[(i + 3) % 4];
    n[i] = (v - u).cross(w - u);
    if (n[i].dot(*p[i] - u) > 0) n[i] = -n[i];
    const double len = n[i].norm();
    if (!(len > 0)) return 1;
    n[i] /= len;
  }
  double worst = -1;  // the dihedral angle at the edge of faces i and j has cosine -n_i . n_j
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) worst = std::max(worst, -n[i].dot(n[j]));
  return worst;
}

double sliver_key(double below_deg) {
  // a dihedral angle θ at the edge ab bounds the solid angles at a and b by 2θ (the corner's
  // spherical triangle lies in the lune of angle θ), so tan(Ω/2) <= tan θ; the margin covers
  // the rounding of the key
  return std::tan(below_deg * kPi / 180) * (1 + 1e-6);
}

std::size_t repair_slivers(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed_nodes, double below_deg, int rounds,
                           std::vector<Index> start) {
  const double limit = std::cos(below_deg * kPi / 180), key = sliver_key(below_deg);
  std::vector<char> fixed = fixed_nodes;  // grows with the nodes inserted (free)
  fixed.resize(X.size(), 0);              // and those an earlier repair inserted are free too
  // what each round changes (node moves, flips, insertions) is the next round's list, with the
  // tetrahedra no move improved; the caller's log, if any, gets it all too
  std::vector<Index>* const outer_log = cx.changed;
  std::vector<Index> changed;
  cx.changed = &changed;
  std::vector<Index> list = below_key(cx, std::move(start), key);
  std::size_t total = 0;
  for (int round = 0; round < rounds && !list.empty(); ++round) {
    changed.clear();
    std::size_t moved = 0;
    std::vector<Index> touched, stuck;  // stuck: no move of a node improves them
    std::size_t step = 0;
    for (Index t : list) {
      cx.poll(step++);
      const Tet u = cx.tet[t];  // no tetrahedron goes within the loop: t is live
      if (tet_worst(X, u) <= limit) continue;
      const double edge = mean_edge(X, u);
      Index best_v = -1;
      Vec3 best_p;
      std::vector<Index> best_around;
      double best = 2;
      for (int k = 0; k < 4; ++k) {
        const Index v = u[k];
        if (fixed[v]) continue;
        const std::vector<Index> around = star(cx, v, t, kLargestStar);
        // a node in hundreds of tetrahedra (a helper a thin cell kept) is no sliver's to move:
        // trying its 13 places costs the whole star each time, and one place cannot suit all
        if (around.size() > kLargestStar) continue;
        const double base = star_worst(X, cx.tet, around);
        const Vec3 &a = X[u[(k + 1) % 4]], &b = X[u[(k + 2) % 4]], &c = X[u[(k + 3) % 4]];
        Vec3 n = (b - a).cross(c - a);
        if (n.dot(X[v] - a) < 0) n = -n;
        if (n.norm() > 0) n.normalize();
        const Vec3 old = X[v];
        // off the opposite face's plane at four steps, the neighbours' mean, and eight fixed
        // directions (the corners of a cube) at a quarter of the edge
        std::vector<Vec3> candidates{old + 0.1 * edge * n, old + 0.2 * edge * n, old + 0.35 * edge * n, old + 0.5 * edge * n,
                                     neighbour_mean(X, cx.tet, around, v)};
        for (int c = 0; c < 8; ++c)
          candidates.push_back(old + 0.25 * edge / std::sqrt(3.0) * Vec3(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1));
        bool better = false;
        for (const Vec3& p : candidates) {
          X[v] = p;
          const double w = star_worst(X, cx.tet, around);
          if (w < base - 1e-12 && w < best) best = w, best_v = v, best_p = p, better = true;
        }
        X[v] = old;
        if (better) best_around = around;
      }
      if (best_v < 0) {
        stuck.push_back(t);
        continue;
      }
      X[best_v] = best_p;
      ++moved;
      cx.moved(best_around);  // their keys now, and on the log
      touched.insert(touched.end(), best_around.begin(), best_around.end());
    }
    // the transformations from the faces of the tetrahedra around moved nodes
    cx.improve_around(touched);
    // A stuck tetrahedron whose four nodes are fixed (four nodes on a curved boundary, the
    // typical case) gets a new free node off its largest face (the boundary face, when it has
    // one), inserted with a Delaunay cavity, which takes the flat tetrahedron when its
    // circumsphere holds the node; the next round moves that node where its tetrahedra are
    // best. Three distances are tried (inserted and undone), the one whose new tetrahedra are
    // best kept. A flat tetrahedron with no boundary face (two nodes on each of two boundary
    // faces that meet at an edge) may have room on one side of its largest face only: both
    // sides are tried, and the node goes in only if its tetrahedra beat the stuck one (lug.stl
    // at 10^6: half an edge off, always on one side, the node went towards the edge, onto one
    // face's plane, and a 6 degree sliver became a 0.6 degree one, every round again; on the
    // better side, a 2 degree one).
    std::size_t inserted = 0;
    std::vector<Tet> replaced;
    for (Index t : stuck) {
      cx.poll(step++);
      if (round + 1 >= rounds || !cx.alive[t]) continue;
      const Tet u = cx.tet[t];
      if (!fixed[u[0]] || !fixed[u[1]] || !fixed[u[2]] || !fixed[u[3]]) continue;
      const double stuck_worst = tet_worst(X, u);
      if (stuck_worst <= limit) continue;
      // the largest boundary face's area normal, else the largest face's (faces' normals point
      // out of t): a flat tetrahedron's largest face may be an inner one, whose normal would
      // send the node out of the mesh
      Vec3 outward = Vec3::Zero();
      bool on_boundary = false;
      for (int f = 0; f < 4; ++f) {
        const auto fv = cx.face(t, f);
        const Vec3 n = (X[fv[1]] - X[fv[0]]).cross(X[fv[2]] - X[fv[0]]);
        const bool b = cx.neighbour(t, f) < 0;
        if ((b && !on_boundary) || (b == on_boundary && n.squaredNorm() > outward.squaredNorm())) outward = n, on_boundary = b;
      }
      const Vec3 here = (X[u[0]] + X[u[1]] + X[u[2]] + X[u[3]]) / 4;
      const Vec3 step = 0.5 * mean_edge(X, u) * outward.normalized();
      // a node inserted at p: the tetrahedra it made, `replaced` what they replaced (from
      // `start`, a live tetrahedron near: t, or after an undone trial one of what came back)
      Index start = t;
      auto insert_at = [&](const Vec3& p) {
        X.push_back(p);
        fixed.push_back(0);
        std::vector<Index> made = cx.insert_delaunay(static_cast<Index>(X.size() - 1), start, &replaced, true);
        if (made.empty()) {  // on a face or node after all: left out
          X.pop_back();
          fixed.pop_back();
        }
        return made;
      };
      // the places tried: a quarter, half and three quarters of an edge off the face, on its
      // inner side only for a boundary face, on both sides otherwise; each inserted, judged by
      // the worst tetrahedron it made, and undone
      std::vector<Vec3> places;
      for (double s : {1.0, 0.5, 1.5}) {
        places.push_back(here - s * step);
        if (!on_boundary) places.push_back(here + s * step);
      }
      double best = 3;
      Vec3 best_place = here;
      for (const Vec3& p : places) {
        const std::vector<Index> tried = insert_at(p);
        if (tried.empty()) continue;
        double worst = -1;
        for (Index m : tried) worst = std::max(worst, tet_worst(X, cx.tet[m]));
        if (worst < best) best = worst, best_place = p;
        start = cx.replace(tried, replaced).front();
        X.pop_back();
        fixed.pop_back();
      }
      // the best place kept; off an inner face only when its tetrahedra beat the stuck one (no
      // new node at all is better than one that makes the sliver flatter)
      std::vector<Index> made;
      if (best < 3 && (on_boundary || best < stuck_worst)) made = insert_at(best_place);
      if (made.empty()) continue;
      ++inserted;
      cx.improve_around(made);
    }
    if (outer_log) outer_log->insert(outer_log->end(), changed.begin(), changed.end());
    if (moved + inserted == 0) break;
    total += moved + inserted;
    stuck.insert(stuck.end(), changed.begin(), changed.end());
    list = below_key(cx, std::move(stuck), key);
  }
  // What the rounds left with two free nodes: their edge collapsed (collapse_free_edge), after
  // the rounds and not within them, where a collapse changed what the later rounds' insertions
  // met (corpus/Cone_1 at 2e4: a 0.02 degree cap where the insertions had left 1.67).
  changed.clear();
  std::size_t step = 0;
  for (Index t : below_key(cx, std::move(list), key)) {
    cx.poll(step++);
    if (!cx.alive[t] || tet_worst(X, cx.tet[t]) <= limit) continue;
    // no transformations after it: they go by the smallest solid angle, and from a collapse on
    // Cone_1 they made a 0.28 degree needle where the collapse had raised the worst angle
    if (!collapse_free_edge(cx, X, fixed, t).empty()) ++total;
  }
  if (outer_log) outer_log->insert(outer_log->end(), changed.begin(), changed.end());
  cx.changed = outer_log;
  return total;
}

}  // namespace bisect::optimize
