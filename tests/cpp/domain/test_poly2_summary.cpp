// Areas and nesting of 2D inputs: holes and sub-domains are found by containment, whatever the
// direction of their polygons, and leave the region that holds them.
#include <gtest/gtest.h>

#include "bisect/poly_input.hpp"

using namespace bisect;

namespace {

// The two thesis examples of 4.6.1: a unit square with an inner square at [0.25, 0.75]^2 (a
// hole, or a sub-domain) beside a second unit square.
Poly2Input squares(bool inner_is_hole, bool reverse_inner) {
  Poly2Input in;
  in.nodes = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}, {0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}};
  in.polygons = {{{0, 1, 2, 3}, false}, {{1, 4, 5, 2}, false}, {{6, 7, 8, 9}, inner_is_hole}};
  if (reverse_inner) in.polygons[2].nodes = {9, 8, 7, 6};
  return in;
}

}  // namespace

TEST(Poly2Summary, SquareWithHoleBesideASquare) {
  for (bool reverse : {false, true}) {
    const Poly2Summary s = summarize(squares(true, reverse));
    ASSERT_EQ(s.polygons.size(), 3u);
    EXPECT_EQ(s.polygons[0].inside, -1);
    EXPECT_EQ(s.polygons[1].inside, -1);  // shares an edge with polygon 0, does not lie in it
    EXPECT_EQ(s.polygons[2].inside, 0);
    EXPECT_DOUBLE_EQ(s.polygons[0].area, 1.0);
    EXPECT_DOUBLE_EQ(s.polygons[0].net_area, 0.75);
    EXPECT_DOUBLE_EQ(s.polygons[1].net_area, 1.0);
    EXPECT_DOUBLE_EQ(s.polygons[2].area, 0.25);
    EXPECT_DOUBLE_EQ(s.polygons[2].net_area, 0.0);  // a hole is no region
    EXPECT_DOUBLE_EQ(s.area, 1.75);
    EXPECT_EQ(s.nodes, 10u);
    EXPECT_EQ(s.bbox_min, Vec2(0, 0));
    EXPECT_EQ(s.bbox_max, Vec2(2, 1));
  }
}

TEST(Poly2Summary, SubDomainIsItsOwnRegion) {
  const Poly2Summary s = summarize(squares(false, false));
  EXPECT_EQ(s.polygons[2].inside, 0);
  EXPECT_DOUBLE_EQ(s.polygons[0].net_area, 0.75);
  EXPECT_DOUBLE_EQ(s.polygons[2].net_area, 0.25);
  EXPECT_DOUBLE_EQ(s.area, 2.0);  // all of both squares is meshed
}

TEST(Poly2Summary, NestedContainmentPicksTheSmallestContainer) {
  // Three concentric squares: the innermost lies directly in the middle one, not in the outer.
  Poly2Input in;
  in.nodes = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {3, 3}, {1, 3}, {1.5, 1.5}, {2.5, 1.5}, {2.5, 2.5},
              {1.5, 2.5}};
  in.polygons = {{{0, 1, 2, 3}, false}, {{4, 5, 6, 7}, true}, {{8, 9, 10, 11}, false}};
  const Poly2Summary s = summarize(in);
  EXPECT_EQ(s.polygons[1].inside, 0);
  EXPECT_EQ(s.polygons[2].inside, 1);
  EXPECT_DOUBLE_EQ(s.polygons[0].net_area, 12.0);
  EXPECT_DOUBLE_EQ(s.polygons[2].net_area, 1.0);
  EXPECT_DOUBLE_EQ(s.area, 13.0);
}

TEST(Poly2Summary, InnerPolygonTouchingTheOuterBoundaryStillLiesInside) {
  // A notch square sharing the bottom edge segment [1,2] of the outer square: every node of it
  // is inside or on the outer boundary; containment is decided by its edge midpoints.
  Poly2Input in;
  in.nodes = {{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 0}, {2, 0}, {2, 1}, {1, 1}};
  in.polygons = {{{0, 1, 2, 3}, false}, {{4, 5, 6, 7}, false}};
  const Poly2Summary s = summarize(in);
  EXPECT_EQ(s.polygons[1].inside, 0);
  EXPECT_DOUBLE_EQ(s.polygons[0].net_area, 8.0);
}
