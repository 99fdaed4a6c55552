// The shared line/segment-against-triangle test and the grid of boxes behind the
// self-intersection checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "geom/box_grid.hpp"
#include "geom/segment_triangle.hpp"

namespace bisect::geom {
namespace {

const Vec3 A(0, 0, 0), B(4, 0, 0), C(0, 4, 0);

TEST(SegmentTriangle, CountsTheEdgesTheLinePassesThrough) {
  // through the interior, across edge AB, through corner A, and beside the triangle
  EXPECT_EQ(segment_through_triangle(Vec3(1, 1, -1), Vec3(1, 1, 1), A, B, C), 0);
  EXPECT_EQ(segment_through_triangle(Vec3(2, 0, -1), Vec3(2, 0, 1), A, B, C), 1);
  EXPECT_EQ(segment_through_triangle(Vec3(0, 0, -1), Vec3(0, 0, 1), A, B, C), 2);
  EXPECT_EQ(segment_through_triangle(Vec3(3, 3, -1), Vec3(3, 3, 1), A, B, C), -1);
  // a slanted segment whose line meets the plane inside, at (1, 1, 0)
  EXPECT_EQ(segment_through_triangle(Vec3(0, 0, -1), Vec3(2, 2, 1), A, B, C), 0);
  EXPECT_TRUE(plane_meeting(Vec3(0, 0, -1), Vec3(2, 2, 1), A, B, C).isApprox(Vec3(1, 1, 0)));
}

TEST(SegmentTriangle, ASegmentThatStopsShortOrTouchesDoesNotPass) {
  // both ends above, one end on the plane: no passing segment, though the line passes inside
  EXPECT_EQ(segment_through_triangle(Vec3(1, 1, 0.5), Vec3(1, 1, 1), A, B, C), -1);
  EXPECT_EQ(segment_through_triangle(Vec3(1, 1, 0), Vec3(1, 1, 1), A, B, C), -1);
  EXPECT_EQ(line_through_triangle(Vec3(1, 1, 0.5), Vec3(1, 1, 1), A, B, C), 0);
}

TEST(BoxGrid, ListsAnItemInEveryBoxItsBoxMeetsAndFindsItFromThere) {
  BoxGrid grid(Vec3::Zero(), 1.0);
  grid.insert(7, Vec3(0.5, 0.5, 0.5), Vec3(2.5, 0.5, 0.5));  // boxes x = 0, 1, 2
  grid.insert(9, Vec3(-1.5, 3.2, 0.1), Vec3(-1.4, 3.3, 0.2));  // box (-2, 3, 0)
  std::vector<std::size_t> met;
  grid.visit(Vec3(1.1, 0.1, 0.1), Vec3(1.2, 0.2, 0.2), [&](std::size_t i) { met.push_back(i); });
  EXPECT_EQ(met, std::vector<std::size_t>{7});
  met.clear();
  grid.visit(Vec3(-2, 0, 0), Vec3(3, 4, 0.5), [&](std::size_t i) { met.push_back(i); });
  std::sort(met.begin(), met.end());
  EXPECT_EQ(met, (std::vector<std::size_t>{7, 7, 7, 9}));  // once per box
  met.clear();
  grid.visit(Vec3(5, 5, 5), Vec3(6, 6, 6), [&](std::size_t i) { met.push_back(i); });
  EXPECT_TRUE(met.empty());
  int boxes = 0;
  grid.for_each_box([&](const BoxGrid::Coord& at, const std::vector<std::size_t>& items) {
    ++boxes;
    EXPECT_EQ(items.size(), 1u);
    EXPECT_EQ(grid.box_of(Vec3(at[0] + 0.5, at[1] + 0.5, at[2] + 0.5)), at);
  });
  EXPECT_EQ(boxes, 4);
}

}  // namespace
}  // namespace bisect::geom
