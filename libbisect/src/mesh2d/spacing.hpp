// Nodal spacing (thesis 4.6.2) and the discretisation of boundary edges (4.5.2, 4.6.5).
//
// The spacing is the side of the equilateral triangle whose area is the domain's area over the
// required number of elements: h = sqrt(4 A_e / sqrt(3)). Each input vertex carries its own
// spacing, no larger than h nor than its shortest edge, so fine boundary segments grade the grid;
// along an edge the spacing grows away from each end at a bounded rate up to h, and nodes are put
// at equal steps of the integral of 1 / spacing. Every edge is discretised once, so regions sharing it conform.
#pragma once
#include <algorithm>
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

// The spacing an edge made by the decomposition's cuts (on a cut face, or across an input face)
// asks of its two nodes: its length, but no less than a third of its face's spacing h_face unless
// that is more than three times its length. A cut's length is an accident of where the planes
// fell (4.6.3: new nodes should not lie too close to others): where cuts cross near each other or
// near an input vertex (round the 64-gon holes of lug.stl, cut edges 0.03 long at a spacing of
// 0.4) the grids graded from that length, put the nodes of interior edges 0.02 from the faces and
// held the coarsest counts up (lug.stl 1,353 tetrahedra, Angled.stl 31,665, flange.stl 15,547).
// The nodes of a short edge keep it in their face's grid, so a spacing far above its length makes
// needles round it (part.stl at 10^5: an edge 0.047 long across a wall at h = 2.8, 3 degrees):
// at three times the length, the triangle standing on it has an apex of about 19 degrees (the
// grids' optimisation then works from there). A half of h_face instead of a third
// lowered the mean alpha of Angled.stl's and flange.stl's coarsest meshes.
inline constexpr double kCutEdgeSpacingRel = 1.0 / 3.0;
inline constexpr double kCutEdgeSpacingMul = 3.0;
inline double cut_edge_spacing(double len, double h_face) {
  return std::max(len, std::min(kCutEdgeSpacingMul * len, kCutEdgeSpacingRel * h_face));
}

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
