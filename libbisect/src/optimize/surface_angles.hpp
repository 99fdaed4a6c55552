// The surface's smallest angles after the volume passes. The face moves of the mean shape
// (mean_shape.hpp) move a node inside a face for its tetrahedra's sake and only keep its boundary
// triangles' smallest angle; where the face grids met at the decomposition's cuts, or where the
// morph onto a curved face bent them, a triangle under 20 degrees can stay (sphere-in-box at its
// floor: 15.7 degrees on the sphere). This pass moves such a triangle's nodes within their faces
// towards the middle of their surface neighbours, for the triangles' sake, while every
// tetrahedron round the node keeps the smallest dihedral angle its star had.
#pragma once
#include <cstdint>
#include <vector>

#include "optimize/mean_shape.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::optimize {

// The smallest angle (degrees) of the node's boundary triangles: the constrained faces at it of
// the tetrahedra `around` it (input faces and interfaces); 180 when there is none.
double smallest_boundary_angle(const tet::TetComplex& cx, const std::vector<Vec3>& X, Index node, const std::vector<Index>& around);

// Boundary triangles under this (degrees) are worked on: above the 20 the surface grids aim at,
// so that a move that lifts a triangle from 19 to 21 degrees is not the last one made.
inline constexpr double kSurfaceWorkBelowDeg = 25;

// Up to `rounds` rounds over the nodes that `slides` lets move (fixed, inside one input face) and
// that have a boundary triangle under kSurfaceWorkBelowDeg. Each node tries two directions in its
// face: towards the middle of its neighbours on its boundary triangles, and up the gradient of
// those triangles' smallest angle (forward differences in the tangent plane, a step of half the
// neighbours' mean distance); along each the whole step, a half, a quarter and an eighth of it,
// taken into the face. It takes the candidate with the largest smallest angle, when that is
// larger than before by 0.01 degrees or more, every tetrahedron round it is positive, and none
// has a dihedral angle smaller than the star's smallest before. One thread, nodes in id order:
// the same mesh for the same input. Returns the moves made.
std::int64_t improve_surface_angles(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, const FaceSlides& slides,
                                    int rounds);

}  // namespace bisect::optimize
