#include "mesh2d/fill_region.hpp"

#include <chrono>

#include "mesh2d/bisect2d.hpp"
#include "mesh2d/convex_decompose.hpp"
#include "mesh2d/loop_geometry.hpp"
#include "mesh2d/shrink_nodes.hpp"
#include "mesh2d/smooth.hpp"
#include "mesh2d/swap.hpp"

namespace bisect::mesh2d {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

std::int64_t fill_region(TriMesh2& m, const std::vector<std::vector<Index>>& loops, double h, double element_area, Index region,
                         FillTimes* times, bool triangulate) {
  FillTimes local;
  FillTimes& t = times ? *times : local;
  const auto t0 = Clock::now();
  const std::vector<std::vector<Index>> pieces = convex_pieces(m.nodes, loops, h);
  std::vector<std::vector<Index>> inside(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    std::vector<Vec2> poly;
    for (Index v : pieces[k]) poly.push_back(m.nodes[v]);
    // a piece left non-convex (see convex_pieces): the clipping can leave a seam outside it
    bool convex = true;
    for (std::size_t i = 0; i < poly.size() && convex; ++i)
      convex = geom::orient2d(poly[(i + poly.size() - 1) % poly.size()], poly[i], poly[(i + 1) % poly.size()]) >= 0;
    for (const Vec2& p : shrink_nodes(poly, h, element_area)) {
      if (!convex && !inside_loop(m.nodes, pieces[k], p)) continue;
      m.nodes.push_back(p);
      inside[k].push_back(static_cast<Index>(m.nodes.size() - 1));
    }
  }
  t.nodes += since(t0);
  if (!triangulate) return static_cast<std::int64_t>(pieces.size());
  const auto t1 = Clock::now();
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    bisection_triangulate(m.nodes, pieces[k], inside[k], m.tris);
    m.tri_region.resize(m.tris.size(), region);
  }
  t.triangulate += since(t1);
  return static_cast<std::int64_t>(pieces.size());
}

void optimize_planar(TriMesh2& m) {
  for (int round = 0; round < 3; ++round) {
    swap_edges(m);
    smooth_laplace(m, {3});
  }
  swap_edges(m);
}

}  // namespace bisect::mesh2d
