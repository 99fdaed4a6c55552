// Stage "Gen. Tets": each convex cell filled by the boundary-constrained local min-max
// triangulation (thesis 7.6) from its face grids and interior nodes, on several threads; the
// tetrahedra join the mesh in cell order whatever the thread count.
#pragma once
#include <functional>

#include "bisect/polyhedral_model.hpp"
#include "pipeline/node_placement.hpp"

namespace bisect::pipeline {

// Fills every cell of d with b's nodes into b.tets and b.region (a helper node a cell keeps
// joins b.X). progress(fraction of cells done) is called on this thread, in cell order; false
// cancels. Adds its time to *gen_tets.
void fill_cells(const Decomposition& d, Built& b, bool delaunay, int threads, const std::function<bool(double)>& progress,
                double* gen_tets);

}  // namespace bisect::pipeline
