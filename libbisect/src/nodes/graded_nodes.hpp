// Interior nodes graded from fine boundary spacing. The face grids follow short edges (a node
// wants no more than its shortest edge, 4.5.2), but 3D shrinking (7.4) fills every cell at the
// one spacing Np, so a short boundary edge faces interior nodes Np away: the tetrahedra on it
// are needles with small dihedral angles. Here every boundary node whose spacing s is finer
// than Np becomes the source of a size field
//
//     h(x) = min(Np, min over sources b of s_b + g |x - b|)       (g: the grading)
//
// and gets shells of nodes around it at that size; then the shells' and the shrinking's nodes
// are thinned in order of their size (finest first), a node kept when no kept node nor boundary
// source lies within 0.7 h(x) and the cell's faces are at least h(x) / 2 away. Away from fine
// boundary spacing, h = Np and the shrinking's nodes stay as they were.
#pragma once
#include <vector>

#include "bisect/types.hpp"
#include "nodes/cell_nodes.hpp"

namespace bisect::nodes {

struct GradedNodeStats {
  std::size_t sources = 0;  // boundary nodes finer than Np
  std::size_t added = 0;    // graded nodes kept
  std::size_t dropped = 0;  // shrinking nodes thinned out near them
};

// cells: the convex cells; uniform[c]: cell c's nodes at spacing np (shrink_cell_nodes);
// boundary / spacing: the face-grid nodes and the spacing each wants. grading <= 0 returns
// `uniform` unchanged. Deterministic: the same input gives the same nodes in the same order.
std::vector<std::vector<Vec3>> graded_cell_nodes(const std::vector<Polytope>& cells, const std::vector<std::vector<Vec3>>& uniform,
                                                 const std::vector<Vec3>& boundary, const std::vector<double>& spacing, double np,
                                                 double grading, GradedNodeStats* stats = nullptr);

}  // namespace bisect::nodes
