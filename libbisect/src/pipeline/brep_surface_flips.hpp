// Edge flips on the B-rep faces for the surface triangles' smallest angles, after the volume
// passes. Node moves (optimize/surface_angles.hpp) cannot mend a triangle whose corners are
// placed well but joined badly: sphere-in-box at its floor kept a flat triangle (142.7 degrees at
// a seam node between two near neighbours) whatever its nodes did. Such a triangle and its
// neighbour across an edge inside one B-rep face take the quadrilateral's other diagonal, with
// the tetrahedra behind them on each side (once on the outer boundary, on both sides of an
// interface): the ring of tetrahedra round the edge gives way to its polygon triangulated and
// joined to the edge's ends (the 2-2 transformation of thesis 7.5 where the ring has two).
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
//   seam: the ends have the same (u, v) in both triangles, up to a chart's shift; a pole, one
//   end at most, has its own (u, v) in each), and the quadrilateral is convex in (u, v) (at a
//   pole, in the plane across the two triangles' normals);
// - on each side the ring of tetrahedra from one triangle to the other round the edge (at most
//   TetComplex::kMaxRing - 1 of them, no constrained face between) has a triangulation of its
//   polygon whose tetrahedra are positive with a smallest dihedral angle of at least the ring's
//   smallest or the floor, whichever is smaller (optimize::surface_trade_floor_deg for triangles
//   under optimize::kSurfaceAimDeg, else optimize::kSurfaceDihedralBarDeg); a ring of one
//   tetrahedron holding both triangles (a cap) goes, on one side at most;
// - the new diagonal lies no further off the surface (at its middle) than the quadrilateral's
//   five edges did: the chordal error of the grid stays;
// - the smaller of the two triangles' smallest angles rises by 0.01 degrees or more.
// The pieces' triangles and their (u, v) follow, so the groups and the order-2 mid-nodes read
// the flipped grid; an interface's new triangles stay constrained in cx. Edges in order of their
// worse triangle, then of their nodes: the same mesh for the same input. Returns the flips made.
std::int64_t flip_surface_edges(const BrepInput& in, BrepGrids& grids, tet::TetComplex& cx, const std::vector<Vec3>& X, int rounds);

}  // namespace bisect::pipeline
