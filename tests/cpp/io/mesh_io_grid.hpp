// The grid mesh the mesh I/O tests write and read (test_mesh_io.cpp, test_mesh_io_errors.cpp).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "bisect/io.hpp"

namespace bisect::test {

// Six times the signed volume of (a, b, c, d), in long double.
inline long double six_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const long double ux = (long double)b.x() - a.x(), uy = (long double)b.y() - a.y(), uz = (long double)b.z() - a.z();
  const long double vx = (long double)c.x() - a.x(), vy = (long double)c.y() - a.y(), vz = (long double)c.z() - a.z();
  const long double wx = (long double)d.x() - a.x(), wy = (long double)d.y() - a.y(), wz = (long double)d.z() - a.z();
  return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
}

// n^3 cells of a rectilinear grid whose coordinates have no short decimal form, each cell cut
// into the 6 Kuhn tetrahedra (positively oriented). Region 1 where the cell lies at i >= n/2,
// so the regions interleave in tetrahedron order. Boundary triangles (outward, tag = side 0..5)
// and the interface between the regions (tag 6), in order 2 with mid-edge nodes everywhere.
inline TetMesh grid_mesh(int n, int order) {
  TetMesh m;
  m.order = order;
  auto coord = [&](int i, double p, double len) { return len * std::pow(i / double(n), p); };
  std::vector<std::array<int, 3>> lattice;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        m.nodes.emplace_back(coord(i, 1.3, 1.1), coord(j, 1.1, 0.7), coord(k, 1.7, std::sqrt(2.0)));
        lattice.push_back({i, j, k});
      }
  auto id = [&](int i, int j, int k) { return Index(i + (n + 1) * (j + (n + 1) * k)); };
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::vector<std::array<Index, 4>> corners;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (auto& p : perms) {
          int c[3] = {i, j, k};
          std::array<Index, 4> t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          if (six_volume(m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]], m.nodes[t[3]]) < 0) std::swap(t[1], t[2]);
          corners.push_back(t);
          m.region.push_back(2 * i >= n ? 1 : 0);
        }
  std::map<std::pair<Index, Index>, Index> mids;
  auto mid = [&](Index a, Index b) {
    auto key = std::minmax(a, b);
    auto it = mids.find(key);
    if (it != mids.end()) return it->second;
    m.nodes.push_back(0.5 * (m.nodes[a] + m.nodes[b]));
    return mids[key] = Index(m.nodes.size() - 1);
  };
  for (std::size_t t = 0; t < corners.size(); ++t) {
    const auto& c = corners[t];
    for (Index v : c) m.tets.push_back(v);
    if (order == 2)
      for (auto& e : kTetEdge) m.tets.push_back(mid(c[e[0]], c[e[1]]));
    for (int f = 0; f < 4; ++f) {
      const auto& fv = kTetFace[f];
      const Index a = c[fv[0]], b = c[fv[1]], d = c[fv[2]];
      int tag = -1;
      for (int axis = 0; axis < 3 && tag < 0; ++axis) {
        const int la = lattice[a][axis];
        if (la != lattice[b][axis] || la != lattice[d][axis]) continue;
        if (la == 0) tag = 2 * axis;
        else if (la == n) tag = 2 * axis + 1;
        else if (axis == 0 && 2 * la == n && m.region[t] == 0) tag = 6;
      }
      if (tag < 0) continue;
      m.tris.insert(m.tris.end(), {a, b, d});
      if (order == 2) m.tris.insert(m.tris.end(), {mid(a, b), mid(b, d), mid(d, a)});
      m.tri_tag.push_back(tag);
    }
  }
  return m;
}

}  // namespace bisect::test
