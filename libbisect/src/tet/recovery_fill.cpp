#include "tet/recovery_fill.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"
#include "tet/face_recovery.hpp"

namespace bisect::tet {

std::vector<Tet> fill_by_recovery(const std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary,
                                  const std::vector<Index>& interior, CellFillStats* stats, std::vector<Vec3>* steiner) {
  CellFillStats st;
  const Index n = static_cast<Index>(X.size());
  std::vector<Index> bnodes;
  for (const auto& t : boundary) bnodes.insert(bnodes.end(), t.begin(), t.end());
  std::sort(bnodes.begin(), bnodes.end());
  bnodes.erase(std::unique(bnodes.begin(), bnodes.end()), bnodes.end());
  if (boundary.size() < 4 || bnodes.size() < 4) throw MeshingError("boundary recovery: the cell has fewer than four boundary triangles");

  // a tetrahedron far around the nodes: four corners at 20 times the box's size
  Vec3 lo = X[bnodes[0]], hi = lo;
  for (Index v : bnodes) lo = lo.cwiseMin(X[v]), hi = hi.cwiseMax(X[v]);
  const Vec3 c = 0.5 * (lo + hi);
  const double s = 20 * std::max((hi - lo).norm(), std::numeric_limits<double>::min());
  std::vector<Vec3> Y = X;
  Y.push_back(c + s * Vec3(1, 1, 1));
  Y.push_back(c + s * Vec3(1, -1, -1));
  Y.push_back(c + s * Vec3(-1, 1, -1));
  Y.push_back(c + s * Vec3(-1, -1, 1));
  Tet big = {n, n + 1, n + 2, n + 3};
  if (geom::orient3d(Y[big[0]], Y[big[1]], Y[big[2]], Y[big[3]]) < 0) std::swap(big[2], big[3]);

  // the boundary nodes, Delaunay, nearest the previous first (short walks)
  TetComplex dt(Y);
  dt.build({big});
  // insertion order: by z, then y, then x (nearest the previous node first: short walks)
  auto by_position = [&](Index a, Index b) {
    const Vec3 pa = X[a] - lo, pb = X[b] - lo;
    return std::tie(pa.z(), pa.y(), pa.x()) < std::tie(pb.z(), pb.y(), pb.x());
  };
  std::vector<Index> order = bnodes;
  std::sort(order.begin(), order.end(), by_position);
  Index last = 0;
  for (Index v : order) {
    const std::vector<Index> made = dt.insert_delaunay(v, last);
    if (made.empty()) throw MeshingError("boundary recovery: two boundary nodes coincide");
    last = made.front();
  }

  // boundary triangles that are not faces restored by local re-triangulation (face_recovery.hpp)
  recover_faces(dt, boundary, steiner ? &Y : nullptr);
  // every boundary triangle a face, seen from the tetrahedron it bounds inside
  std::unordered_map<FaceKey, std::array<Index, 3>, FaceKeyHash> wanted;  // key -> triangle, smallest node first
  for (const auto& t : boundary) wanted[face_key(t[0], t[1], t[2])] = smallest_first(t);
  std::vector<char> side(dt.tet.size(), 0);  // 1 inside, 2 outside
  std::size_t found = 0;
  for (std::size_t t = 0; t < dt.tet.size(); ++t) {
    if (!dt.alive[t]) continue;
    for (int f = 0; f < 4; ++f) {
      const std::array<Index, 3> fc = dt.face(static_cast<Index>(t), f);
      const auto it = wanted.find(face_key(fc[0], fc[1], fc[2]));
      if (it == wanted.end()) continue;
      // the triangle's outward normal leaves the cell: the tetrahedron whose face turns the same
      // way lies inside
      const bool inside = smallest_first(fc) == it->second;
      const char mark = inside ? 1 : 2;
      if (side[t] != 0 && side[t] != mark) throw MeshingError("boundary recovery: a tetrahedron lies on both sides of the boundary");
      side[t] = mark;
      found += inside;
    }
  }
  if (found != boundary.size())
    throw MeshingError("boundary recovery: " + std::to_string(boundary.size() - found) + " of " + std::to_string(boundary.size()) +
                       " boundary triangles are not faces of the Delaunay tetrahedralization");
  // the sides spread across every face that is no boundary triangle
  std::vector<Index> stack;
  for (std::size_t t = 0; t < dt.tet.size(); ++t)
    if (dt.alive[t] && side[t]) stack.push_back(static_cast<Index>(t));
  while (!stack.empty()) {
    const Index t = stack.back();
    stack.pop_back();
    for (int f = 0; f < 4; ++f) {
      const Index u = dt.neighbour(t, f);
      if (u < 0) continue;
      const std::array<Index, 3> fc = dt.face(t, f);
      if (wanted.count(face_key(fc[0], fc[1], fc[2]))) continue;
      if (side[u] == 0) {
        side[u] = side[t];
        stack.push_back(u);
      } else if (side[u] != side[t]) {
        throw MeshingError("boundary recovery: the boundary does not close off an inside");
      }
    }
  }
  std::vector<Tet> inside;
  // Steiner points (Y's nodes past the box's corners) that inside tetrahedra use follow X's
  // nodes, in the order those tetrahedra first use them; those outside the cell are dropped
  std::vector<Index> renumber(Y.size() - (n + 4), -1);
  std::vector<Vec3> Z = X;
  for (std::size_t t = 0; t < dt.tet.size(); ++t) {
    if (!dt.alive[t]) continue;
    if (side[t] == 0) throw MeshingError("boundary recovery: a tetrahedron is on neither side of the boundary");
    if (side[t] != 1) continue;
    Tet q = dt.tet[t];
    for (Index& v : q) {
      if (v < n) continue;
      if (v < n + 4) throw MeshingError("boundary recovery: the boundary is open");
      Index& r = renumber[v - (n + 4)];
      if (r < 0) r = static_cast<Index>(Z.size()), Z.push_back(Y[v]);
      v = r;
    }
    inside.push_back(q);
  }
  st.steiner = static_cast<std::int64_t>(Z.size() - X.size());
  if (steiner) steiner->assign(Z.begin() + n, Z.end());

  // the interior nodes, with Delaunay cavities held by the boundary, then the min-max passes
  TetComplex cx(Z);
  cx.edge_removal_below = 0.060072058;  // as fill_convex_cell: the global passes do the rest
  cx.build(std::move(inside));
  st.flips += cx.improve_all(std::numeric_limits<std::int64_t>::max());
  std::vector<Index> rest = interior;
  std::sort(rest.begin(), rest.end(), by_position);
  last = 0;
  for (Index v : rest) {
    while (!cx.alive[last]) ++last;  // the first live one: the walk starts from a tetrahedron
    const std::vector<Index> made = cx.insert_delaunay(v, last);
    if (made.empty()) {
      ++st.skipped;
      continue;
    }
    ++st.inserted;
    last = made.front();
  }
  st.flips += cx.improve_all(std::numeric_limits<std::int64_t>::max());
  std::vector<Tet> out = cx.tets();
  for (const Tet& t : out)
    if (geom::orient3d(Z[t[0]], Z[t[1]], Z[t[2]], Z[t[3]]) <= 0) throw MeshingError("boundary recovery: a flat or inverted tetrahedron");
  if (stats) *stats = st;
  return out;
}

}  // namespace bisect::tet
