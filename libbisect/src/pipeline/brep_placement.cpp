#include "pipeline/brep_placement.hpp"

#include <algorithm>

#include "nodes/sized_nodes.hpp"
#include "pipeline/brep_cells.hpp"
#include "pipeline/brep_morph.hpp"
#include "pipeline/node_placement.hpp"
#include "util/ordered_parallel.hpp"

namespace bisect::pipeline {
namespace {

// A cell's interior nodes: where they are in the proxy's geometry (at the size field's sizes),
// and where the morph takes them.
struct CellNodes {
  nodes::Polytope poly;
  std::vector<Vec3> proxy, moved;
  std::size_t fine = 0;  // placed finer than the cell's own spacing (graded)
};

// Every cell's, each on its own on the threads (a cell's nodes depend on it alone: the same for
// every thread count).
std::vector<CellNodes> interior_nodes(const Decomposition& d, const size::SizeField& h, const Morph& morph, int threads) {
  std::vector<CellNodes> out(d.cells.size());
  util::ordered_parallel(
      d.cells.size(), util::thread_count(threads),
      [&](std::size_t c) {
        CellNodes& n = out[c];
        n.poly = cell_polytope(d.model, d.cells[c]);
        n.proxy = nodes::sized_cell_nodes(n.poly, h, &n.fine);
        for (const Vec3& p : n.proxy) n.moved.push_back(p + morph.displacement(p));
      },
      [](std::size_t) {});
  return out;
}

}  // namespace

std::int64_t BrepPlacement::boundary_nodes() const {
  return std::count(on_boundary.begin(), on_boundary.end(), 1);
}

std::int64_t BrepPlacement::inside_nodes() const { return static_cast<std::int64_t>(on_boundary.size()) - boundary_nodes(); }

BrepPlacement place_brep_nodes(const BrepInput& in, const BrepProxy& proxy, const Decomposition& d, const size::SizeField& h,
                               int threads, const std::function<bool(double)>& progress) {
  BrepBoundary bd(in, proxy, d.model);
  BrepPlacement f;
  f.grids = mesh_brep_faces(bd, d, h, threads, progress);
  const Morph morph(f.grids.nodes, h);
  const auto& gn = f.grids.nodes;
  f.X = gn.x;
  f.P = gn.p;
  f.on_boundary.assign(gn.x.size(), 0);
  for (std::size_t v = 0; v < gn.x.size(); ++v) {
    if (gn.on[v].kind == PointOn::kInterior) f.X[v] = gn.p[v] + morph.displacement(gn.p[v]);
    else f.on_boundary[v] = 1;
  }
  const std::vector<CellNodes> placed = interior_nodes(d, h, morph, threads);
  std::vector<BrepCell>& cells = f.cells;
  cells.resize(d.cells.size());
  for (std::size_t c = 0; c < d.cells.size(); ++c) {
    const CellNodes& n = placed[c];
    f.graded_nodes += static_cast<std::int64_t>(n.fine);
    for (std::size_t i = 0; i < n.proxy.size(); ++i) {
      f.X.push_back(n.moved[i]);
      f.P.push_back(n.proxy[i]);
      f.on_boundary.push_back(0);
      cells[c].interior.push_back(static_cast<Index>(f.X.size() - 1));
    }
    const Vec3 centre = n.poly.centroid();
    cells[c].centre = centre + morph.displacement(centre);
    cells[c].centre_p = centre;
    cells[c].volume = n.poly.volume();
  }
  return f;
}

}  // namespace bisect::pipeline
