#include "mesh2d/smooth.hpp"

#include <algorithm>
#include <map>

#include "geom/predicates.hpp"
#include "mesh2d/tri_quality.hpp"
#include <cmath>

namespace bisect::mesh2d {

SmoothStats smooth_laplace(TriMesh2& m, const SmoothOptions& opt) {
  SmoothStats st;
  const std::size_t n = m.nodes.size();
  std::vector<char> pinned(n, 0);
  for (std::size_t v = 0; v < n && v < m.fixed.size(); ++v) pinned[v] = m.fixed[v];
  // Elements as corner lists (triangles, then quadrilaterals) with their regions.
  std::vector<std::vector<Index>> els;
  std::vector<Index> region;
  for (std::size_t t = 0; t < m.tris.size(); ++t) els.push_back({m.tris[t].begin(), m.tris[t].end()}), region.push_back(m.tri_region[t]);
  for (std::size_t q = 0; q < m.quads.size(); ++q) els.push_back({m.quads[q].begin(), m.quads[q].end()}), region.push_back(m.quad_region[q]);
  // an edge with one element, or elements of two regions, is boundary or interface
  std::map<std::pair<Index, Index>, std::pair<int, Index>> edges;  // count, region
  for (std::size_t e = 0; e < els.size(); ++e)
    for (std::size_t k = 0; k < els[e].size(); ++k) {
      const Index a = els[e][k], b = els[e][(k + 1) % els[e].size()];
      auto& c = edges[{std::min(a, b), std::max(a, b)}];
      if (c.first == 0) c.second = region[e];
      else if (c.second != region[e]) c.first = 99;
      ++c.first;
    }
  for (const auto& [e, c] : edges)
    if (c.first != 2) pinned[e.first] = pinned[e.second] = 1;
  std::vector<std::vector<Index>> nbr(n), around(n);
  for (std::size_t e = 0; e < els.size(); ++e)
    for (std::size_t k = 0; k < els[e].size(); ++k) {
      const Index a = els[e][k];
      around[a].push_back(static_cast<Index>(e));
      for (Index b : {els[e][(k + 1) % els[e].size()], els[e][(k + els[e].size() - 1) % els[e].size()]})
        if (std::find(nbr[a].begin(), nbr[a].end(), b) == nbr[a].end()) nbr[a].push_back(b);
    }
  // the smallest corner of the elements around v; *valid false when one is not strictly convex
  auto local = [&](Index v, bool* valid) {
    double worst = 180;
    *valid = true;
    for (Index e : around[v]) {
      const auto& E = els[e];
      const std::size_t k = E.size();
      for (std::size_t i = 0; i < k; ++i) {
        const Vec2 &p = m.nodes[E[(i + k - 1) % k]], &c = m.nodes[E[i]], &q = m.nodes[E[(i + 1) % k]];
        if (geom::orient2d(p, c, q) <= 0) *valid = false;
        if (k == 3) continue;  // below, one arctangent for the triangle
        const Vec2 a = p - c, b = q - c;
        worst = std::min(worst, std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b)) * 180 / M_PI);
      }
      if (k == 3) worst = std::min(worst, min_angle_deg(m.nodes[E[0]], m.nodes[E[1]], m.nodes[E[2]]));
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
