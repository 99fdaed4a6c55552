// Interior nodes of a convex cell at the sizes of a size field (the B-rep route): 3D shrinking
// (7.4) at the base spacing where the field is at its base, and where it asks for less (near a
// small hole, a fillet, a short edge, a mesh region) an octree of the cell's box cut until each
// leaf is no larger than the size at its centre, one jittered node per fine leaf. Nodes keep half
// a size from the cell's faces and 0.6 of a size from each other.
#pragma once
#include <vector>

#include "nodes/polytope.hpp"
#include "size/size_field.hpp"

namespace bisect::nodes {

// *graded: how many of the nodes came from the octree (finer than the base).
std::vector<Vec3> sized_cell_nodes(const Polytope& cell, const size::SizeField& h, std::size_t* graded = nullptr);

}  // namespace bisect::nodes
