// The steps of the planar mesher that fill one region whose boundary is already discretised:
// convex pieces (4.6.3, 4.6.4), nodes by shrinking each piece (4.6.5), each piece triangulated by
// recursive bisection (4.3); and the optimisation that follows (4.4). Shared by the .poly2
// mesher and the face grids of polyhedral models (5.2), which differ only in where the boundary
// nodes come from.
#pragma once
#include <cstdint>
#include <vector>

#include "mesh2d/tri_mesh2.hpp"

namespace bisect::mesh2d {

// loops: node ids in m.nodes, loops[0] counter-clockwise, holes clockwise, every boundary node
// already there. Appends separator and interior nodes and the region's triangles (tri_region =
// region) to m; returns the number of convex pieces. The caller marks the fixed nodes. `times`,
// when given, accumulates the seconds spent placing nodes and triangulating.
struct FillTimes {
  double nodes = 0, triangulate = 0;
};
// With `triangulate` false only the nodes are placed (what a count of nodes needs).
std::int64_t fill_region(TriMesh2& m, const std::vector<std::vector<Index>>& loops, double h, double element_area, Index region,
                         FillTimes* times = nullptr, bool triangulate = true);

// Vertex swapping and Laplace smoothing in turn (4.4), each opening moves for the other; fixed
// nodes stay where they are.
void optimize_planar(TriMesh2& m);

}  // namespace bisect::mesh2d
