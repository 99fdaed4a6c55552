#include "tet/boundary_crossing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "geom/predicates.hpp"

namespace bisect::tet {
namespace {

using geom::orient3d;

// Segment pq, its ends strictly on either side of abc's plane, meets the closed triangle abc.
bool passes_through(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
  if (sp == 0 || sq == 0 || sp == sq) return false;
  const int s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
  return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

}  // namespace

std::optional<BoundaryCrossing> boundary_crossing(const std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary) {
  if (boundary.empty()) return std::nullopt;
  // the grid's box: about the mean edge's length, so that a triangle covers a few boxes
  Vec3 lo = X[boundary[0][0]], hi = lo;
  double total = 0;
  for (const auto& t : boundary)
    for (int i = 0; i < 3; ++i) {
      lo = lo.cwiseMin(X[t[i]]), hi = hi.cwiseMax(X[t[i]]);
      total += (X[t[i]] - X[t[(i + 1) % 3]]).norm();
    }
  const double h = std::max(total / (3.0 * static_cast<double>(boundary.size())), 1e-12 * std::max(1.0, (hi - lo).norm()));
  auto cell = [&](double x, double origin) { return static_cast<std::int64_t>(std::floor((x - origin) / h)); };
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return (static_cast<std::uint64_t>(i) * 73856093u) ^ (static_cast<std::uint64_t>(j) * 19349663u) ^ (static_cast<std::uint64_t>(k) * 83492791u);
  };
  // each triangle listed in every box its bounding box meets (a hash collision only adds candidates)
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> boxes;
  auto range = [&](const Vec3& a, const Vec3& b, std::array<std::int64_t, 6>* r) {
    const Vec3 l = a.cwiseMin(b), u = a.cwiseMax(b);
    *r = {cell(l.x(), lo.x()), cell(l.y(), lo.y()), cell(l.z(), lo.z()), cell(u.x(), lo.x()), cell(u.y(), lo.y()), cell(u.z(), lo.z())};
  };
  for (std::size_t t = 0; t < boundary.size(); ++t) {
    const auto& tri = boundary[t];
    std::array<std::int64_t, 6> r;
    range(X[tri[0]].cwiseMin(X[tri[1]]).cwiseMin(X[tri[2]]), X[tri[0]].cwiseMax(X[tri[1]]).cwiseMax(X[tri[2]]), &r);
    for (std::int64_t i = r[0]; i <= r[3]; ++i)
      for (std::int64_t j = r[1]; j <= r[4]; ++j)
        for (std::int64_t k = r[2]; k <= r[5]; ++k) boxes[key(i, j, k)].push_back(t);
  }
  std::vector<std::size_t> seen(boundary.size(), 0);  // stamp per triangle: once per edge
  std::size_t stamp = 0;
  for (std::size_t e = 0; e < boundary.size(); ++e)
    for (int s = 0; s < 3; ++s) {
      const Index p = boundary[e][s], q = boundary[e][(s + 1) % 3];
      if (p > q) continue;  // each edge once: a closed boundary has it going up in one of its two triangles
      ++stamp;
      std::array<std::int64_t, 6> r;
      range(X[p], X[q], &r);
      for (std::int64_t i = r[0]; i <= r[3]; ++i)
        for (std::int64_t j = r[1]; j <= r[4]; ++j)
          for (std::int64_t k = r[2]; k <= r[5]; ++k) {
            const auto it = boxes.find(key(i, j, k));
            if (it == boxes.end()) continue;
            for (std::size_t t : it->second) {
              if (seen[t] == stamp) continue;
              seen[t] = stamp;
              const auto& c = boundary[t];
              if (std::count(c.begin(), c.end(), p) || std::count(c.begin(), c.end(), q)) continue;
              const Vec3 &A = X[c[0]], &B = X[c[1]], &C = X[c[2]];
              if (!passes_through(X[p], X[q], A, B, C)) continue;
              const Vec3 n = (B - A).cross(C - A);
              const double dp = n.dot(X[p] - A), dq = n.dot(X[q] - A);
              return BoundaryCrossing{e, t, X[p] + dp / (dp - dq) * (X[q] - X[p])};
            }
          }
    }
  return std::nullopt;
}

}  // namespace bisect::tet
