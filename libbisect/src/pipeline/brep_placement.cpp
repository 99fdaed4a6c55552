#include "pipeline/brep_placement.hpp"

#include <algorithm>

#include "nodes/sized_nodes.hpp"
#include "pipeline/brep_cells.hpp"
#include "pipeline/brep_morph.hpp"
#include "pipeline/node_placement.hpp"

namespace bisect::pipeline {
namespace {

// The cells' interior nodes in the proxy's geometry, at the size field's sizes.
std::vector<std::vector<Vec3>> interior_nodes(const Decomposition& d, const size::SizeField& h, std::vector<nodes::Polytope>* polys,
                                              std::int64_t* graded) {
  std::vector<std::vector<Vec3>> placed;
  for (const ConvexCell& c : d.cells) {
    polys->push_back(cell_polytope(d.model, c));
    std::size_t fine = 0;
    placed.push_back(nodes::sized_cell_nodes(polys->back(), h, &fine));
    *graded += static_cast<std::int64_t>(fine);
  }
  return placed;
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
  std::vector<nodes::Polytope> polys;
  const auto placed = interior_nodes(d, h, &polys, &f.graded_nodes);
  std::vector<BrepCell>& cells = f.cells;
  cells.resize(d.cells.size());
  for (std::size_t c = 0; c < d.cells.size(); ++c) {
    for (const Vec3& p : placed[c]) {
      f.X.push_back(p + morph.displacement(p));
      f.P.push_back(p);
      f.on_boundary.push_back(0);
      cells[c].interior.push_back(static_cast<Index>(f.X.size() - 1));
    }
    const Vec3 centre = polys[c].centroid();
    cells[c].centre = centre + morph.displacement(centre);
    cells[c].centre_p = centre;
    cells[c].volume = polys[c].volume();
  }
  return f;
}

}  // namespace bisect::pipeline
