// Interior nodes of a convex polygon by shrinking it (thesis 4.6.5, after Joe's shrinking of a
// convex polygon): layer k is the polygon with every edge moved inwards by k h, i.e. the
// intersection of the moved half-planes; its corners sharper than 30 degrees are cut off by a
// line h / (2 tan(phi / 2)) from the corner (narrowness), corners closer than h / 2 are merged
// (short edges), and nodes go round it at spacing h. When not even the first layer exists, a
// polygon whose area exceeds 1.5 (n - 2) element areas gets one node at its centroid.
#pragma once
#include <vector>

#include "bisect/types.hpp"

namespace bisect::mesh2d {

// polygon: convex, counter-clockwise, with n boundary nodes; element_area: the target triangle
// area. Returns the interior nodes only.
std::vector<Vec2> shrink_nodes(const std::vector<Vec2>& polygon, double h, double element_area);

// The convex polygon clipped to the half-plane left of the directed line through p along d.
std::vector<Vec2> clip_left(const std::vector<Vec2>& polygon, const Vec2& p, const Vec2& d);

}  // namespace bisect::mesh2d
