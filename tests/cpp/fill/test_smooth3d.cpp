// Node moves of the generator's last stage: the dihedral measure, guarded Laplace smoothing and
// sliver repair, which must leave every tetrahedron positive and fixed nodes where they were.
#include <gtest/gtest.h>

#include <cmath>

#include "fill/cell_fill.hpp"
#include "fill/smooth3d.hpp"
#include "fill/tet_complex.hpp"

namespace bisect::fill {
namespace {

// A triangular bipyramid (apexes fixed at z = +-1, the equator fixed at z = 0) and one free node
// just under the top apex: the three tetrahedra between that node and the top faces are flat.
struct Bipyramid {
  std::vector<Vec3> X{{1, 0, 0}, {-0.5, 0.8660254037844386, 0}, {-0.5, -0.8660254037844386, 0}, {0, 0, 1}, {0, 0, -1}, {0.003, 0.004, 0.97}};
  std::vector<std::array<Index, 3>> boundary{{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}};  // outward
  std::vector<char> fixed = std::vector<char>(6, 1);
  Bipyramid() { fixed[5] = 0; }
};

double worst_cos(const std::vector<Vec3>& X, const std::vector<Tet>& tets) {
  double w = -1;
  for (const Tet& t : tets) w = std::max(w, worst_dihedral_cos(X[t[0]], X[t[1]], X[t[2]], X[t[3]]));
  return w;
}

TEST(Smooth3d, WorstDihedralCosine) {
  const Vec3 a(1, 1, 1), b(1, -1, -1), c(-1, 1, -1), d(-1, -1, 1);  // regular
  // one orientation is positive: arccos(1/3) = 70.53 degrees; the other is not
  EXPECT_NEAR(std::min(worst_dihedral_cos(a, b, c, d), worst_dihedral_cos(a, c, b, d)), 1.0 / 3, 1e-12);
  EXPECT_EQ(std::max(worst_dihedral_cos(a, b, c, d), worst_dihedral_cos(a, c, b, d)), 2);
  // a sliver: four nodes near one circle
  const Vec3 s0(1, 0, 0.01), s1(0, 1, -0.01), s2(-1, 0, 0.01), s3(0, -1, -0.01);
  const double sliver = std::min(worst_dihedral_cos(s0, s1, s2, s3), worst_dihedral_cos(s0, s2, s1, s3));
  EXPECT_GT(sliver, std::cos(5 * 3.14159265358979323846 / 180));
}

TEST(Smooth3d, SliverRepairMovesTheFreeNodeAndKeepsFixedOnes) {
  Bipyramid p;
  const std::vector<Tet> tets = fill_convex_cell(p.X, p.boundary, {5}, Vec3(0, 0, 0));
  ASSERT_EQ(tets.size(), 6u);
  EXPECT_GT(worst_cos(p.X, tets), std::cos(10 * 3.14159265358979323846 / 180)) << "the set-up has no sliver";
  const std::vector<Vec3> before = p.X;
  TetComplex cx(p.X);
  cx.build(tets);
  const std::size_t moves = repair_slivers(cx, p.X, p.fixed, 10, 5);
  EXPECT_GE(moves, 1u);
  for (std::size_t v = 0; v < 5; ++v) EXPECT_EQ(p.X[v], before[v]) << "fixed node " << v << " moved";
  for (const Tet& t : cx.tets()) EXPECT_TRUE(positive(p.X, t));
  EXPECT_LT(worst_cos(p.X, cx.tets()), std::cos(10 * 3.14159265358979323846 / 180));
  // no rounds, no change
  Bipyramid q;
  TetComplex untouched(q.X);
  untouched.build(fill_convex_cell(q.X, q.boundary, {5}, Vec3(0, 0, 0)));
  EXPECT_EQ(repair_slivers(untouched, q.X, q.fixed, 10, 0), 0u);
  EXPECT_EQ(q.X[5], Bipyramid().X[5]);
}

TEST(Smooth3d, LaplaceNeverInvertsNorMovesFixedNodes) {
  Bipyramid p;
  const std::vector<Tet> tets = fill_convex_cell(p.X, p.boundary, {5}, Vec3(0, 0, 0));
  const std::vector<Vec3> before = p.X;
  EXPECT_EQ(smooth_interior(p.X, tets, p.fixed, 1), 1u);
  for (std::size_t v = 0; v < 5; ++v) EXPECT_EQ(p.X[v], before[v]);
  EXPECT_LT(p.X[5].z(), 0.5);  // towards the neighbours' mean, (0, 0, 0)
  for (const Tet& t : tets) EXPECT_TRUE(positive(p.X, t));
}

}  // namespace
}  // namespace bisect::fill
