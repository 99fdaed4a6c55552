// The Jacobian of a 10-node tetrahedron, x(l) = sum_c l_c (2 l_c - 1) x_c + sum_e 4 l_a l_b m_e in
// barycentric coordinates l, evaluated where a solver needs it positive: the corners and the
// 4 Gauss points of the degree-2 rule that CalculiX's C3D10 uses; and the edges' middles and
// the centre, where a fold between those points shows.
#include <algorithm>
#include <array>

#include "bisect/validate.hpp"

namespace bisect {
namespace {

// dx/dxi_k with xi_k = l_{k+1} (l_0 = 1 - xi_1 - xi_2 - xi_3), at barycentric l.
double jacobian_det(const std::array<Vec3, 10>& x, const std::array<double, 4>& l) {
  Eigen::Matrix3d J;
  for (int k = 1; k <= 3; ++k) {
    // d l_c / d xi_k: -1 for c = 0, 1 for c = k, 0 otherwise
    auto dl = [k](int c) { return c == 0 ? -1.0 : (c == k ? 1.0 : 0.0); };
    Vec3 d = Vec3::Zero();
    for (int c = 0; c < 4; ++c) d += (4 * l[c] - 1) * dl(c) * x[c];
    for (int e = 0; e < 6; ++e) {
      const int a = kTetEdge[e][0], b = kTetEdge[e][1];
      d += 4 * (dl(a) * l[b] + l[a] * dl(b)) * x[4 + e];
    }
    J.col(k - 1) = d;
  }
  return J.determinant();
}

}  // namespace

double tet10_jacobian_ratio(const TetMesh& mesh, std::size_t t) {
  std::array<Vec3, 10> x;
  for (int i = 0; i < 10; ++i) x[i] = mesh.nodes[mesh.tet_node(t, i)];
  const double straight = (x[1] - x[0]).dot((x[2] - x[0]).cross(x[3] - x[0]));
  if (!(straight > 0)) return -1;  // the straight element is flat or inverted already
  constexpr double a = 0.5854101966249685, b = 0.1381966011250105;
  // the corners and Gauss points, then the edges' middles and the centre: a curved mid-node can
  // fold the element between the Gauss points (a sliver under a cylinder whose surface edge's
  // mid-node landed on the opposite edge's middle: positive at all 8 points, two mid-nodes at
  // one place)
  constexpr double h = 0.5, q = 0.25;
  static const std::array<std::array<double, 4>, 15> points{{{1, 0, 0, 0},
                                                             {0, 1, 0, 0},
                                                             {0, 0, 1, 0},
                                                             {0, 0, 0, 1},
                                                             {a, b, b, b},
                                                             {b, a, b, b},
                                                             {b, b, a, b},
                                                             {b, b, b, a},
                                                             {h, h, 0, 0},
                                                             {h, 0, h, 0},
                                                             {h, 0, 0, h},
                                                             {0, h, h, 0},
                                                             {0, h, 0, h},
                                                             {0, 0, h, h},
                                                             {q, q, q, q}}};
  double worst = 1e300;
  for (const auto& l : points) worst = std::min(worst, jacobian_det(x, l));
  return worst / straight;
}

}  // namespace bisect
