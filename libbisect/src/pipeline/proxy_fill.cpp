#include "pipeline/proxy_fill.hpp"

#include <algorithm>
#include <string>

#include <Eigen/Dense>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"

namespace bisect::pipeline {
namespace {

double volume(const std::vector<Vec3>& X, const tet::Tet& t) {
  return (X[t[1]] - X[t[0]]).dot((X[t[2]] - X[t[0]]).cross(X[t[3]] - X[t[0]])) / 6;
}

// The point that maximises the smallest distance to the planes of the faces opposite v in the
// tetrahedra round it (each tetrahedron's volume is linear in v's position: positive on one side
// of that plane): a 4-variable linear programme (x, s) whose optimum has four active planes,
// found by trying every four. The stars untangled here hold a few dozen tetrahedra at most.
bool chebyshev_centre(const std::vector<Vec3>& X, const std::vector<tet::Tet>& tets, const std::vector<Index>& around, Index v,
                      Vec3* best) {
  std::vector<Vec3> u;
  std::vector<double> e;
  for (Index t : around) {
    // the volume is linear in v's position: its gradient n and value at the current position
    tet::Tet k = tets[t];
    std::vector<Vec3> P = {X[k[0]], X[k[1]], X[k[2]], X[k[3]]};
    int i = 0;
    while (k[i] != v) ++i;
    const double v0 = volume(X, k);
    Vec3 n;
    for (int d = 0; d < 3; ++d) {
      std::vector<Vec3> Q = P;
      Q[i][d] += 1;
      n[d] = (Q[1] - Q[0]).dot((Q[2] - Q[0]).cross(Q[3] - Q[0])) / 6 - v0;
    }
    const double len = n.norm();
    if (len < 1e-300) continue;
    u.push_back(n / len);
    e.push_back((n.dot(X[v]) - v0) / len);
  }
  const std::size_t m = u.size();
  if (m < 4 || m > 48) return false;
  double best_s = -1e300;
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b)
      for (std::size_t c = b + 1; c < m; ++c)
        for (std::size_t d = c + 1; d < m; ++d) {
          Eigen::Matrix4d A;
          Eigen::Vector4d r;
          const std::size_t pick[4] = {a, b, c, d};
          // (r(j) apart: inside the comma initializer it was a fifth value, written past the row
          // into A(0, 1), which the sanitizer build's Eigen assertion caught)
          for (int j = 0; j < 4; ++j) {
            A.row(j) << u[pick[j]].x(), u[pick[j]].y(), u[pick[j]].z(), -1.0;
            r(j) = e[pick[j]];
          }
          // the closed-form 4x4 inverse: these solves are most of an untangling's time (a star of
          // 40 planes has 91,390 fours; FullPivLU took 12% of corpus/x_ring.brep's meshing)
          Eigen::Matrix4d inv;
          bool invertible = false;
          double det = 0;
          A.computeInverseAndDetWithCheck(inv, det, invertible, 1e-12);
          if (!invertible) continue;
          const Eigen::Vector4d xs = inv * r;
          if (xs(3) <= best_s) continue;
          const Vec3 x(xs(0), xs(1), xs(2));
          bool ok = true;
          for (std::size_t j = 0; j < m && ok; ++j) ok = u[j].dot(x) - e[j] >= xs(3) - 1e-12 * (1 + std::abs(e[j]));
          if (ok) best_s = xs(3), *best = x;
        }
  return best_s > -1e300;
}

}  // namespace

std::vector<tet::Tet> fill_in_proxy(std::vector<Vec3>& X, std::vector<Vec3>& P, const std::vector<std::array<Index, 3>>& boundary,
                                    const std::vector<Index>& interior, const Vec3& centroid_p, bool delaunay, tet::CellFillStats* stats,
                                    bool keep_inverted) {
  const std::size_t before = P.size();
  std::vector<tet::Tet> tets = tet::fill_convex_cell(P, boundary, interior, centroid_p, delaunay, stats);
  for (std::size_t v = before; v < P.size(); ++v) X.push_back(P[v]);  // a helper: inside, away from the moved boundary
  std::vector<char> fixed(X.size(), 0);
  for (const auto& t : boundary)
    for (Index v : t) fixed[v] = 1;
  std::vector<std::vector<Index>> around(X.size());
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (Index v : tets[t]) around[v].push_back(static_cast<Index>(t));
  auto inverted = [&](const tet::Tet& t) { return geom::orient3d(X[t[0]], X[t[1]], X[t[2]], X[t[3]]) <= 0; };
  auto worst_at = [&](Index v) {
    double w = 1e300;
    for (Index t : around[v]) w = std::min(w, volume(X, tets[t]));
    return w;
  };
  for (int round = 0; round < 30; ++round) {
    std::vector<Index> bad;
    for (const tet::Tet& t : tets)
      if (inverted(t))
        for (Index v : t)
          if (!fixed[v]) bad.push_back(v);
    if (bad.empty()) break;  // none inverted, or only ones with no node free to move
    std::sort(bad.begin(), bad.end());
    bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
    bool moved = false;
    for (Index v : bad) {
      Vec3 mean = Vec3::Zero();
      int n = 0;
      for (Index t : around[v])
        for (Index w : tets[t])
          if (w != v) mean += X[w], ++n;
      mean /= std::max(n, 1);
      const Vec3 was = X[v];
      double best = worst_at(v);
      Vec3 best_p = was;
      for (const Vec3& c : {P[v], Vec3(0.75 * P[v] + 0.25 * was), Vec3(0.5 * (P[v] + was)), Vec3(0.25 * P[v] + 0.75 * was), mean,
                            Vec3(0.5 * (mean + was))}) {
        X[v] = c;
        const double w = worst_at(v);
        if (w > best) best = w, best_p = c;
      }
      Vec3 centre;
      if (best <= 0 && chebyshev_centre(X, tets, around[v], v, &centre)) {
        X[v] = centre;
        const double w = worst_at(v);
        if (w > best) best = w, best_p = centre;
      }
      X[v] = best_p;
      moved = moved || best_p != was;
    }
    if (!moved) break;
  }
  if (keep_inverted) return tets;
  for (const tet::Tet& t : tets)
    if (inverted(t))
      throw MeshingError("a tetrahedron made in the proxy's geometry turns inside out on the true surfaces and cannot be untangled");
  return tets;
}

}  // namespace bisect::pipeline
