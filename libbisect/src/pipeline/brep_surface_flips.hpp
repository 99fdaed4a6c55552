// Edge flips on the B-rep faces for the surface triangles' smallest angles, after the volume
// passes. Node moves (optimize/surface_angles.hpp) cannot mend a triangle whose corners are
// placed well but joined badly: sphere-in-box at its floor kept a flat triangle (142.7 degrees at
// a seam node between two near neighbours) whatever its nodes did. Such a triangle and its
// neighbour across an edge inside one B-rep face take the quadrilateral's other diagonal, with
// the tetrahedra behind them: the 2-2 transformation of thesis 7.5 on each side (once on the
// outer boundary, on both sides of an interface: 4 tetrahedra for 4).
#pragma once
#include <cstdint>
#include <vector>

#include "bisect/brep_input.hpp"
#include "pipeline/brep_grids.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::pipeline {

// Up to `rounds` rounds over the face pieces' triangles under optimize::kSurfaceWorkBelowDeg.
// An edge of such a triangle is flipped when
// - both its triangles lie in one B-rep face, the edge runs inside it (not along a B-rep edge or
//   seam: the ends have the same (u, v) in both triangles, up to a chart's shift), and the
//   quadrilateral is convex in (u, v);
// - on each side the edge has exactly two tetrahedra, with a common fourth node, and the two new
//   ones are positive with a smallest dihedral angle of at least their old ones' smallest or
//   optimize::kSurfaceDihedralBarDeg, whichever is smaller;
// - the new diagonal lies no further off the surface (at its middle) than the quadrilateral's
//   five edges did: the chordal error of the grid stays;
// - the smaller of the two triangles' smallest angles rises by 0.01 degrees or more.
// The pieces' triangles and their (u, v) follow, so the groups and the order-2 mid-nodes read
// the flipped grid; an interface's new triangles stay constrained in cx. Edges in order of their
// worse triangle, then of their nodes: the same mesh for the same input. Returns the flips made.
std::int64_t flip_surface_edges(const BrepInput& in, BrepGrids& grids, tet::TetComplex& cx, const std::vector<Vec3>& X, int rounds);

}  // namespace bisect::pipeline
