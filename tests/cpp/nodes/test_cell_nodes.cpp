// 3D convex domain shrinking (thesis 7.4): polytope clipping, layers of nodes inside the cell at
// the spacing, sharp edges cut off, thin layers as one sheet, gaps wider than the spacing a sheet
// or a line through their middle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "nodes/cell_nodes.hpp"

namespace bisect::nodes {
namespace {

// An axis-aligned box as a polytope (faces counter-clockwise from outside).
Polytope box(double x, double y, double z) {
  Polytope p;
  p.v = {{0, 0, 0}, {x, 0, 0}, {x, y, 0}, {0, y, 0}, {0, 0, z}, {x, 0, z}, {x, y, z}, {0, y, z}};
  p.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  p.normal = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  p.offset = {0, z, 0, x, y, 0};
  return p;
}

// how far the jitter moves a node of spacing 0.1 along one axis, at most
constexpr double kShift = 0.5 * kNodeJitter * 0.1 + 1e-12;

double min_gap(const std::vector<Vec3>& pts) {
  double g = 1e300;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) g = std::min(g, (pts[i] - pts[j]).norm());
  return g;
}

TEST(CellNodes, ClipKeepsTheLowerPart) {
  const Polytope cube = box(1, 1, 1);
  EXPECT_NEAR(cube.volume(), 1, 1e-12);
  EXPECT_NEAR(cube.area(), 6, 1e-12);
  const Polytope half = clip(cube, Vec3(0, 0, 1), 0.5, 1);
  EXPECT_NEAR(half.volume(), 0.5, 1e-12);
  EXPECT_EQ(half.faces.size(), 6u);
  const Vec3 n = Vec3(1, 1, 1).normalized();
  const Polytope tip = clip(cube, n, n.dot(Vec3(1, 0, 0)), 1);  // the corner tetrahedron at the origin
  EXPECT_NEAR(tip.volume(), 1.0 / 6, 1e-12);
  EXPECT_EQ(tip.faces.size(), 4u);
  EXPECT_TRUE(clip(cube, Vec3(0, 0, 1), -0.1, 1).faces.empty());  // all of it above the plane
}

TEST(CellNodes, BoxGetsLayersInsideAtTheSpacing) {
  const double np = 0.1;
  const std::vector<Vec3> nodes = shrink_cell_nodes(box(1, 1, 1), np);
  ASSERT_FALSE(nodes.empty());
  for (const Vec3& p : nodes) {
    const double d = std::min({p.x(), p.y(), p.z(), 1 - p.x(), 1 - p.y(), 1 - p.z()});
    EXPECT_GT(d, np - kShift);  // layer 1 and deeper
  }
  EXPECT_GT(min_gap(nodes), 0.5 * np - 2 * kShift * std::sqrt(3.0));
  // about one node per np^3 inside the first layer (0.8^3 / 0.001 = 512), within a factor 2
  EXPECT_GT(nodes.size(), 250u);
  EXPECT_LT(nodes.size(), 1100u);
}

TEST(CellNodes, ThinCellGetsOneSheetAndTinyCellNone) {
  const double np = 0.1;
  const std::vector<Vec3> sheet = shrink_cell_nodes(box(1, 1, 0.24), np);  // layer 1 is 0.04 thick
  ASSERT_FALSE(sheet.empty());
  for (const Vec3& p : sheet) EXPECT_NEAR(p.z(), 0.12, kShift);
  EXPECT_GT(min_gap(sheet), 0.5 * np - 2 * kShift * std::sqrt(3.0));
  EXPECT_TRUE(shrink_cell_nodes(box(0.09, 0.09, 0.09), np).empty());  // no gap as wide as np
}

TEST(CellNodes, GapWiderThanTheSpacingGetsNodesThroughItsMiddle) {
  const double np = 0.1;
  // 1.5 spacings each way: no layer at np, one node at the centre
  const std::vector<Vec3> one = shrink_cell_nodes(box(0.15, 0.15, 0.15), np);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NEAR((one[0] - Vec3(0.075, 0.075, 0.075)).norm(), 0, std::sqrt(3.0) * kShift);
  // a 1.5 x 1.5 x 10 spacings bar: one line of nodes along its axis, np apart, from 0.05 to 0.95
  const std::vector<Vec3> line = shrink_cell_nodes(box(0.15, 0.15, 1.0), np);
  ASSERT_GE(line.size(), 8u);
  ASSERT_LE(line.size(), 11u);
  double lo = 1, hi = 0;
  for (const Vec3& p : line) {
    EXPECT_NEAR(p.x(), 0.075, kShift);
    EXPECT_NEAR(p.y(), 0.075, kShift);
    lo = std::min(lo, p.z()), hi = std::max(hi, p.z());
  }
  EXPECT_NEAR(lo, 0.05, kShift);
  EXPECT_NEAR(hi, 0.95, kShift);
  EXPECT_GT(min_gap(line), 0.9 * np - 2 * kShift * std::sqrt(3.0));
  // a slab 3.5 spacings thick: layers at np and 2 np from each side, 1.5 np apart, and a sheet
  // half way between them
  const std::vector<Vec3> slab = shrink_cell_nodes(box(1, 1, 0.35), np);
  std::size_t middle = 0;
  for (const Vec3& p : slab) middle += std::abs(p.z() - 0.175) < kShift;
  EXPECT_GT(middle, 20u);
}

TEST(CellNodes, SharpWedgeKeepsClearOfItsEdge) {
  // a wedge whose edge along z has a 10 degree angle: nodes stay away from that edge
  const double t = std::tan(10.0 * M_PI / 180);
  Polytope w;
  w.v = {{0, 0, 0}, {4, 0, 0}, {4, 4 * t, 0}, {0, 0, 1}, {4, 0, 1}, {4, 4 * t, 1}};
  w.faces = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  const Vec3 slanted = Vec3(-t, 1, 0).normalized();
  w.normal = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {1, 0, 0}, slanted};
  w.offset = {0, 1, 0, 4, 0};
  const double np = 0.1;
  const std::vector<Vec3> nodes = shrink_cell_nodes(w, np);
  ASSERT_FALSE(nodes.empty());
  for (const Vec3& p : nodes) EXPECT_GT(p.x(), 0.5 * np / std::tan(5.0 * M_PI / 180) - kShift);
  EXPECT_GT(min_gap(nodes), 0.5 * np - 2 * kShift * std::sqrt(3.0));
}

}  // namespace
}  // namespace bisect::nodes
