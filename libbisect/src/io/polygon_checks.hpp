// The check that a 2D input's polygon is simple: no two of its edges cross or touch, except
// neighbours at their shared node, and no edge turns straight back along the one before it. The
// planar mesher's pieces assume simple loops: a self-crossing polygon made clockwise triangles
// deep inside the recursive bisection, which the user could not trace back to the input.
#pragma once
#include <string>
#include <vector>

#include "bisect/types.hpp"

namespace bisect::io {

// Throws InputError "WHERE: polygon N crosses itself (its edges from node a to b and from node c
// to d), at (x, y)", or "... touches itself ...", nodes by the file's 1-based numbers. Edges are
// paired through a uniform grid, so a coastline of 10^5 nodes takes milliseconds.
void check_simple_polygon(const std::vector<Vec2>& nodes, const std::vector<Index>& polygon, Index number,
                          const std::string& where);

}  // namespace bisect::io
