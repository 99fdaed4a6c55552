// Guarded Laplace smoothing: it never inverts a tetrahedron nor moves a fixed node.
#include <gtest/gtest.h>

#include "optimize/bipyramid.hpp"
#include "optimize/smooth.hpp"
#include "tet/cell_fill.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::optimize {
namespace {

using tet::fill_convex_cell;
using tet::positive;
using tet::Tet;

TEST(Smooth, LaplaceNeverInvertsNorMovesFixedNodes) {
  Bipyramid p;
  const std::vector<Tet> tets = fill_convex_cell(p.X, p.boundary, {5}, Vec3(0, 0, 0));
  const std::vector<Vec3> before = p.X;
  tet::TetComplex cx(p.X);
  cx.build(tets);
  EXPECT_EQ(smooth_nodes(cx, p.X, p.fixed, {0}), 1u);  // the free node, met through one tetrahedron
  for (std::size_t v = 0; v < 5; ++v) EXPECT_EQ(p.X[v], before[v]);
  EXPECT_LT(p.X[5].z(), 0.5);  // towards the neighbours' mean, (0, 0, 0)
  for (const Tet& t : tets) EXPECT_TRUE(positive(p.X, t));
}

}  // namespace
}  // namespace bisect::optimize
