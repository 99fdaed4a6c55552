// Sliver repair and its dihedral measure: every tetrahedron stays positive and fixed nodes stay
// where they were.
#include <gtest/gtest.h>

#include <cmath>

#include "optimize/bipyramid.hpp"
#include "optimize/node_stars.hpp"
#include "optimize/sliver_repair.hpp"
#include "tet/cell_fill.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::optimize {
namespace {

using tet::fill_convex_cell;
using tet::positive;
using tet::Tet;
using tet::TetComplex;

double worst_cos(const std::vector<Vec3>& X, const std::vector<Tet>& tets) {
  double w = -1;
  for (const Tet& t : tets) w = std::max(w, worst_dihedral_cos(X[t[0]], X[t[1]], X[t[2]], X[t[3]]));
  return w;
}

TEST(SliverRepair, WorstDihedralCosine) {
  const Vec3 a(1, 1, 1), b(1, -1, -1), c(-1, 1, -1), d(-1, -1, 1);  // regular
  // one orientation is positive: arccos(1/3) = 70.53 degrees; the other is not
  EXPECT_NEAR(std::min(worst_dihedral_cos(a, b, c, d), worst_dihedral_cos(a, c, b, d)), 1.0 / 3, 1e-12);
  EXPECT_EQ(std::max(worst_dihedral_cos(a, b, c, d), worst_dihedral_cos(a, c, b, d)), 2);
  // a sliver: four nodes near one circle
  const Vec3 s0(1, 0, 0.01), s1(0, 1, -0.01), s2(-1, 0, 0.01), s3(0, -1, -0.01);
  const double sliver = std::min(worst_dihedral_cos(s0, s1, s2, s3), worst_dihedral_cos(s0, s2, s1, s3));
  EXPECT_GT(sliver, std::cos(5 * 3.14159265358979323846 / 180));
}

TEST(SliverRepair, SliverRepairMovesTheFreeNodeAndKeepsFixedOnes) {
  Bipyramid p;
  const std::vector<Tet> tets = fill_convex_cell(p.X, p.boundary, {5}, Vec3(0, 0, 0));
  ASSERT_EQ(tets.size(), 6u);
  EXPECT_GT(worst_cos(p.X, tets), std::cos(10 * 3.14159265358979323846 / 180)) << "the set-up has no sliver";
  const std::vector<Vec3> before = p.X;
  TetComplex cx(p.X);
  cx.build(tets);
  const std::size_t moves = repair_slivers(cx, p.X, p.fixed, 10, 5, all_below_key(cx, sliver_key(10)));
  EXPECT_GE(moves, 1u);
  for (std::size_t v = 0; v < 5; ++v) EXPECT_EQ(p.X[v], before[v]) << "fixed node " << v << " moved";
  for (const Tet& t : cx.tets()) EXPECT_TRUE(positive(p.X, t));
  EXPECT_LT(worst_cos(p.X, cx.tets()), std::cos(10 * 3.14159265358979323846 / 180));
  // no rounds, no change
  Bipyramid q;
  TetComplex untouched(q.X);
  untouched.build(fill_convex_cell(q.X, q.boundary, {5}, Vec3(0, 0, 0)));
  EXPECT_EQ(repair_slivers(untouched, q.X, q.fixed, 10, 0, all_below_key(untouched, sliver_key(10))), 0u);
  EXPECT_EQ(q.X[5], Bipyramid().X[5]);
}

}  // namespace
}  // namespace bisect::optimize
