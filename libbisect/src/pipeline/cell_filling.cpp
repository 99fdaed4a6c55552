#include "pipeline/cell_filling.hpp"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <string>

#include "bisect/errors.hpp"
#include "optimize/sliver_repair.hpp"
#include "pipeline/proxy_fill.hpp"
#include "tet/cell_fill.hpp"
#include "tet/local_nodes.hpp"
#include "tet/recovery_fill.hpp"
#include "util/ordered_parallel.hpp"
#include "util/progress_poll.hpp"

namespace bisect::pipeline {
namespace {

// A star fill with more than this share of its tetrahedra under 10 degrees is tried again by
// Delaunay boundary recovery (see fill_one). A cell of a solid part leaves the star with at
// most 2% there (lug, flange, plate-hole at 1e5), which the global optimisation mends; a thin
// cell leaves 14 to 48% (a 1 mm disc, two bonded 1 mm plates); a small cell of part.stl's needle
// facets 10 to 12%.
constexpr double kRetryShare = 0.10;

// The share of the tetrahedra whose smallest dihedral angle is under 10 degrees.
// (By the cosine of the smallest dihedral angle: tet_quality's every measure, with its arc
// tangents, was 2.6% of lug's run at 3*10^5.)
double share_under_10(const std::vector<Vec3>& X, const std::vector<tet::Tet>& tets) {
  const double cos10 = std::cos(10 * M_PI / 180);
  std::size_t low = 0;
  for (const tet::Tet& t : tets) low += optimize::worst_dihedral_cos(X[t[0]], X[t[1]], X[t[2]], X[t[3]]) > cos10;
  return tets.empty() ? 0.0 : static_cast<double>(low) / static_cast<double>(tets.size());
}

// One cell's filling on its own copy of its nodes (so that cells fill in parallel): local ids
// follow the global ones in order, so the filling is the one the global ids would give.
struct CellFilling {
  std::vector<Index> global;  // local node -> node of X (a node the fill added: -1 until committed)
  std::vector<Vec3> moved;    // in_proxy: the cell's nodes' true positions after the untangling
  std::vector<Vec3> helper;   // nodes the fill added: the star's helper (left out of the mesh when removed
                              // again), or the recovery's Steiner points
  std::vector<tet::Tet> tets;
  tet::CellFillStats stats;
  bool recovered = false;     // a star fill replaced by Delaunay boundary recovery's (better)
};

CellFilling fill_one(const CellJob& job, const std::vector<Vec3>& nodes, const std::vector<Vec3>* proxy, bool delaunay,
                     const std::function<bool()>& cancelled = {}) {
  CellFilling out;
  const tet::LocalNodes own_ids(job.boundary, job.interior);
  out.global = own_ids.global;
  std::vector<Vec3> X = own_ids.points(nodes);
  const std::vector<std::array<Index, 3>> boundary = own_ids.triangles(job.boundary);
  const std::vector<Index> interior = own_ids.nodes(job.interior);
  try {
    if (job.recover) {
      // Steiner points where a hole needs them: they join the cell's nodes as helpers do
      std::vector<Vec3> steiner;
      out.tets = tet::fill_by_recovery(X, boundary, interior, &out.stats, job.steiner ? &steiner : nullptr);
      X.insert(X.end(), steiner.begin(), steiner.end());
    } else if (job.in_proxy) {
      std::vector<Vec3> P = own_ids.points(*proxy);
      out.tets = fill_in_proxy(X, P, boundary, interior, job.centre_p, delaunay, &out.stats, job.keep_inverted);
      out.moved.assign(X.begin(), X.begin() + static_cast<std::ptrdiff_t>(out.global.size()));
    } else {
      const std::size_t own = X.size();
      out.tets = tet::fill_convex_cell(X, boundary, interior, job.centre, delaunay, &out.stats, cancelled);
      // The star and the local transformations from it can stay far from what the nodes allow:
      // a thin cell (a plate whose thickness is about the spacing, its two faces' grids not in
      // line) keeps a third of its tetrahedra under 10 degrees, which no later pass repairs.
      // Delaunay boundary recovery starts from the nodes' own Delaunay tetrahedralization and
      // gets there (a 1 mm disc at spacing 1: 17% of the tetrahedra under 10 degrees -> 0.02%).
      const double star_share = share_under_10(X, out.tets);
      if (star_share > kRetryShare) {
        const std::vector<Vec3> own_nodes(X.begin(), X.begin() + static_cast<std::ptrdiff_t>(own));
        try {
          tet::CellFillStats rs;
          std::vector<tet::Tet> recovered = tet::fill_by_recovery(own_nodes, boundary, interior, &rs);
          // kept only when it has at most half the star's share under 10 degrees: a small cell
          // of needle facets (part.stl) went from 10% to 9.5% there, and the global
          // optimisation then left a worse sliver than from the star
          if (share_under_10(own_nodes, recovered) <= 0.5 * star_share) {
            out.tets = std::move(recovered);
            X.resize(own);  // the star's helper, if it kept one, is not in this fill
            rs.flips += out.stats.flips;
            out.stats = rs;
            out.recovered = true;
          }
        } catch (const MeshingError&) {
          // the star's fill stands: the recovery cannot restore every boundary triangle here
        }
      }
    }
  } catch (const MeshingError& e) {
    throw MeshingError(job.name + ": " + e.what());
  }
  for (std::size_t i = out.global.size(); i < X.size(); ++i) out.helper.push_back(X[i]);  // the helper (7.6), Steiner points
  out.global.resize(X.size(), -1);
  return out;
}

}  // namespace

bool fill_job_works(const CellJob& job, const std::vector<Vec3>& X, const std::vector<Vec3>* P, bool delaunay) {
  try {
    fill_one(job, X, P, delaunay);
    return true;
  } catch (const MeshingError&) {
    return false;
  }
}

FilledCells fill_cell_jobs(std::vector<Vec3>& X, const std::vector<CellJob>& jobs, bool delaunay, int threads,
                           const std::function<bool(double)>& progress, const std::vector<Vec3>* P) {
  FilledCells out;
  const std::size_t n = jobs.size();
  std::vector<CellFilling> made(n);
  std::vector<std::size_t> largest_first(n);  // the long jobs first: no thread waits on one at the end
  for (std::size_t c = 0; c < n; ++c) largest_first[c] = c;
  std::stable_sort(largest_first.begin(), largest_first.end(),
                   [&](std::size_t x, std::size_t y) { return jobs[x].interior.size() > jobs[y].interior.size(); });
  const std::vector<Vec3> nodes = X;  // the cells read these while helpers join X
  // Stop within a cell: the fills poll it (a 2e5 mesh of 13 cells went a second without a call)
  util::ParallelPoll poll(progress);
  const std::function<bool()> cancelled = poll.hook();
  util::ordered_parallel(
      n, util::thread_count(threads), [&](std::size_t c) { made[c] = fill_one(jobs[c], nodes, P, delaunay, cancelled); },
      [&](std::size_t c) {
        poll.at(static_cast<double>(c) / static_cast<double>(n));
        CellFilling& f = made[c];
        // an untangled cell's interior nodes moved (its boundary nodes, shared, did not)
        for (std::size_t i = 0; i < f.moved.size(); ++i) X[f.global[i]] = f.moved[i];
        const std::size_t own = f.global.size() - f.helper.size();
        for (std::size_t i = 0; i < f.helper.size(); ++i) {
          X.push_back(f.helper[i]);
          f.global[own + i] = static_cast<Index>(X.size() - 1);
        }
        out.steiner_nodes += f.stats.steiner;
        out.helper_nodes += f.stats.helper;
        out.helpers_removed += f.stats.helper_removed;
        out.skipped_nodes += f.stats.skipped;
        out.flips += f.stats.flips;
        out.refilled += f.recovered ? 1 : 0;
        for (tet::Tet t : f.tets) {
          for (Index& v : t) v = f.global[v];
          out.tets.push_back(t);
        }
        out.region.resize(out.tets.size(), jobs[c].region);
        f = {};
        if (progress && !progress(static_cast<double>(c + 1) / static_cast<double>(n))) throw Cancelled();
      },
      largest_first, [&poll] { poll.idle(); });
  if (poll.cancelled()) throw Cancelled();
  return out;
}

void fill_cells(const Decomposition& d, Built& b, bool delaunay, int threads, const std::function<bool(double)>& progress,
                double* gen_tets) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<CellJob> jobs(d.cells.size());
  for (std::size_t c = 0; c < d.cells.size(); ++c) {
    const ConvexCell& cell = d.cells[c];
    CellJob& job = jobs[c];
    for (std::size_t k = 0; k < cell.faces.size(); ++k)
      for (const auto& t : b.grids.face_tris[cell.faces[k]]) job.boundary.push_back(cell.outward[k] ? t : std::array<Index, 3>{t[0], t[2], t[1]});
    job.interior = b.interior[c];
    job.centre = b.polys[c].centroid();
    job.region = cell.source_region;
    job.name = "convex cell " + std::to_string(c + 1) + " of input region " + std::to_string(cell.source_region + 1);
  }
  FilledCells f = fill_cell_jobs(b.X, jobs, delaunay, threads, progress);
  b.tets = std::move(f.tets);
  b.region = std::move(f.region);
  b.helper_nodes += f.helper_nodes, b.helpers_removed += f.helpers_removed, b.skipped_nodes += f.skipped_nodes, b.flips += f.flips;
  b.refilled_cells += f.refilled;
  *gen_tets += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace bisect::pipeline
