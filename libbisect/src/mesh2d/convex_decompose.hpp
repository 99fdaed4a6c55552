// A planar region cut into convex pieces (thesis 4.6.3, 4.6.4) for the nodal placement by
// shrinking. Each hole is first joined to the outer boundary by two separators (cut edges from
// the hole's nodes to the nearest boundary nodes that see them), which splits the region into
// simple polygons; then every reflex vertex is resolved by a separator to a visible boundary
// node inside its inner cone, the one making the largest smallest angle. Separators get nodes at
// the spacing h, shared by the pieces on both sides.
#pragma once
#include <vector>

#include "bisect/types.hpp"

namespace bisect::mesh2d {

// loops: loops[0] the outer boundary counter-clockwise, the others holes clockwise, with their
// boundary nodes. New separator nodes are appended to `nodes`. Returns counter-clockwise loops,
// convex except where a reflex vertex has no separator at all (a neck narrower than the angles
// allow, seen on faces of CSG unions): that piece is returned as it is, and the shrinking nodes,
// which lie inside the moved half-planes of all its edges, still fall inside it.
std::vector<std::vector<Index>> convex_pieces(std::vector<Vec2>& nodes, const std::vector<std::vector<Index>>& loops, double h);

}  // namespace bisect::mesh2d
