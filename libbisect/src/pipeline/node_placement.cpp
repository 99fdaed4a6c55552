#include "pipeline/node_placement.hpp"

#include <algorithm>
#include <chrono>

#include "nodes/cell_nodes.hpp"
#include "nodes/graded_nodes.hpp"
#include "util/ordered_parallel.hpp"

namespace bisect::pipeline {

nodes::Polytope cell_polytope(const PolyhedralModel& m, const ConvexCell& c) {
  nodes::Polytope p;
  std::vector<int> local(m.nodes.size(), -1);
  for (std::size_t k = 0; k < c.faces.size(); ++k) {
    const ModelFace& f = m.faces[c.faces[k]];
    std::vector<int> loop;
    for (Index v : f.loops[0]) {
      if (local[v] < 0) {
        local[v] = static_cast<int>(p.v.size());
        p.v.push_back(m.nodes[v]);
      }
      loop.push_back(local[v]);
    }
    if (!c.outward[k]) std::reverse(loop.begin(), loop.end());
    p.faces.push_back(std::move(loop));
    p.normal.push_back(c.outward[k] ? f.normal : Vec3(-f.normal));
    p.offset.push_back(c.outward[k] ? f.offset : -f.offset);
  }
  return p;
}

Built place_nodes(const Decomposition& d, double np, const std::vector<double>& cap, int threads, double grading, double* gen_nodes,
                  bool count_only) {
  Built b;
  const auto t0 = std::chrono::steady_clock::now();
  mesh2d::FaceGridOptions fo;
  fo.size = np;
  fo.nodes_only = count_only;
  fo.threads = threads;
  // each cell's spacing: np, or its cap where that is finer; a face takes its cells' finest
  std::vector<double> cell_np(d.cells.size(), np);
  for (std::size_t c = 0; c < d.cells.size() && c < cap.size(); ++c)
    if (cap[c] > 0 && cap[c] < np) {
      cell_np[c] = cap[c];
      fo.face_size.resize(d.model.faces.size(), 0.0);
      for (Index f : d.cells[c].faces) fo.face_size[f] = fo.face_size[f] > 0 ? std::min(fo.face_size[f], cap[c]) : cap[c];
    }
  b.grids = mesh2d::mesh_faces(d.model, fo);
  b.X = b.grids.nodes;
  b.boundary_nodes = b.X.size();
  b.interior.assign(d.cells.size(), {});
  // each cell's nodes on its own, on the threads (a cell's shrinking depends on it alone: the
  // nodes are the same for every thread count)
  b.polys.resize(d.cells.size());
  std::vector<std::vector<Vec3>> uniform(d.cells.size());
  util::ordered_parallel(
      d.cells.size(), util::thread_count(threads),
      [&](std::size_t c) {
        b.polys[c] = cell_polytope(d.model, d.cells[c]);
        uniform[c] = nodes::shrink_cell_nodes(b.polys[c], cell_np[c]);
      },
      [](std::size_t) {});
  // graded from the boundary's fine spacing (short edges); the shrinking's alone elsewhere
  nodes::GradedNodeStats gs;
  const auto placed = nodes::graded_cell_nodes(b.polys, uniform, b.grids.nodes, b.grids.spacing, np, grading, &gs);
  b.graded_nodes = static_cast<std::int64_t>(gs.added);
  for (std::size_t c = 0; c < d.cells.size(); ++c)
    for (const Vec3& p : placed[c]) {
      b.X.push_back(p);
      b.interior[c].push_back(static_cast<Index>(b.X.size() - 1));
    }
  *gen_nodes += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return b;
}

std::vector<char> node_kinds(const PolyhedralModel& m, const Built& b) {
  std::vector<char> kind(b.X.size(), kUnused);
  for (std::size_t v = m.nodes.size(); v < b.X.size(); ++v) kind[v] = kInside;
  for (const ModelFace& f : m.faces) {
    if (!f.alive) continue;
    const char k = f.source >= 0 ? kOnInputFace : kInside;
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index a = loop[i], c = loop[(i + 1) % loop.size()];
        kind[a] = std::max(kind[a], k);
        const auto e = b.grids.edge_nodes.find({std::min(a, c), std::max(a, c)});
        if (e != b.grids.edge_nodes.end())
          for (Index v : e->second) kind[v] = std::max(kind[v], k);
      }
  }
  for (std::size_t v = m.nodes.size(); v < b.boundary_nodes; ++v)
    if (b.grids.face_of[v] >= 0 && m.faces[b.grids.face_of[v]].source >= 0) kind[v] = kOnInputFace;
  return kind;
}

}  // namespace bisect::pipeline
