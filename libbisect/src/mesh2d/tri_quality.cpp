#include "mesh2d/tri_quality.hpp"

#include <algorithm>
#include <cmath>

namespace bisect::mesh2d {
namespace {

double corner_deg(const Vec2& p, const Vec2& q, const Vec2& r) {  // angle at p
  const Vec2 a = q - p, b = r - p;
  return std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b)) * 180.0 / M_PI;
}

template <std::size_t N, class F>
void corners(const TriMesh2& m, const std::vector<std::array<Index, N>>& els, F f) {
  for (const auto& e : els)
    for (std::size_t k = 0; k < N; ++k)
      f(corner_deg(m.nodes[e[k]], m.nodes[e[(k + 1) % N]], m.nodes[e[(k + N - 1) % N]]));
}

}  // namespace

double min_angle_deg(const Vec2& a, const Vec2& b, const Vec2& c) {
  // the smallest angle faces the shortest side: one arctangent instead of three (the swaps and
  // the smoothing of every face grid call this)
  const double bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm(), ab = (b - a).squaredNorm();
  if (bc <= ca && bc <= ab) return corner_deg(a, b, c);
  return ca <= ab ? corner_deg(b, c, a) : corner_deg(c, a, b);
}

double min_angle_deg(const TriMesh2& m) {
  double v = 180;
  corners(m, m.tris, [&](double a) { v = std::min(v, a); });
  corners(m, m.quads, [&](double a) { v = std::min(v, a); });
  return v;
}

double max_angle_deg(const TriMesh2& m) {
  double v = 0;
  corners(m, m.tris, [&](double a) { v = std::max(v, a); });
  corners(m, m.quads, [&](double a) { v = std::max(v, a); });
  return v;
}

double total_area(const TriMesh2& m) {
  double a = 0;
  auto area = [&](const auto& e) {
    double s = 0;
    for (std::size_t k = 0; k < e.size(); ++k) {
      const Vec2 &p = m.nodes[e[k]], &q = m.nodes[e[(k + 1) % e.size()]];
      s += p.x() * q.y() - p.y() * q.x();
    }
    return 0.5 * s;
  };
  for (const auto& t : m.tris) a += area(t);
  for (const auto& q : m.quads) a += area(q);
  return a;
}

}  // namespace bisect::mesh2d
