// Slender convex cells cut again across their length (bisect/slender_split.hpp): bars and plates
// that hold many elements, never a thin wall the spacing crosses in a couple of elements, never a
// cell of moderate aspect.
#include <gtest/gtest.h>

#include <cmath>

#include "bisect/decomposition_checks.hpp"
#include "bisect/polyhedral_model.hpp"
#include "bisect/slender_split.hpp"
#include "poly_shapes.hpp"

namespace bisect {
namespace {

using test::poly;

// An a x b x 1 box.
PolyInput box(double a, double b) { return poly(test::prism({{0, 0}, {a, 0}, {a, b}, {0, b}})); }

// The slender cuts alone: the cuts for the threads' balance (balance_split) would halve these
// cells further, and have tests of their own.
DecomposeOptions slender_only() {
  DecomposeOptions opt;
  opt.balance_cells = false;
  return opt;
}

std::size_t splits(const Decomposition& d) {
  const auto it = d.stats.bisections.find("slender_split");
  return it == d.stats.bisections.end() ? 0 : it->second;
}

// The cells' extents along x, sorted.
std::vector<double> lengths(const Decomposition& d) {
  std::vector<double> out;
  for (const ConvexCell& c : d.cells) {
    double lo = 1e300, hi = -1e300;
    for (Index f : c.faces)
      for (Index v : d.model.faces[f].loops[0]) lo = std::min(lo, d.model.nodes[v].x()), hi = std::max(hi, d.model.nodes[v].x());
    out.push_back(hi - lo);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(SlenderSplit, ABarIsHalvedUntilItIsNoLongerSlender) {
  DecomposeOptions opt = slender_only();
  opt.split_elements = 2e5;
  const Decomposition d = decompose(box(32, 1), opt);  // 32:1, then 16:1 (not above 16)
  ASSERT_EQ(d.cells.size(), 2u);
  EXPECT_EQ(splits(d), 1u);
  test::expect_valid_cells(d, 32.0);
  for (double l : lengths(d)) EXPECT_NEAR(l, 16, 1e-9);
  // a 100 x 5 x 1 plate (a bimetal strip's): 100, 50, 25, then 12.5 long cells
  const Decomposition p = decompose(box(100, 5), opt);
  ASSERT_EQ(p.cells.size(), 8u);
  EXPECT_EQ(splits(p), 7u);
  test::expect_valid_cells(p, 500.0);
  for (double l : lengths(p)) EXPECT_NEAR(l, 12.5, 1e-9);
}

TEST(SlenderSplit, OnlyWhenTheMeshIsFineAcrossTheCell) {
  DecomposeOptions opt = slender_only();
  EXPECT_EQ(decompose(box(32, 1), opt).cells.size(), 1u);  // no count nor size: the thesis's cells
  opt.split_size = 0.1;  // 10 elements across: cut
  EXPECT_EQ(decompose(box(32, 1), opt).cells.size(), 2u);
  opt.split_size = 0.8;  // 1.25 across (under kSlenderMinThickness): a thin wall, not cut
  EXPECT_EQ(decompose(box(32, 1), opt).cells.size(), 1u);
  opt.split_size = 0;
  opt.split_elements = 1e4;  // the plate at 10^4: its spacing 0.74 makes it 1.4 elements thick
  EXPECT_EQ(decompose(box(100, 5), opt).cells.size(), 1u);
  opt.split_elements = 1e3;  // the bar at 10^3: thick enough (0.5 spacing) but too few elements
  EXPECT_EQ(decompose(box(32, 1), opt).cells.size(), 1u);
}

TEST(SlenderSplit, CellsOfModerateAspectAndOtherCutsStayAsTheyWere) {
  DecomposeOptions opt = slender_only();
  opt.split_elements = 1e6;
  const Decomposition bar = decompose(box(16, 1), opt);  // 16:1 is not above the limit
  EXPECT_EQ(bar.cells.size(), 1u);
  EXPECT_EQ(splits(bar), 0u);
  const Decomposition l = decompose(poly(test::l_prism()), opt);
  EXPECT_EQ(l.cells.size(), 2u);
  EXPECT_EQ(splits(l), 0u);
}

}  // namespace
}  // namespace bisect
