// The mesh validator: every violation of the invariants of ARCHITECTURE.md §3, with ids.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bisect/tet_mesh.hpp"

namespace bisect {

enum class ViolationKind {
  BadNodeIndex,     // a tetrahedron or triangle refers to a node that does not exist; ids: element
  RepeatedNode,     // a tetrahedron uses one node twice; ids: tetrahedron
  InvertedTet,      // negative orientation (exact orient3d); ids: tetrahedron
  ZeroVolumeTet,    // the four corners are coplanar (exact); ids: tetrahedron
  NonManifoldFace,  // a face shared by more than two tetrahedra; ids: the tetrahedra
  OpenBoundary,     // an edge of the boundary surface used by an odd number of boundary faces;
                    // ids: the edge's two nodes
  DuplicateNode,    // two nodes of one body (tetrahedra joined through nodes) at the same
                    // coordinates; ids: the nodes. Separate bodies may touch.
  UnusedNode,       // a node no tetrahedron uses; ids: the node
  BadMidNode,       // order 2: a mid-edge node shared inconsistently by two tetrahedra of the
                    // same edge; ids: the tetrahedra
  NonFiniteNode,    // a node with a NaN or infinite coordinate; ids: the node (the tetrahedra
                    // using it are not judged for orientation)
  NonPositiveJacobian,  // order 2: the element's Jacobian determinant is zero or negative at a
                        // corner, at one of the 4 Gauss points CalculiX integrates C3D10 at, at
                        // an edge's middle or at the centre; ids: tetrahedron
};

// The kind as a snake_case name ("inverted_tet"), the spelling of the CLI's JSON and Python.
const char* to_string(ViolationKind k);

struct Violation {
  ViolationKind kind;
  std::vector<std::int64_t> ids;  // element or node numbers as reported (TetMesh::tet_id/node_id)
  std::string message;            // one line naming what and where
};

// Order 2: the smallest determinant of tetrahedron t's Jacobian over its 4 corners, the 4
// Gauss points of the 4-point rule, its 6 edges' middles and its centre, divided by the straight element's (6 V, positive for a
// positively oriented one). 1 for a straight element; <= 0 for a folded one.
double tet10_jacobian_ratio(const TetMesh& mesh, std::size_t t);

// All violations, in a stable order (by kind, then by id). An empty result means a valid mesh.
// Mid-edge nodes of order-2 meshes count as used. progress (optional) is called with the
// fraction done, at most every 50 ms; when it returns false the check stops with Cancelled.
std::vector<Violation> validate(const TetMesh& mesh, const std::function<bool(double)>& progress = {});

}  // namespace bisect
