// Boundary triangles restored in a Delaunay tetrahedralization by local re-triangulation, for
// the fill by boundary recovery (recovery_fill.hpp). A boundary triangle missing from the
// tetrahedralization is crossed by some of its edges (or one of its own edges is missing and
// crosses some faces). The tetrahedra so crossed are taken out, and the hole they leave is
// filled again as a fan from one of its vertices that sees all of it, in which the missing
// edge or triangle is present: from an end of a missing edge; on either side of a missing
// triangle, whose own three edges are there. No node is ever added on the boundary (its grid is
// shared with the neighbouring cells). A hole no vertex sees whole is left as it was, unless the
// caller allows the second phase, run once the fans alone have done what they can:
// - a missing edge is brought closer by 2-3 flips and edge removals that leave fewer tetrahedra
//   in its way (or as many, when none leaves fewer, never undoing such a level change), none
//   taking out a wanted triangle or edge already there, until a fan from one of its ends fills
//   what is left;
// - Steiner points: a hole no vertex sees whole, but some point does (the side of a missing
//   triangle, or the tetrahedra in a missing edge's way), is fanned from a point added inside it.
#pragma once
#include <array>
#include <vector>

#include "tet/tet_complex.hpp"

namespace bisect::tet {

// Tries to make every triangle of `wanted` (node ids of dt's nodes) a face of dt. Returns how
// many are still missing. grow: null (the fans alone), or the very vector dt.X refers to (the
// second phase too); Steiner points are appended to it (those of a try that failed taken off
// again).
std::size_t recover_faces(TetComplex& dt, const std::vector<std::array<Index, 3>>& wanted, std::vector<Vec3>* grow = nullptr);

}  // namespace bisect::tet
