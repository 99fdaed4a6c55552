// Whether a cell's boundary crosses itself: an edge of one of its triangles passing through
// another triangle that shares no node with it. No tetrahedra can fill such a boundary, by any
// method, with or without points added inside: the B-rep route tells the user so, and where,
// when every fill has failed (a thin cell whose grids on two curved faces, moved from the proxy
// onto the true surfaces, pass through each other).
#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "bisect/types.hpp"

namespace bisect::tet {

struct BoundaryCrossing {
  std::size_t edge_triangle = 0;  // a triangle the crossing edge belongs to
  std::size_t crossed = 0;        // the triangle it passes through
  Vec3 at = Vec3::Zero();         // where (the edge's point in the crossed triangle's plane)
};

// The first crossing found (exact predicates; an edge through the crossed triangle's interior or
// across one of its edges; one that only touches it does not count), or none. Triangles are found
// through a uniform grid of boxes, so a cell of n triangles costs about O(n).
std::optional<BoundaryCrossing> boundary_crossing(const std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary);

}  // namespace bisect::tet
