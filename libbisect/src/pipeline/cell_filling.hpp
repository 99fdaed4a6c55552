// Stage "Gen. Tets": each cell filled by the boundary-constrained local min-max triangulation
// (thesis 7.6) from its boundary triangles and interior nodes, on several threads; the
// tetrahedra join the mesh in cell order whatever the thread count. The polyhedral route's cells
// are convex; the B-rep route's are star-shaped about their centre (convex cells whose faces were
// moved onto the true surfaces).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bisect/polyhedral_model.hpp"
#include "pipeline/node_placement.hpp"

namespace bisect::pipeline {

struct CellJob {
  std::vector<std::array<Index, 3>> boundary;  // node ids, counter-clockwise seen from outside
  std::vector<Index> interior;                 // node ids strictly inside
  Vec3 centre = Vec3::Zero();                  // a point the whole boundary is seen from
  Index region = 0;                            // the tetrahedra's region
  std::string name;                            // for messages ("convex cell 3 of input region 1")
  // The B-rep route: fill in the proxy's geometry (proxy_fill.hpp) at the nodes' proxy positions
  // (fill_cell_jobs' P), the cell being convex there, when no point sees it whole as it is.
  bool in_proxy = false;
  bool keep_inverted = false;  // in_proxy: the last resort, inverted tetrahedra kept (proxy_fill.hpp)
  // The B-rep route: filled by Delaunay boundary recovery (tet/recovery_fill.hpp), when neither
  // the star nor the proxy's geometry fills it
  bool recover = false;
  // recover: with the recovery's second phase (flips and Steiner points, face_recovery.hpp), the
  // fill after the last resort; without, a cell the fans alone recover is filled as before
  bool steiner = false;
  Vec3 centre_p = Vec3::Zero();  // the proxy cell's centroid
};

struct FilledCells {
  std::vector<tet::Tet> tets;
  std::vector<Index> region;
  std::int64_t helper_nodes = 0, helpers_removed = 0, skipped_nodes = 0, flips = 0;
  std::int64_t refilled = 0;  // star fills replaced by Delaunay boundary recovery's, a better one
  std::int64_t steiner_nodes = 0;  // Steiner points the fills by boundary recovery added
};

// Fills every job; a helper node a cell keeps, and a recovery's Steiner points, join X.
// progress(fraction of cells done) is called on this thread, in cell order; false cancels.
// P: the nodes' proxy positions, for the jobs filled in_proxy (may be null otherwise). X may move
// (the untangling of a cell filled in the proxy's geometry moves its interior nodes).
FilledCells fill_cell_jobs(std::vector<Vec3>& X, const std::vector<CellJob>& jobs, bool delaunay, int threads,
                           const std::function<bool(double)>& progress, const std::vector<Vec3>* P = nullptr);

// Whether the job fills (a trial: the tetrahedra are dropped), as fill_cell_jobs would fill it.
bool fill_job_works(const CellJob& job, const std::vector<Vec3>& X, const std::vector<Vec3>* P, bool delaunay);

// The polyhedral route: every convex cell of d with b's nodes into b.tets and b.region. Adds its
// time to *gen_tets.
void fill_cells(const Decomposition& d, Built& b, bool delaunay, int threads, const std::function<bool(double)>& progress,
                double* gen_tets);

}  // namespace bisect::pipeline
