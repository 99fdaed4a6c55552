// Nodal spacing (thesis 4.6.2) and the discretisation of boundary edges (4.5.2, 4.6.5).
//
// The spacing is the side of the equilateral triangle whose area is the domain's area over the
// required number of elements: h = sqrt(4 A_e / sqrt(3)). Each input vertex carries its own
// spacing, no larger than h nor than its shortest edge, so fine boundary segments grade the grid;
// along an edge the spacing grows away from each end at a bounded rate up to h, and nodes are put
// at equal steps of the integral of 1 / spacing. Every edge is discretised once, so regions sharing it conform.
#pragma once
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "mesh2d/prep_regions.hpp"

namespace bisect::mesh2d {

double element_spacing(double area, std::int64_t elements);

// How fast the spacing may grow away from a fine node: per unit length, so neighbouring
// segments differ by about this fraction. A linear blend between the ends would keep a long
// edge between two short ones fine all along (thousands of nodes on a long STL edge).
inline constexpr double kSpacingGrowth = 0.3;

// The spacing wanted at distance x along an edge of length len whose ends want sa and sb (both
// at most h): min(h, sa + growth x, sb + growth (len - x)).
double edge_spacing_at(double x, double len, double sa, double sb, double h);

// The inner nodes of that edge, as fractions of the way from the sa end: equal steps of the
// integral of 1 / spacing. Empty when one step covers the edge.
std::vector<double> graded_edge_fractions(double len, double sa, double sb, double h);

struct BoundaryGrid {
  std::vector<Vec2> nodes;                           // input nodes first, then edge nodes
  std::vector<double> spacing;                       // per node
  std::vector<std::vector<std::vector<Index>>> loops;  // per region, its loops with edge nodes
};

BoundaryGrid discretise_boundaries(const PlanarDomain& d, double h);

}  // namespace bisect::mesh2d
