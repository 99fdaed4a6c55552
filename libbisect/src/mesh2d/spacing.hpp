// Nodal spacing (thesis 4.6.2) and the discretisation of boundary edges (4.5.2, 4.6.5).
//
// The spacing is the side of the equilateral triangle whose area is the domain's area over the
// required number of elements: h = sqrt(4 A_e / sqrt(3)). Each input vertex carries its own
// spacing, no larger than h nor than its shortest edge, so fine boundary segments grade the grid;
// along an edge the spacing runs linearly between its ends, and nodes are put at equal steps of
// the integral of 1 / spacing. Every edge is discretised once, so regions sharing it conform.
#pragma once
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "mesh2d/prep_regions.hpp"

namespace bisect::mesh2d {

double element_spacing(double area, std::int64_t elements);

struct BoundaryGrid {
  std::vector<Vec2> nodes;                           // input nodes first, then edge nodes
  std::vector<double> spacing;                       // per node
  std::vector<std::vector<std::vector<Index>>> loops;  // per region, its loops with edge nodes
};

BoundaryGrid discretise_boundaries(const PlanarDomain& d, double h);

}  // namespace bisect::mesh2d
