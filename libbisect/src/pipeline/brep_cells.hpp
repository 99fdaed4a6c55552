// The B-rep route's cells as the cell fill takes them. A convex cell of the proxy whose faces
// moved onto the true surfaces is star-shaped when it is wide against the surfaces' bulge, and is
// filled as it is; a narrow one beside a concave face (a sliver between two cuts next to a hole)
// may not be: it is filled in the proxy's geometry, where it is convex (proxy_fill.hpp), when
// the tetrahedra made there can be untangled on the true geometry; otherwise it is joined with
// its neighbours across cut faces (a few at most) until a point sees the group whole. Failing
// that, the cell alone by Delaunay boundary recovery (tet/recovery_fill.hpp), which needs no
// point that sees it whole; failing that too, the last resort: the cell alone in
// the proxy's geometry, the tetrahedra its untangling leaves inverted kept for the global
// optimisation's flips and fold refill to mend (the finished mesh is checked).
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "bisect/polyhedral_model.hpp"
#include "pipeline/brep_grids.hpp"
#include "pipeline/cell_filling.hpp"

namespace bisect::pipeline {

struct BrepCell {
  std::vector<Index> interior;  // node ids inside it
  Vec3 centre = Vec3::Zero();   // its centroid, moved onto the true geometry
  Vec3 centre_p = Vec3::Zero(); // its centroid in the proxy
  double volume = 0;            // of the proxy cell
};

struct BrepCellCounts {
  std::int64_t in_proxy = 0;  // cells filled in the proxy's geometry
  std::int64_t joined = 0;    // cells joined with a neighbour
  std::int64_t recovered = 0; // cells filled by Delaunay boundary recovery (tet/recovery_fill.hpp)
};

// One job per cell or group of joined cells. X, P: the nodes' true and proxy positions. Throws
// MeshingError naming the cell when none of the four ways works. cancelled(fraction of the
// cells done) is asked before each cell; true stops with Cancelled.
std::vector<CellJob> brep_cell_jobs(const BrepInput& in, const Decomposition& d, const BrepGrids& g, const std::vector<Vec3>& X,
                                    const std::vector<Vec3>& P, const std::vector<BrepCell>& cells, bool delaunay,
                                    BrepCellCounts* counts,
                                    const std::function<bool(double)>& cancelled = {});

}  // namespace bisect::pipeline
