#include "pipeline/cell_filling.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include "bisect/errors.hpp"
#include "tet/cell_fill.hpp"
#include "util/ordered_parallel.hpp"

namespace bisect::pipeline {
namespace {

// One cell's filling on its own copy of its nodes (so that cells fill in parallel): local ids
// follow the global ones in order, so the filling is the one the global ids would give.
struct CellFilling {
  std::vector<Index> global;  // local node -> node of b.X (a helper: -1 until committed)
  std::vector<Vec3> helper;   // the helper node, when one was added (left out of the mesh when removed again)
  std::vector<tet::Tet> tets;
  tet::CellFillStats stats;
};

CellFilling fill_cell(const Decomposition& d, const Built& b, const std::vector<Vec3>& nodes, std::size_t c, bool delaunay) {
  const ConvexCell& cell = d.cells[c];
  CellFilling out;
  std::vector<std::array<Index, 3>> boundary;
  for (std::size_t k = 0; k < cell.faces.size(); ++k)
    for (const auto& t : b.grids.face_tris[cell.faces[k]]) {
      boundary.push_back(cell.outward[k] ? t : std::array<Index, 3>{t[0], t[2], t[1]});
      out.global.insert(out.global.end(), t.begin(), t.end());
    }
  out.global.insert(out.global.end(), b.interior[c].begin(), b.interior[c].end());
  std::sort(out.global.begin(), out.global.end());
  out.global.erase(std::unique(out.global.begin(), out.global.end()), out.global.end());
  auto local = [&](Index v) { return static_cast<Index>(std::lower_bound(out.global.begin(), out.global.end(), v) - out.global.begin()); };
  std::vector<Vec3> X;
  X.reserve(out.global.size() + 1);
  for (Index v : out.global) X.push_back(nodes[v]);
  for (auto& t : boundary)
    for (Index& v : t) v = local(v);
  std::vector<Index> interior;
  for (Index v : b.interior[c]) interior.push_back(local(v));
  try {
    out.tets = tet::fill_convex_cell(X, boundary, interior, b.polys[c].centroid(), delaunay, &out.stats);
  } catch (const MeshingError& e) {
    throw MeshingError("convex cell " + std::to_string(c + 1) + " of input region " + std::to_string(cell.source_region + 1) + ": " + e.what());
  }
  if (X.size() > out.global.size()) {  // the helper (7.6)
    out.helper.push_back(X.back());
    out.global.push_back(-1);
  }
  return out;
}

}  // namespace

void fill_cells(const Decomposition& d, Built& b, bool delaunay, int threads, const std::function<bool(double)>& progress,
                double* gen_tets) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = d.cells.size();
  std::vector<CellFilling> made(n);
  std::vector<std::size_t> largest_first(n);  // the long jobs first: no thread waits on one at the end
  for (std::size_t c = 0; c < n; ++c) largest_first[c] = c;
  std::stable_sort(largest_first.begin(), largest_first.end(), [&](std::size_t x, std::size_t y) { return b.interior[x].size() > b.interior[y].size(); });
  const std::vector<Vec3> nodes = b.X;  // the cells read these while helpers join b.X
  util::ordered_parallel(
      n, util::thread_count(threads), [&](std::size_t c) { made[c] = fill_cell(d, b, nodes, c, delaunay); },
      [&](std::size_t c) {
        CellFilling& f = made[c];
        if (!f.helper.empty()) {
          b.X.push_back(f.helper.front());
          f.global.back() = static_cast<Index>(b.X.size() - 1);
        }
        b.helper_nodes += f.stats.helper;
        b.helpers_removed += f.stats.helper_removed;
        b.skipped_nodes += f.stats.skipped;
        b.flips += f.stats.flips;
        for (tet::Tet t : f.tets) {
          for (Index& v : t) v = f.global[v];
          b.tets.push_back(t);
        }
        b.region.resize(b.tets.size(), d.cells[c].source_region);
        f = {};
        if (progress && !progress(static_cast<double>(c + 1) / static_cast<double>(n))) throw Cancelled();
      },
      largest_first);
  *gen_tets += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace bisect::pipeline
