// Convex cells halved for the threads (bisect/balance_split.hpp): a cell holding more than a
// sixth of the job's elements, and at least 20,000 of them, is halved until it holds no more;
// never a thin wall, never when the option is off.
#include <gtest/gtest.h>

#include <algorithm>

#include "bisect/balance_split.hpp"
#include "bisect/decomposition_checks.hpp"
#include "bisect/polyhedral_model.hpp"
#include "poly_shapes.hpp"

namespace bisect {
namespace {

using test::poly;

// An a x b x 1 box.
PolyInput box(double a, double b) { return poly(test::prism({{0, 0}, {a, 0}, {a, b}, {0, b}})); }

std::size_t splits(const Decomposition& d) {
  const auto it = d.stats.bisections.find("balance_split");
  return it == d.stats.bisections.end() ? 0 : it->second;
}

// The largest cell's share of the volume.
double largest_share(const Decomposition& d, double volume) {
  double largest = 0;
  for (std::size_t c = 0; c < d.cells.size(); ++c) largest = std::max(largest, d.model.region_volume(static_cast<Index>(c)));
  return largest / volume;
}

Decomposition decompose_at(const PolyInput& in, double elements, bool balance = true) {
  DecomposeOptions opt;
  opt.split_elements = elements;
  opt.balance_cells = balance;
  return decompose(in, opt);
}

TEST(BalanceSplit, ALargeCellIsHalvedUntilItHoldsASixthAtMost) {
  // a 4 x 4 x 1 plate, one convex cell: at 10^6 elements halved into eighths (a quarter holds
  // more than a sixth)
  const Decomposition d = decompose_at(box(4, 4), 1e6);
  test::expect_valid_cells(d, 16.0);
  EXPECT_EQ(d.cells.size(), 8u);
  EXPECT_EQ(splits(d), 7u);
  EXPECT_LE(largest_share(d, 16.0), kBalanceShare);
  // the L prism's two cells (three unit squares, one of them two): its larger cell holds two
  // thirds, and is halved twice; the other, a third, once
  const Decomposition l = decompose_at(poly(test::l_prism()), 1e6);
  test::expect_valid_cells(l, 3.0);
  EXPECT_LE(largest_share(l, 3.0), kBalanceShare + 1e-12);
  EXPECT_GE(l.cells.size(), 6u);
  EXPECT_EQ(splits(l), l.cells.size() - 2);
}

TEST(BalanceSplit, SmallJobsThinWallsAndTheOptionOffAreNotCut) {
  // 3 * 10^4 elements: the plate's one cell holds more than kBalanceMinElements, so halved once;
  // at 1.9 * 10^4 it holds fewer and stays whole
  EXPECT_EQ(decompose_at(box(4, 4), 3e4).cells.size(), 2u);
  EXPECT_EQ(decompose_at(box(4, 4), 1.9e4).cells.size(), 1u);
  // a 100 x 100 x 1 wall at 10^5: the spacing (0.93) crosses it in about one element; cut faces
  // would only add constraints
  const Decomposition wall = decompose_at(box(100, 100), 1e5);
  EXPECT_EQ(wall.cells.size(), 1u);
  EXPECT_EQ(splits(wall), 0u);
  EXPECT_EQ(decompose_at(box(4, 4), 1e6, false).cells.size(), 1u);
  EXPECT_EQ(decompose(box(4, 4), DecomposeOptions{}).cells.size(), 1u);  // no count nor size: the thesis's cells
}

}  // namespace
}  // namespace bisect
