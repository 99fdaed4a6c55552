// TetMesh: the value every stage ends in and every writer, reader and checker works on.
//
// Flat arrays of plain values indexed by int32 (ARCHITECTURE.md §5, after HXT):
//   nodes          #N          coordinates
//   tets           #T * npt    corner nodes first, then for order 2 the mid-edge nodes
//   region         #T          region id of each tetrahedron (0-based, as the input's regions)
//   tris           #B * 3|6    boundary (or interface) triangles, corners then mid-edge nodes
//   tri_tag        #B          the input face (or B-rep face) each triangle lies on
//
// Local numbering (one drawing for the whole project):
//
//            3                 positive orientation: orient3d(p0, p1, p2, p3) > 0, i.e.
//           /|\                (p1 - p0) . ((p2 - p0) x (p3 - p0)) > 0
//          / | \ .
//         /  |  \              face f is opposite corner f; kTetFace[f] lists its corners in
//        0---|---2             the order whose right-hand normal points out of the tetrahedron
//         \  |  /
//          \ | /               mid-edge nodes of a 10-node tetrahedron, in slots 4..9, lie on
//           \|/                the edges kTetEdge[0..5] = 01 12 02 03 13 23 (the order of VTK,
//            1                 Abaqus C3D10 and FreeCAD/SMESH; Gmsh swaps the last two)
//
// Triangles: corners 0 1 2, then for order 2 the mid-edge nodes of edges 01 12 20.
#pragma once
#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include "bisect/types.hpp"

namespace bisect {

constexpr std::array<std::array<int, 3>, 4> kTetFace{{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};
constexpr std::array<std::array<int, 2>, 6> kTetEdge{{{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}}};
constexpr std::array<std::array<int, 2>, 3> kTriEdge{{{0, 1}, {1, 2}, {2, 0}}};

struct TetMesh {
  int order = 1;  // 1: 4-node tetrahedra, 3-node triangles; 2: 10-node and 6-node
  std::vector<Vec3> nodes;
  std::vector<Index> tets;
  std::vector<Index> region;
  std::vector<Index> tris;
  std::vector<Index> tri_tag;
  // Optional numbers the nodes and tetrahedra carry in a file they were read from (reports name
  // elements by them); empty means "index + 1".
  std::vector<std::int64_t> node_ids;
  std::vector<std::int64_t> tet_ids;

  int nodes_per_tet() const { return order == 2 ? 10 : 4; }
  int nodes_per_tri() const { return order == 2 ? 6 : 3; }
  std::size_t num_tets() const { return tets.size() / nodes_per_tet(); }
  std::size_t num_tris() const { return tris.size() / nodes_per_tri(); }
  Index tet_node(std::size_t t, int i) const { return tets[t * nodes_per_tet() + i]; }
  std::int64_t node_id(std::size_t n) const { return node_ids.empty() ? std::int64_t(n) + 1 : node_ids[n]; }
  std::int64_t tet_id(std::size_t t) const { return tet_ids.empty() ? std::int64_t(t) + 1 : tet_ids[t]; }

  // Appends a tetrahedron (npt nodes) in the given region; returns its index.
  Index add_tet(const Index* v, Index region_id = 0);

  // Face adjacency, computed on demand: neigh[4*t + f] = 4*t2 + f2 when face f of t is face f2
  // of t2, -1 on the boundary. Faces shared by more than two tetrahedra are left at -1 for all
  // but the first pair; the validator reports them.
  std::vector<Index> neighbours() const;
};

// The 10-node mesh of a 4-node one: a node at the middle of every edge, shared by the
// tetrahedra and triangles on that edge, in the kTetEdge and kTriEdge slots. Straight edges keep
// the mid-nodes on the (planar) faces of a polyhedral domain. Corner nodes keep their indices;
// the mid-nodes follow them. A mesh already of order 2 comes back unchanged. cancelled
// (optional) is asked every 4096 tetrahedra; true stops with Cancelled.
TetMesh to_second_order(const TetMesh& linear, const std::function<bool()>& cancelled = {});

}  // namespace bisect
