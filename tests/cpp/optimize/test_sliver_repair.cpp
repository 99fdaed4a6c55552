// Sliver repair and its dihedral measure: every tetrahedron stays positive and fixed nodes stay
// where they were.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "optimize/bipyramid.hpp"
#include "optimize/grid_cube.hpp"
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

TEST(SliverRepair, TwoFreeNodesTooCloseBecomeOne) {
  // a jittered grid with one more free node 0.01 from an inner one: the tetrahedra between the
  // two are slivers that no move of either removes for good; with no rounds of moves, the
  // repair's last stage collapses their edge
  GridCube g(4, 0.02, 5);
  const Vec3 twin = g.X[8 + 21] + Vec3(0.006, 0.005, 0.006);
  g.X.push_back(twin);
  g.fixed.push_back(0);
  TetComplex cx(g.X);
  cx.build(g.fill());
  const auto used = [&] {
    std::set<Index> nodes;
    for (std::size_t t = 0; t < cx.tet.size(); ++t)
      if (cx.alive[t]) nodes.insert(cx.tet[t].begin(), cx.tet[t].end());
    return nodes;
  };
  const std::size_t nodes_before = used().size();
  const double before = worst_cos(g.X, cx.tets());
  ASSERT_GT(before, std::cos(10 * 3.14159265358979323846 / 180));  // the pair makes a sliver
  std::vector<Index> all;
  for (std::size_t t = 0; t < cx.tet.size(); ++t) all.push_back(static_cast<Index>(t));
  const std::vector<Vec3> start = g.X;
  EXPECT_GT(repair_slivers(cx, g.X, g.fixed, 10, 0, all), 0u);
  const std::set<Index> after_nodes = used();
  EXPECT_LT(after_nodes.size(), nodes_before);
  EXPECT_TRUE(after_nodes.count(8 + 21) == 0 || after_nodes.count(static_cast<Index>(g.X.size() - 1)) == 0);
  EXPECT_LT(worst_cos(g.X, cx.tets()), before);
  for (const Tet& t : cx.tets()) EXPECT_TRUE(positive(g.X, t));
  for (std::size_t v = 0; v < 8; ++v) EXPECT_EQ(g.X[v], start[v]) << v;
  // the keys the complex keeps are the tetrahedra's own
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t]) {
      EXPECT_DOUBLE_EQ(cx.q[t], tet::tet_angle_key(g.X, cx.tet[t]));
    }
}

}  // namespace
}  // namespace bisect::optimize
