// The local transformations of thesis 7.5 driven from a queue of faces: 2-3 across a face, 2-2 on
// the outer boundary, and edge removal where a tetrahedron is poor (tet_edge_removal.cpp).
#include "tet/tet_complex.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "bisect/errors.hpp"
#include "bisect/quality.hpp"
#include "geom/predicates.hpp"
#include "util/edge_key.hpp"

namespace bisect::tet {

using geom::orient3d;

namespace {

// The 2-2 transformation keeps boundary triangles at or above this (20 degrees), or at the
// poorer old one's angle when that was below.
constexpr double kMinBoundaryAngle = 0.3490658503988659;

}  // namespace

bool TetComplex::try_flip22(Index t, int f, std::vector<std::pair<Index, int>>& queue) {
  const Index n = neighbour(t, f);
  const auto fv = face(t, f);
  const Index d = tet[t][f];
  const int nf = neighbour_face(t, f);
  const Index e = tet[n][nf];
  for (int k = 0; k < 3; ++k) {
    // the edge (x, y) of the shared face, its third node c: the faces (x, y, d) of t and
    // (x, y, e) of n are those opposite c
    const Index x = fv[k], y = fv[(k + 1) % 3], c = fv[(k + 2) % 3];
    const int ct = corner_of(t, c), cn = corner_of(n, c);
    if (neighbour(t, ct) >= 0 || neighbour(n, cn) >= 0) continue;  // not two faces of the outer boundary
    const auto ft = face(t, ct), fn = face(n, cn);
    const auto tag_t = surface_tag.find(face_key(ft[0], ft[1], ft[2]));
    const auto tag_n = surface_tag.find(face_key(fn[0], fn[1], fn[2]));
    if (tag_t == surface_tag.end() || tag_n == surface_tag.end() || tag_t->second != tag_n->second) continue;
    Tet tx = tet[t], ty = tet[t];  // (c, d, e) with x, and with y
    tx[corner_of(t, y)] = e;
    ty[corner_of(t, x)] = e;
    if (!positive(X, tx) || !positive(X, ty)) continue;  // the quadrilateral x d y e is not convex
    const double need = std::min(q[t], q[n]) * (1 + 1e-9);
    if (!(tet_angle_key(X, tx) > need) || !(tet_angle_key(X, ty) > need)) continue;
    // the boundary's grid was made for its triangles (4.4); they may not get worse than the
    // poorer of the two, nor under 20 degrees when they were above (without this, the flips
    // left more slivers than they removed, measured on the ../shared STL models)
    const double was = std::min(triangle_min_angle(X[x], X[y], X[d]), triangle_min_angle(X[x], X[y], X[e]));
    const double now = std::min(triangle_min_angle(X[x], X[d], X[e]), triangle_min_angle(X[y], X[d], X[e]));
    if (now < std::min(was, kMinBoundaryAngle)) continue;
    const Index tag = tag_t->second;
    surface_tag.erase(tag_t);
    surface_tag.erase(tag_n);
    surface_tag[face_key(x, d, e)] = tag;
    surface_tag[face_key(y, d, e)] = tag;
    failed_.erase(edge_key(x, y));
    for (Index id : replace({t, n}, {tx, ty}, true))
      for (int g = 0; g < 4; ++g) queue.push_back({id, g});
    return true;
  }
  return false;
}

bool TetComplex::flip23_unchecked(Index t, int f, std::vector<Tet>* fresh) const {
  const Index n = neighbour(t, f);
  if (n < 0 || is_constrained(t, f)) return false;
  const auto fv = face(t, f);
  const Index e = tet[n][neighbour_face(t, f)];  // n's corner opposite the shared face
  fresh->clear();
  for (Index c : fv) {  // each face corner of t replaced by e
    Tet m = tet[t];
    m[corner_of(t, c)] = e;
    fresh->push_back(m);
  }
  return true;
}

bool TetComplex::positive_all(const std::vector<Tet>& tets) const {
  for (const Tet& m : tets)
    if (!positive(X, m)) return false;
  return true;
}

bool TetComplex::try_flip23(Index t, int f, std::vector<std::pair<Index, int>>& queue) {
  const Index n = neighbour(t, f);
  if (n < 0) return false;
  flip_failed_.resize(4 * tet.size(), 0);
  const std::size_t here = 4 * static_cast<std::size_t>(t) + static_cast<std::size_t>(f);
  if (const std::uint64_t was = flip_failed_[here]; was != 0 && born_[t] <= was && born_[n] <= was) return false;
  const auto fail = [&] {
    if (clock_ < std::numeric_limits<std::uint32_t>::max())
      flip_failed_[here] = flip_failed_[4 * static_cast<std::size_t>(n) + static_cast<std::size_t>(neighbour_face(t, f))] =
          static_cast<std::uint32_t>(clock_);
    return false;
  };
  std::vector<Tet>& fresh = fresh_;
  if (!flip23_unchecked(t, f, &fresh)) return false;  // constrained
  const double need = std::min(q[t], q[n]) * (1 + 1e-9);
  for (const Tet& m : fresh)
    if (!(tet_angle_key(X, m) > need)) return fail();  // the smallest solid angle would not rise
  if (!positive_all(fresh)) return fail();  // the segment between the apexes misses the face
  old_.assign({t, n});
  for (Index id : replace(old_, fresh))
    for (int g = 0; g < 4; ++g) queue.push_back({id, g});
  return true;
}

std::int64_t TetComplex::improve(std::vector<std::pair<Index, int>> queue, std::int64_t max_ops) {
  std::int64_t ops = 0;
  for (std::size_t i = 0; i < queue.size() && ops < max_ops; ++i) {
    poll(i);
    const auto [t, f] = queue[i];
    if (!alive[t] || is_constrained(t, f)) continue;
    if (try_flip23(t, f, queue) || (boundary_flips && try_flip22(t, f, queue))) {
      ++ops;
      continue;
    }
    // edge removal costs a small dynamic programme per edge: only around a poor tetrahedron
    if (std::min(q[t], q[neighbour(t, f)]) >= edge_removal_below) continue;
    const auto fv = face(t, f);
    for (int e = 0; e < 3; ++e)
      if (try_edge_removal(t, fv[e], fv[(e + 1) % 3], queue)) {
        ++ops;
        break;
      }
  }
  return ops;
}

std::int64_t TetComplex::improve_around(const std::vector<Index>& tets) {
  std::vector<std::pair<Index, int>> queue;
  queue.reserve(4 * tets.size());
  for (Index t : tets)
    for (int f = 0; f < 4; ++f) queue.push_back({t, f});
  return improve(std::move(queue), std::numeric_limits<std::int64_t>::max());
}

std::int64_t TetComplex::improve_all(std::int64_t max_ops) {
  std::vector<std::pair<Index, int>> queue;
  for (std::size_t t = 0; t < tet.size(); ++t)
    if (alive[t])
      for (int f = 0; f < 4; ++f)
        if (neighbour(t, f) > static_cast<Index>(t)) queue.push_back({static_cast<Index>(t), f});
  return improve(std::move(queue), max_ops);
}

}  // namespace bisect::tet
