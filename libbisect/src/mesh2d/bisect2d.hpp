// Triangulation by recursive bisection after Lewis and Robinson (thesis 4.3): a polygon with
// nodes inside is split along a line between two of its boundary nodes, "opposite" ones tried
// first, the line weighted by prod(E^b) (4.3.1: the product of the boundary nodes' distances to
// it, times E to the power of their number, E the smaller of half the mean boundary spacing and
// the distance of the nearest inside node within the line's rectangle); inside nodes close to
// the line join the new boundary (4.3.2). A polygon with no acceptable split is a domain of
// peculiarity (4.3.3): the vertex whose cut-off triangle has the largest smallest angle is
// removed; a triangle with nodes inside is split by joining two of its corners to one of them.
#pragma once
#include <array>
#include <vector>

#include "bisect/types.hpp"

namespace bisect::mesh2d {

// loop: boundary node ids, counter-clockwise, a simple polygon; inside: node ids strictly inside
// it. Appends counter-clockwise triangles to `tris`; throws MeshingError when it cannot finish.
void bisection_triangulate(const std::vector<Vec2>& nodes, const std::vector<Index>& loop,
                           const std::vector<Index>& inside, std::vector<std::array<Index, 3>>& tris);

}  // namespace bisect::mesh2d
