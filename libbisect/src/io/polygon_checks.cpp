#include "io/polygon_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <unordered_map>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"

namespace bisect::io {
namespace {

bool within_box(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
         p.y() <= std::max(a.y(), b.y());
}

// Whether closed segments ab and cd meet; *at a point where they do, *proper whether they cross.
bool meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, Vec2* at, bool* proper) {
  const int o1 = geom::orient2d(a, b, c), o2 = geom::orient2d(a, b, d);
  const int o3 = geom::orient2d(c, d, a), o4 = geom::orient2d(c, d, b);
  *proper = false;
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    const double den = (b - a).x() * (d - c).y() - (b - a).y() * (d - c).x();
    const double t = ((c - a).x() * (d - c).y() - (c - a).y() * (d - c).x()) / den;
    *at = a + std::clamp(t, 0.0, 1.0) * (b - a);
    *proper = true;
    return true;
  }
  if (o1 == 0 && within_box(a, b, c)) return *at = c, true;
  if (o2 == 0 && within_box(a, b, d)) return *at = d, true;
  if (o3 == 0 && within_box(c, d, a)) return *at = a, true;
  if (o4 == 0 && within_box(c, d, b)) return *at = b, true;
  return false;
}

}  // namespace

void check_simple_polygon(const std::vector<Vec2>& X, const std::vector<Index>& poly, Index number, const std::string& where) {
  const std::size_t n = poly.size();
  if (n < 3) return;
  const auto node = [&](std::size_t i) { return X[poly[i % n]]; };
  const auto fail = [&](const std::string& how, std::size_t i, std::size_t j, const Vec2& at) {
    std::ostringstream m;
    m.precision(9);
    m << where << ": polygon " << number + 1 << " " << how << " (its edges from node " << poly[i] + 1 << " to " << poly[(i + 1) % n] + 1
      << " and from node " << poly[j] + 1 << " to " << poly[(j + 1) % n] + 1 << "), at (" << at.x() << ", " << at.y()
      << "); a polygon must be simple";
    throw InputError(m.str());
  };
  // neighbours: the second edge may not run back along the first
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = node(i), &b = node(i + 1), &c = node(i + 2);
    if (geom::orient2d(a, b, c) == 0 && (a - b).dot(c - b) > 0) fail("turns back on itself", i, (i + 1) % n, b);
  }
  if (n == 3) return;
  // other pairs, through a grid of cells about an edge long (a long edge spans several)
  Vec2 lo = node(0), hi = node(0);
  double length = 0;
  for (std::size_t i = 0; i < n; ++i) lo = lo.cwiseMin(node(i)), hi = hi.cwiseMax(node(i)), length += (node(i + 1) - node(i)).norm();
  const double extent = (hi - lo).maxCoeff();
  const double cell = std::max({length / static_cast<double>(n), extent / std::sqrt(static_cast<double>(n)), 1e-300});
  const auto index = [&](double v, double base) {
    return static_cast<std::int64_t>(std::min(std::floor((v - base) / cell), 1e9));
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = node(i), &b = node(i + 1);
    const std::int64_t x0 = index(std::min(a.x(), b.x()), lo.x()), x1 = index(std::max(a.x(), b.x()), lo.x());
    const std::int64_t y0 = index(std::min(a.y(), b.y()), lo.y()), y1 = index(std::max(a.y(), b.y()), lo.y());
    for (std::int64_t x = x0; x <= x1; ++x)
      for (std::int64_t y = y0; y <= y1; ++y) cells[static_cast<std::uint64_t>(x) << 32 | static_cast<std::uint64_t>(y)].push_back(i);
  }
  // the first pair in edge order, whichever cell finds it, so the message does not depend on hashing
  std::size_t best_i = n, best_j = n;
  Vec2 best_at = Vec2::Zero();
  bool best_proper = false;
  for (const auto& [key, edges] : cells)
    for (std::size_t s = 0; s < edges.size(); ++s)
      for (std::size_t t = s + 1; t < edges.size(); ++t) {
        const std::size_t i = std::min(edges[s], edges[t]), j = std::max(edges[s], edges[t]);
        if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // neighbours, checked above
        if (i > best_i || (i == best_i && j >= best_j)) continue;
        Vec2 at;
        bool proper = false;
        if (!meet(node(i), node(i + 1), node(j), node(j + 1), &at, &proper)) continue;
        best_i = i, best_j = j, best_at = at, best_proper = proper;
      }
  if (best_i < n) fail(best_proper ? "crosses itself" : "touches itself", best_i, best_j, best_at);
}

}  // namespace bisect::io
