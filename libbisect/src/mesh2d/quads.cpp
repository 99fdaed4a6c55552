#include "mesh2d/quads.hpp"

#include <algorithm>
#include <cmath>

#include "geom/predicates.hpp"
#include "mesh2d/smooth.hpp"
#include "mesh2d/tri_adjacency.hpp"
#include "mesh2d/tri_quality.hpp"

namespace bisect::mesh2d {
namespace {

// The smallest corner of quad q in degrees, or -1 when it is not strictly convex.
double quad_min_angle(const TriMesh2& m, const std::array<Index, 4>& q) {
  double worst = 180;
  for (int k = 0; k < 4; ++k) {
    const Vec2 &p = m.nodes[q[(k + 3) % 4]], &c = m.nodes[q[k]], &n = m.nodes[q[(k + 1) % 4]];
    if (geom::orient2d(p, c, n) <= 0) return -1;
    const Vec2 a = p - c, b = n - c;
    worst = std::min(worst, std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b)) * 180 / M_PI);
  }
  return worst;
}

}  // namespace

QuadStats make_quads(TriMesh2& m, const QuadOptions& opt) {
  const TriAcross nb = triangle_neighbours(m);
  const std::size_t nt = m.tris.size();
  std::vector<char> used(nt, 0);
  // the best partner of triangle t among its unused neighbours of the same region
  auto best_pair = [&](int t, std::array<Index, 4>* quad) {
    int best = -1;
    double best_angle = opt.min_angle_deg;
    for (int k = 0; k < 3; ++k) {
      const auto [j, kj] = nb[t][k];
      if (j < 0 || used[j] || m.tri_region[j] != m.tri_region[t]) continue;
      const Index c = m.tris[t][k], a = m.tris[t][(k + 1) % 3], b = m.tris[t][(k + 2) % 3], d = m.tris[j][kj];
      const std::array<Index, 4> q{a, d, b, c};  // counter-clockwise round both triangles
      const double ang = quad_min_angle(m, q);
      if (ang >= best_angle) best_angle = ang, best = j, *quad = q;
    }
    return best;
  };
  std::vector<std::array<Index, 4>> quads;
  std::vector<Index> quad_region;
  std::vector<std::pair<int, int>> stack;  // quads as their two triangles
  auto form = [&](int t) {
    std::array<Index, 4> q;
    const int j = best_pair(t, &q);
    if (j < 0) return false;
    used[t] = used[j] = 1;
    quads.push_back(q);
    quad_region.push_back(m.tri_region[t]);
    stack.push_back({t, j});
    return true;
  };
  for (std::size_t start = 0; start < nt; ++start) {
    if (used[start] || !form(static_cast<int>(start))) continue;
    while (!stack.empty()) {  // walk on from each quad's sides
      const auto [t1, t2] = stack.back();
      stack.pop_back();
      for (int t : {t1, t2})
        for (int k = 0; k < 3; ++k) {
          const int across = nb[t][k].first;
          if (across >= 0 && !used[across]) form(across);
        }
    }
  }
  std::vector<std::array<Index, 3>> tris;
  std::vector<Index> tri_region;
  for (std::size_t t = 0; t < nt; ++t)
    if (!used[t]) tris.push_back(m.tris[t]), tri_region.push_back(m.tri_region[t]);
  m.tris = std::move(tris);
  m.tri_region = std::move(tri_region);
  m.quads.insert(m.quads.end(), quads.begin(), quads.end());
  m.quad_region.insert(m.quad_region.end(), quad_region.begin(), quad_region.end());
  if (opt.smooth_passes > 0) smooth_laplace(m, {opt.smooth_passes});
  QuadStats st;
  st.quads = static_cast<std::int64_t>(quads.size());
  st.triangles_left = static_cast<std::int64_t>(m.tris.size());
  st.min_angle_deg = min_angle_deg(m);
  return st;
}

}  // namespace bisect::mesh2d
