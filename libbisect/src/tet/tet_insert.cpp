// Point location and node insertion in the tetrahedral complex: the visibility walk, the split of
// the tetrahedra holding a node (thesis 7.6), and the Delaunay cavity (Bowyer-Watson).
#include "tet/tet_complex.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <utility>

#include "bisect/errors.hpp"
#include "bisect/quality.hpp"
#include "bisect/tet_mesh.hpp"
#include "geom/predicates.hpp"

namespace bisect::tet {

using geom::orient3d;

Index TetComplex::locate(const Vec3& p, Index start, bool near_only) const {
  near_searched = 0;
  Index t = start;
  if (t < 0 || t >= static_cast<Index>(tet.size()) || !alive[t]) {
    t = -1;
    for (std::size_t k = 0; k < tet.size() && t < 0; ++k)
      if (alive[k]) t = static_cast<Index>(k);
    if (t < 0) return -1;
  }
  // visibility walk; the face to try first rotates, which keeps the walk from cycling
  const std::size_t limit = 64 + 4 * tet.size();
  unsigned rot = 0;
  for (std::size_t step = 0; step < limit; ++step) {
    bool moved = false;
    for (int k = 0; k < 4 && !moved; ++k) {
      const int f = static_cast<int>((k + rot) % 4);
      const auto fv = face(t, f);
      if (orient3d(X[fv[0]], X[fv[1]], X[fv[2]], p) > 0) {
        // across the boundary: outside the cell, or (a cell that is star-shaped but not convex)
        // round a dent in it: only a search of every tetrahedron tells
        if (neighbour(t, f) < 0) {
          step = limit;
          break;
        }
        t = neighbour(t, f);
        moved = true;
      }
    }
    if (step == limit) break;
    if (!moved) return t;
    rot = rot * 1103515245u + 12345u;
    rot >>= 3;
  }
  // The walk did not settle (it met the boundary round a dent of a cell that is not convex, as
  // Delaunay boundary recovery fills): the tetrahedra nearest p first, through their neighbours
  // from where the walk stopped, then any left unreached. Scanning every tetrahedron for every
  // such node took sphere-in-box at 2e5 from 36 s to 112 s once its cells were fewer and larger.
  auto holds = [&](Index k) {
    for (int f = 0; f < 4; ++f) {
      const auto fv = face(k, f);
      if (orient3d(X[fv[0]], X[fv[1]], X[fv[2]], p) > 0) return false;
    }
    return true;
  };
  auto distance = [&](Index k) {
    const Tet& q = tet[k];
    return (0.25 * (X[q[0]] + X[q[1]] + X[q[2]] + X[q[3]]) - p).squaredNorm();
  };
  const unsigned seen = new_stamp();  // reached
  std::priority_queue<std::pair<double, Index>, std::vector<std::pair<double, Index>>, std::greater<>> near;
  near.push({distance(t), t});
  mark_[t] = seen;
  std::size_t searched = 0;
  // near_only: a tetrahedron whose closure holds p has its centroid within its longest edge of
  // p. The search ends once the nearest tetrahedron left is further from p than `start`'s
  // centroid by twice the longest edge of start or of the walk's last tetrahedron: the tetrahedra
  // round start, of its size (a point placed outside the mesh beside start: the sliver repair's
  // trials on corpus/Zylkopf.brep went through all kNearSearch 4,545 times, a quarter of its
  // run; every holder found lay within 25 tetrahedra and a quarter of an edge of start).
  const auto longest_edge = [&](Index k) {
    const Tet& q = tet[k];
    double most = 0;
    for (const auto& e : kTetEdge) most = std::max(most, (X[q[e[1]]] - X[q[e[0]]]).squaredNorm());
    return std::sqrt(most);
  };
  const bool from_start = near_only && start >= 0 && start < static_cast<Index>(tet.size()) && alive[start];
  const double start_distance = from_start ? std::sqrt(distance(start)) : 0;
  const double reach = from_start ? std::max(longest_edge(start), longest_edge(t)) : 0;
  const double bound = (start_distance + 2 * reach) * (start_distance + 2 * reach);
  while (!near.empty()) {
    const auto [d2, k] = near.top();
    near.pop();
    if (from_start && d2 > bound) return -1;
    near_searched = ++searched;
    if (holds(k)) return k;
    if (near_only && searched >= kNearSearch) return -1;
    for (int f = 0; f < 4; ++f) {
      const Index u = neighbour(k, f);
      if (u >= 0 && alive[u] && !marked(u, seen)) mark_[u] = seen, near.push({distance(u), u});
    }
  }
  if (near_only) return -1;
  for (std::size_t k = 0; k < tet.size(); ++k)
    if (alive[k] && !marked(static_cast<Index>(k), seen) && holds(static_cast<Index>(k))) return static_cast<Index>(k);
  return -1;
}

bool TetComplex::holders(const Vec3& p, Index t0, std::vector<Index>* hold) const {
  *hold = {t0};
  for (std::size_t i = 0; i < hold->size(); ++i) {
    const Index t = (*hold)[i];
    int zeros = 0;
    for (int f = 0; f < 4; ++f) {
      const auto fv = face(t, f);
      if (orient3d(X[fv[0]], X[fv[1]], X[fv[2]], p) != 0) continue;
      ++zeros;
      if (is_constrained(t, f)) return false;  // on the boundary: not ours to split
      if (std::find(hold->begin(), hold->end(), neighbour(t, f)) == hold->end()) hold->push_back(neighbour(t, f));
    }
    if (zeros >= 3) return false;  // on a node
  }
  return true;
}

std::vector<Index> TetComplex::insert(Index v, Index start) {
  const Vec3& p = X[v];
  const Index t0 = locate(p, start);
  std::vector<Index> hold;
  if (t0 < 0 || !holders(p, t0, &hold)) return {};
  std::vector<Tet> fresh;
  for (Index t : hold)
    for (int j = 0; j < 4; ++j) {
      const auto fv = face(t, j);
      if (orient3d(X[fv[0]], X[fv[1]], X[fv[2]], p) >= 0) continue;
      Tet n = tet[t];
      n[j] = v;
      fresh.push_back(n);
    }
  return replace(hold, fresh);
}

std::vector<Index> TetComplex::insert_delaunay(Index v, Index start, std::vector<Tet>* replaced, bool near_only) {
  const Vec3& p = X[v];
  const Index t0 = locate(p, start, near_only);
  if (t0 < 0) return {};
  std::vector<Index> seed;  // the tetrahedra whose closure holds p
  if (!holders(p, t0, &seed)) return {};
  const unsigned in_cavity = new_stamp();
  std::vector<Index> cavity = seed;
  for (Index t : seed) mark_[t] = in_cavity;
  for (std::size_t i = 0; i < cavity.size(); ++i)
    for (int f = 0; f < 4; ++f) {
      const Index n = neighbour(cavity[i], f);
      if (n < 0 || marked(n, in_cavity) || is_constrained(cavity[i], f)) continue;
      const Tet& u = tet[n];
      if (geom::insphere(X[u[0]], X[u[1]], X[u[2]], X[u[3]], p) > 0) {
        cavity.push_back(n);
        mark_[n] = in_cavity;
      }
    }
  // star-shaped from p: drop (non-seed) tetrahedra whose outer faces p does not see from
  // inside, keep what still hangs together from the seeds, until nothing changes
  auto is_seed = [&](Index t) { return std::find(seed.begin(), seed.end(), t) != seed.end(); };
  unsigned current = in_cavity;
  for (;;) {
    std::vector<Index> kept;
    for (Index t : cavity) {
      bool sees = true;
      for (int f = 0; f < 4 && sees && !is_seed(t); ++f) {
        if (marked(neighbour(t, f), current)) continue;
        const auto fv = face(t, f);
        sees = orient3d(X[fv[0]], X[fv[1]], X[fv[2]], p) < 0;
      }
      if (sees) kept.push_back(t);
    }
    if (kept.size() == cavity.size()) break;
    const unsigned in_kept = new_stamp();
    for (Index t : kept) mark_[t] = in_kept;
    const unsigned reached = new_stamp();
    std::vector<Index> front = seed;
    for (Index t : seed) mark_[t] = reached;
    for (std::size_t i = 0; i < front.size(); ++i)
      for (int f = 0; f < 4; ++f) {
        const Index n = neighbour(front[i], f);
        if (n < 0 || !marked(n, in_kept) || is_constrained(front[i], f)) continue;
        mark_[n] = reached;
        front.push_back(n);
      }
    cavity = std::move(front);
    current = reached;
  }
  const unsigned final_mark = new_stamp();
  for (Index t : cavity) mark_[t] = final_mark;
  // two arms of the cavity may meet across a constrained face: it must stay, so v does not go in
  for (Index t : cavity)
    for (int f = 0; f < 4; ++f)
      if (marked(neighbour(t, f), final_mark) && is_constrained(t, f)) return {};
  std::vector<Tet> fresh;
  for (Index t : cavity)
    for (int f = 0; f < 4; ++f) {
      const Index n = neighbour(t, f);
      if (marked(n, final_mark)) continue;
      const auto fv = face(t, f);
      if (orient3d(X[fv[0]], X[fv[1]], X[fv[2]], p) >= 0) continue;  // a seed face p lies on
      Tet m = tet[t];
      m[f] = v;
      fresh.push_back(m);
    }
  if (replaced) {
    replaced->clear();
    for (Index t : cavity) replaced->push_back(tet[t]);
  }
  return replace(cavity, fresh);
}

}  // namespace bisect::tet
