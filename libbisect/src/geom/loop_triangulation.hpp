// Triangulation of a simple polygon with holes by ear clipping, for the interface surfaces of
// edge-following bisection (thesis 7.3.3-7.3.4: the walked loops are projected onto the cut plane
// and triangulated there, and the triangles stitched back in 3D). Every decision is an exact
// orient2d on the projected points.
#pragma once
#include <array>
#include <vector>

#include "bisect/types.hpp"

namespace bisect {

// loops[0] counter-clockwise, the others (holes) clockwise, points by index into pts. Returns
// counter-clockwise triangles of point indices; empty when the loops are not a simple polygon.
std::vector<std::array<int, 3>> triangulate_loops(const std::vector<Vec2>& pts, const std::vector<std::vector<int>>& loops);

}  // namespace bisect
