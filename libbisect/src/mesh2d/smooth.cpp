#include "mesh2d/smooth.hpp"

#include <algorithm>
#include <map>

#include "geom/predicates.hpp"
#include "mesh2d/tri_quality.hpp"

namespace bisect::mesh2d {

SmoothStats smooth_laplace(TriMesh2& m, const SmoothOptions& opt) {
  SmoothStats st;
  const std::size_t n = m.nodes.size();
  std::vector<char> pinned(n, 0);
  for (std::size_t v = 0; v < n && v < m.fixed.size(); ++v) pinned[v] = m.fixed[v];
  // an edge with one triangle, or triangles of two regions, is boundary or interface
  std::map<std::pair<Index, Index>, std::pair<int, Index>> edges;  // count, region
  for (std::size_t t = 0; t < m.tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index a = m.tris[t][k], b = m.tris[t][(k + 1) % 3];
      auto& e = edges[{std::min(a, b), std::max(a, b)}];
      if (e.first == 0) e.second = m.tri_region[t];
      else if (e.second != m.tri_region[t]) e.first = 99;
      ++e.first;
    }
  for (const auto& [e, c] : edges)
    if (c.first != 2) pinned[e.first] = pinned[e.second] = 1;
  for (const auto& q : m.quads)
    for (Index v : q) pinned[v] = 1;  // quads keep their nodes: smoothing is for triangles
  std::vector<std::vector<Index>> nbr(n), around(n);
  for (std::size_t t = 0; t < m.tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index a = m.tris[t][k];
      around[a].push_back(static_cast<Index>(t));
      for (int j = 1; j < 3; ++j) {
        const Index b = m.tris[t][(k + j) % 3];
        if (std::find(nbr[a].begin(), nbr[a].end(), b) == nbr[a].end()) nbr[a].push_back(b);
      }
    }
  auto local = [&](Index v, bool* valid) {
    double worst = 180;
    *valid = true;
    for (Index t : around[v]) {
      const auto& T = m.tris[t];
      if (geom::orient2d(m.nodes[T[0]], m.nodes[T[1]], m.nodes[T[2]]) <= 0) *valid = false;
      worst = std::min(worst, min_angle_deg(m.nodes[T[0]], m.nodes[T[1]], m.nodes[T[2]]));
    }
    return worst;
  };
  for (int pass = 0; pass < opt.passes; ++pass) {
    std::int64_t moved = 0;
    for (std::size_t v = 0; v < n; ++v) {
      if (pinned[v] || nbr[v].empty()) continue;
      Vec2 c = Vec2::Zero();
      for (Index j : nbr[v]) c += m.nodes[j];
      c /= static_cast<double>(nbr[v].size());
      bool valid = true;
      const double before = local(static_cast<Index>(v), &valid);
      const Vec2 old = m.nodes[v];
      m.nodes[v] = c;
      const double after = local(static_cast<Index>(v), &valid);
      if (!valid || after < before) {
        m.nodes[v] = old;
        ++st.rejected;
      } else if ((c - old).squaredNorm() > 0) {
        ++moved;
      }
    }
    st.passes = pass + 1;
    st.moves += moved;
    if (moved == 0) break;
  }
  return st;
}

}  // namespace bisect::mesh2d
