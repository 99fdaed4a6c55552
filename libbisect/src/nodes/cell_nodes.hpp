// Interior nodes of a convex cell by 3D convex domain shrinking (thesis 7.4): layer k is the cell
// with every face plane moved inwards by k Np, i.e. the intersection of the moved half-spaces;
// its edges sharper than 30 degrees are cut off by a plane Np / (2 tan(phi / 2)) in from the
// edge; nodes go on each of its faces by the 2D placement (edges at spacing Np, face interiors
// by 2D shrinking), nodes closer than Np / 2 merged (short edges, narrowness); repeated until
// the layer is empty. A layer thinner than Np / 2 gets one sheet of nodes through its middle and
// ends the shrinking; so does the layer half a spacing deeper than the last one, when it exists
// (the gap left is wider than Np). A sheet narrower than Np / 2 becomes a line of nodes through
// its middle, a small one a node at its centre. Every node is then moved by a small deterministic jitter (see
// kNodeJitter) that breaks the co-spherical ties of the layers' regular grids.
#pragma once
#include <vector>

#include "bisect/types.hpp"
#include "nodes/polytope.hpp"

namespace bisect::nodes {

// The jitter's width, as a fraction of Np: each coordinate moves by up to half of it either way.
inline constexpr double kNodeJitter = 0.1;

// The interior nodes of the convex cell `cell` at spacing np.
std::vector<Vec3> shrink_cell_nodes(const Polytope& cell, double np);

}  // namespace bisect::nodes
