// The surface's smallest angles after the volume passes. The face moves of the mean shape
// (mean_shape.hpp) move a node inside a face for its tetrahedra's sake and only keep its boundary
// triangles' smallest angle; where the face grids met at the decomposition's cuts, or where the
// morph onto a curved face bent them, a triangle under 20 degrees can stay (sphere-in-box at its
// floor: 15.7 degrees on the sphere, at its seam). This pass moves such a triangle's nodes within
// their faces, and along their B-rep edges, for the triangles' sake, while no tetrahedron round
// the node falls under its bar (kSurfaceDihedralBarDeg). What moves cannot mend, the B-rep route
// flips (pipeline/brep_surface_flips.hpp).
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "optimize/mean_shape.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::optimize {

// The smallest angle (degrees) of the node's boundary triangles: the constrained faces at it of
// the tetrahedra `around` it (input faces and interfaces); 180 when there is none.
double smallest_boundary_angle(const tet::TetComplex& cx, const std::vector<Vec3>& X, Index node, const std::vector<Index>& around);

// The smallest angle (degrees) the surface grids aim at: a change that lifts a triangle under it
// may trade tetrahedra's angles down to surface_trade_floor_deg for it.
inline constexpr double kSurfaceAimDeg = 20;

// Boundary triangles under this (degrees) are worked on: above the 20 the surface grids aim at,
// so that a move that lifts a triangle from 19 to 21 degrees is not the last one made.
inline constexpr double kSurfaceWorkBelowDeg = 25;

// A move for the surface may lower a tetrahedron's smallest dihedral angle down to this (degrees)
// or to its star's smallest, whichever is larger, and never one's that is already lower: a move
// that rounds off one triangle must not leave slivers beside a sharp B-rep edge (part.step at
// 10^5: with the star's smallest as the only bar, 40 tetrahedra under 10 degrees against 18).
inline constexpr double kSurfaceDihedralBarDeg = 15;

// The smallest dihedral angle (degrees) a change may leave a tetrahedron at (never below its own)
// to lift a boundary triangle whose smallest angle, `triangle` degrees, is under kSurfaceAimDeg:
// 5 degrees under the triangle's, between 10 (the sliver repair's bar) and kSurfaceDihedralBarDeg.
// The worse the triangle, the more a tetrahedron may give for it: on a box with a ball inside
// (tests/cpp/occ/test_brep_surface_flips.cpp) at R = 3000, a 4-degree triangle at the ball's seam
// rose to 12.7 for a tetrahedron from 13.3 to 10.8 degrees, and flips that lift triangles from
// 16-18 degrees to 23-38 left new tetrahedra at 13-14.8.
// A trade is taken only where it lifts the triangle this much (degrees) more than a change
// within the strict bars does.
inline constexpr double kSurfaceTradeGainDeg = 1;
inline double surface_trade_floor_deg(double triangle) { return std::clamp(triangle - 5, 10.0, kSurfaceDihedralBarDeg); }

// Up to `rounds` rounds over the nodes that `slides` lets move (fixed, inside one input face or
// one B-rep edge) and that have a boundary triangle under kSurfaceWorkBelowDeg. A node in a face
// tries two directions in it: towards the middle of its neighbours on its boundary triangles, and
// up the gradient of those triangles' smallest angle (forward differences in the tangent plane, a
// step of half the neighbours' mean distance); a node in an edge, the edge's tangent either way
// (the same step). Along each the whole step, a half, a quarter and an eighth of it, taken into
// the face or onto the edge. It takes the candidate with the largest smallest angle, when that is
// larger than before by 0.01 degrees or more, every tetrahedron round it is positive, and none
// falls under its bar (kSurfaceDihedralBarDeg, or the star's smallest). With `trades` (the
// B-rep route, whose surfaces aim at 20 degrees; a polyhedral input's facets often cannot, and
// lug.stl lost 13.1 to 10.2 degrees of its smallest dihedral angle to trades): for a triangle
// under kSurfaceAimDeg where no such candidate reaches the aim, the best under the trade's floor
// (surface_trade_floor_deg) instead, when it gains kSurfaceTradeGainDeg more; and where neither
// is taken, the best candidate of all with the transformations of 7.5 round the node after it,
// undone unless every tetrahedron left there meets the trade's bars. One thread, nodes in id
// order: the same mesh for the same input. Returns the moves made.
std::int64_t improve_surface_angles(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, const FaceSlides& slides,
                                    int rounds, bool trades = false);

}  // namespace bisect::optimize
