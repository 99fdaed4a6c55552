#include "optimize/inverted_refill.hpp"

#include <algorithm>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"
#include "optimize/node_stars.hpp"
#include "tet/cell_fill.hpp"
#include "tet/local_nodes.hpp"
#include "tet/recovery_fill.hpp"

namespace bisect::optimize {
namespace {

// Layers of neighbours the hole may grow by, and its size past which it stops growing: the folds
// sphere-in-box.brep leaves fill with the stars alone or a layer more (holes of 42 to 179
// tetrahedra); a hole of thousands is a mesh beyond mending here.
constexpr int kMaxLayers = 4;
constexpr std::size_t kMaxHole = 4000;

bool inverted(const std::vector<Vec3>& X, const tet::Tet& t) { return geom::orient3d(X[t[0]], X[t[1]], X[t[2]], X[t[3]]) <= 0; }

std::vector<Index> all_inverted(const tet::TetComplex& cx, const std::vector<Vec3>& X) {
  std::vector<Index> bad;
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t] && inverted(X, cx.tet[t])) bad.push_back(static_cast<Index>(t));
  return bad;
}

// The hole's boundary triangles (counter-clockwise from outside it) and its inner nodes; false
// when an input face's node, or a held face, would be inside (never cut out).
bool hole_shape(const tet::TetComplex& cx, const std::vector<Index>& hole, const std::vector<char>& fixed,
                std::vector<std::array<Index, 3>>* boundary, std::vector<Index>* inner) {
  boundary->clear(), inner->clear();
  std::vector<Index> on, all;
  for (Index t : hole)
    for (int f = 0; f < 4; ++f) {
      all.push_back(cx.tet[t][f]);
      const Index n = cx.neighbour(t, f);
      if (n >= 0 && std::binary_search(hole.begin(), hole.end(), n)) {
        if (cx.is_constrained(t, f)) return false;
        continue;
      }
      boundary->push_back(cx.face(t, f));
      on.insert(on.end(), boundary->back().begin(), boundary->back().end());
    }
  std::sort(on.begin(), on.end());
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  for (Index v : all)
    if (!std::binary_search(on.begin(), on.end(), v)) {
      if (fixed[v]) return false;
      inner->push_back(v);
    }
  return true;
}

// The hole filled again: from a point that sees its whole boundary (the star fill of a convex
// cell, 7.6) when there is one, else by Delaunay boundary recovery (which needs none, but fails
// on a boundary whose nodes the Delaunay tetrahedralization joins otherwise, as on a plane of
// co-circular grid nodes). Empty when neither works. No node is added: a helper the star fill
// keeps makes it fail here. Both work on the hole's own nodes, numbered locally (a copy of the
// mesh's nodes per try would cost more than the fill).
std::vector<tet::Tet> fill_hole(const std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary,
                                const std::vector<Index>& inner) {
  const tet::LocalNodes own(boundary, inner);
  std::vector<Vec3> Y = own.points(X);
  const std::vector<std::array<Index, 3>> lb = own.triangles(boundary);
  const std::vector<Index> li = own.nodes(inner);
  Vec3 centroid = Vec3::Zero();
  double area = 0;
  for (const auto& t : boundary) {
    const double a = (X[t[1]] - X[t[0]]).cross(X[t[2]] - X[t[0]]).norm();
    centroid += a * (X[t[0]] + X[t[1]] + X[t[2]]) / 3, area += a;
  }
  if (area > 0) centroid /= area;
  std::vector<tet::Tet> tets;
  try {
    tets = tet::fill_convex_cell(Y, lb, li, centroid);
    if (Y.size() != own.global.size()) tets.clear();
  } catch (const MeshingError&) {
  }
  if (tets.empty()) {
    try {
      Y.resize(own.global.size());
      tets = tet::fill_by_recovery(Y, lb, li);
    } catch (const MeshingError&) {
      return {};
    }
  }
  for (tet::Tet& t : tets)
    for (Index& v : t) v = own.global[v];
  return tets;
}

void sort_unique(std::vector<Index>* v) {
  std::sort(v->begin(), v->end());
  v->erase(std::unique(v->begin(), v->end()), v->end());
}

// The stars (within `region`) of the free nodes of the tetrahedra `folds` that are not opened
// yet go into the hole (unsorted); true when one was opened.
bool open_stars(const tet::TetComplex& cx, const std::vector<char>& fixed, const std::vector<Index>& folds, Index region,
                std::vector<Index>* hole, std::vector<Index>* opened) {
  bool any = false;
  for (Index t : folds)
    for (Index v : cx.tet[t]) {
      if (fixed[v] || std::find(opened->begin(), opened->end(), v) != opened->end()) continue;
      opened->push_back(v);
      for (Index u : star(cx, v, t))
        if (cx.tag[u] == region) hole->push_back(u);
      any = true;
    }
  return any;
}

// The hole closed over the fold: the stars of the free nodes of every inverted tetrahedron in it
// or next to it (across a face that is neither held nor another region's), until none is left
// at its edge (a last-resort cell can leave a cluster of them, each folding over the next:
// sphere-in-box.brep at 1.5e5 on the second proxy, 13 in one place).
void close_over_folds(const tet::TetComplex& cx, const std::vector<Vec3>& X, const std::vector<char>& fixed, std::vector<Index>* hole,
                      std::vector<Index>* opened) {
  const Index region = cx.tag[hole->front()];
  for (bool more = true; more;) {
    std::vector<Index> folds;
    for (Index t : *hole) {
      if (inverted(X, cx.tet[t])) folds.push_back(t);
      for (int f = 0; f < 4; ++f) {
        const Index n = cx.neighbour(t, f);
        if (n >= 0 && !cx.is_constrained(t, f) && cx.tag[n] == region && inverted(X, cx.tet[n])) folds.push_back(n);
      }
    }
    more = open_stars(cx, fixed, folds, region, hole, opened);
    // a fold of fixed nodes only, next to the hole, joins it too
    for (Index t : folds)
      if (std::find(hole->begin(), hole->end(), t) == hole->end()) hole->push_back(t), more = true;
    sort_unique(hole);
  }
}

// One more layer: the neighbours across faces that are neither constrained nor in another region.
void grow(const tet::TetComplex& cx, std::vector<Index>* hole) {
  const std::vector<Index> was = *hole;
  for (Index t : was)
    for (int f = 0; f < 4; ++f) {
      const Index n = cx.neighbour(t, f);
      if (n >= 0 && !cx.is_constrained(t, f) && cx.tag[n] == cx.tag[t] && !std::binary_search(was.begin(), was.end(), n))
        hole->push_back(n);
    }
  sort_unique(hole);
}

// Whether the new tetrahedra's outer faces are exactly the hole's boundary triangles, each once
// (the fills make positively oriented tetrahedra, so their outer faces then face out of the
// hole as its boundary does): what TetComplex::replace needs, checked before it (it throws halfway
// through, the complex changed: FreeCAD's constraint_tie at 6,044, order 2, ended in its error).
bool fills_exactly(const std::vector<tet::Tet>& fresh, const std::vector<std::array<Index, 3>>& boundary) {
  std::vector<std::array<Index, 3>> outer, want;
  const auto sorted = [](std::array<Index, 3> k) {
    std::sort(k.begin(), k.end());
    return k;
  };
  std::vector<std::array<Index, 3>> all;
  for (const tet::Tet& t : fresh)
    for (int f = 0; f < 4; ++f) all.push_back(sorted({t[(f + 1) % 4], t[(f + 2) % 4], t[(f + 3) % 4]}));
  std::sort(all.begin(), all.end());
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i + 1;
    while (j < all.size() && all[j] == all[i]) ++j;
    if (j - i > 2) return false;
    if (j - i == 1) outer.push_back(all[i]);
    i = j;
  }
  for (const auto& t : boundary) want.push_back(sorted(t));
  std::sort(want.begin(), want.end());
  return outer == want;
}

// The hole filled, grown by a layer (then opened up again) while that fails; true when filled.
template <typename OpenUp>
bool fill_layers(tet::TetComplex& cx, const std::vector<Vec3>& X, const std::vector<char>& fixed, std::vector<Index>* hole,
                 const OpenUp& open_up) {
  std::vector<std::array<Index, 3>> boundary;
  std::vector<Index> inner;
  for (int layer = 0; layer <= kMaxLayers && hole->size() <= kMaxHole; ++layer) {
    if (layer > 0) {
      grow(cx, hole);
      open_up();
    }
    if (!hole_shape(cx, *hole, fixed, &boundary, &inner)) continue;
    const std::vector<tet::Tet> fresh = fill_hole(X, boundary, inner);
    if (fresh.empty() || !fills_exactly(fresh, boundary)) continue;  // the hole's boundary folds too: a layer more
    cx.improve_around(cx.replace(*hole, fresh));
    return true;
  }
  return false;
}

}  // namespace

RefillCounts refill_inverted(tet::TetComplex& cx, const std::vector<Vec3>& X, const std::vector<char>& fixed) {
  RefillCounts n;
  for (const Index t0 : all_inverted(cx, X)) {
    // an earlier hole may have taken it (its id perhaps reused by a positive tetrahedron)
    if (!cx.alive[t0] || !inverted(X, cx.tet[t0])) continue;
    // first the stars of the fold's own free nodes, then the hole closed over the folds next to
    // it (sphere-in-box.brep: at 2e5, 1 of 4 folds filled only so, at 3e5, 3 of 3); each fold
    // is tried on its own, as one that fails in a cluster's hole may fill in its own
    for (const bool closed : {false, true}) {
      std::vector<Index> hole{t0};
      std::vector<Index> opened;  // free nodes whose stars are in the hole
      const auto open_up = [&] {
        if (closed) return close_over_folds(cx, X, fixed, &hole, &opened);
        open_stars(cx, fixed, {t0}, cx.tag[t0], &hole, &opened);
        sort_unique(&hole);
      };
      open_up();
      if (fill_layers(cx, X, fixed, &hole, open_up)) {
        ++n.refilled;
        break;
      }
    }
  }
  n.remaining = all_inverted(cx, X).size();
  return n;
}

bool find_fold(const tet::TetComplex& cx, const std::vector<Vec3>& X, Vec3* centroid, Index* region, tet::Tet* nodes) {
  for (std::size_t t = 0; t < cx.tet.size(); ++t) {
    const tet::Tet& u = cx.tet[t];
    if (!cx.alive[t] || !inverted(X, u)) continue;
    *centroid = (X[u[0]] + X[u[1]] + X[u[2]] + X[u[3]]) / 4;
    *region = cx.tag[t];
    if (nodes) *nodes = u;
    return true;
  }
  return false;
}

}  // namespace bisect::optimize
