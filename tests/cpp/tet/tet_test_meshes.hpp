// Small meshes built by hand for the tet tests: a valid two-tetrahedron mesh and a structured
// k×k×k cube mesh (each cube split into 6 tetrahedra around its main diagonal), in order 1 or 2.
#pragma once
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <map>
#include <utility>

#include "bisect/tet_mesh.hpp"

namespace bisect::test {

// Signed 6·volume in floating point: exact for the small integer coordinates used here.
inline double six_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a));
}

// Two positively oriented tetrahedra sharing the face 0 1 2: apex 3 above it, apex 4 below.
inline TetMesh two_tet_mesh() {
  TetMesh m;
  m.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.2, 0.3, 1), Vec3(0.3, 0.2, -1)};
  const Index t0[4] = {0, 1, 2, 3};
  const Index t1[4] = {0, 2, 1, 4};
  m.add_tet(t0);
  m.add_tet(t1, 1);
  return m;
}

inline Index grid_node(int k, int i, int j, int l) { return Index(i + (k + 1) * (j + (k + 1) * l)); }

// The unit cube [0,k]^3 in k^3 cubes of edge 1, each cut into the 6 Kuhn tetrahedra
// corner, corner+e_σ0, corner+e_σ0+e_σ1, opposite corner for the 6 permutations σ. All cubes cut
// alike, so the mesh is conforming; tetrahedra of odd permutations are reoriented by swapping
// their last two nodes.
inline TetMesh cube_mesh(int k) {
  TetMesh m;
  for (int l = 0; l <= k; ++l)
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i <= k; ++i) m.nodes.emplace_back(i, j, l);
  std::array<int, 3> perms[6] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  m.tets.reserve(std::size_t(6) * k * k * k * 4);
  m.region.reserve(std::size_t(6) * k * k * k);
  for (int l = 0; l < k; ++l)
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i)
        for (const auto& p : perms) {
          int c[3] = {i, j, l};
          Index v[4];
          v[0] = grid_node(k, c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            v[s + 1] = grid_node(k, c[0], c[1], c[2]);
          }
          if (six_volume(m.nodes[v[0]], m.nodes[v[1]], m.nodes[v[2]], m.nodes[v[3]]) < 0) std::swap(v[2], v[3]);
          m.add_tet(v);
        }
  return m;
}

// Order 2 from order 1: one mid-edge node per edge, at the midpoint, shared by every
// tetrahedron around the edge (slots 4..9 on kTetEdge).
inline TetMesh to_order2(const TetMesh& linear) {
  TetMesh m;
  m.order = 2;
  m.nodes = linear.nodes;
  std::map<std::pair<Index, Index>, Index> mid;
  for (std::size_t t = 0; t < linear.num_tets(); ++t) {
    Index v[10];
    for (int i = 0; i < 4; ++i) v[i] = linear.tet_node(t, i);
    for (int e = 0; e < 6; ++e) {
      Index a = v[kTetEdge[e][0]], b = v[kTetEdge[e][1]];
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it == mid.end()) {
        it = mid.emplace(key, Index(m.nodes.size())).first;
        m.nodes.push_back((m.nodes[a] + m.nodes[b]) / 2);
      }
      v[4 + e] = it->second;
    }
    m.add_tet(v, linear.region.empty() ? 0 : linear.region[t]);
  }
  return m;
}

// Removes tetrahedron t (0-based), keeping the nodes.
inline TetMesh without_tet(const TetMesh& m, std::size_t t) {
  TetMesh out = m;
  const int npt = m.nodes_per_tet();
  out.tets.erase(out.tets.begin() + std::ptrdiff_t(t * npt), out.tets.begin() + std::ptrdiff_t((t + 1) * npt));
  out.region.erase(out.region.begin() + std::ptrdiff_t(t));
  return out;
}

}  // namespace bisect::test
