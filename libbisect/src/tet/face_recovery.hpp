// Boundary triangles restored in a Delaunay tetrahedralization by local re-triangulation, for
// the fill by boundary recovery (recovery_fill.hpp). A boundary triangle missing from the
// tetrahedralization is crossed by some of its edges (or one of its own edges is missing and
// crosses some faces). The tetrahedra so crossed are taken out, and the hole they leave is
// filled again as a fan from one of its vertices that sees all of it, in which the missing
// edge or triangle is present: from an end of a missing edge; on either side of a missing
// triangle, whose own three edges are there. No node is added (the boundary is shared with the
// neighbouring cells); a hole no vertex sees whole is left as it was.
#pragma once
#include <array>
#include <vector>

#include "tet/tet_complex.hpp"

namespace bisect::tet {

// Tries to make every triangle of `wanted` (node ids of dt's nodes) a face of dt. Returns how
// many are still missing.
std::size_t recover_faces(TetComplex& dt, const std::vector<std::array<Index, 3>>& wanted);

}  // namespace bisect::tet
