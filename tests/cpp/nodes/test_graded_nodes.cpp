// Interior nodes graded from fine boundary spacing: denser near a fine boundary node, the
// shrinking's nodes unchanged far from it and when grading is off, never near the cell's faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "nodes/graded_nodes.hpp"

namespace bisect::nodes {
namespace {

Polytope unit_box() {
  Polytope p;
  p.v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  p.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  p.normal = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  p.offset = {0, 1, 0, 1, 1, 0};
  return p;
}

std::size_t within(const std::vector<Vec3>& pts, const Vec3& c, double r) {
  return static_cast<std::size_t>(std::count_if(pts.begin(), pts.end(), [&](const Vec3& p) { return (p - c).norm() < r; }));
}

TEST(GradedNodes, DenserNearAFineBoundaryNodeOnly) {
  const double np = 0.1;
  const std::vector<Polytope> cells = {unit_box()};
  const std::vector<std::vector<Vec3>> uniform = {shrink_cell_nodes(cells[0], np)};
  // boundary nodes: the middle of the bottom face wants 0.01, a corner wants np
  const Vec3 fine(0.5, 0.5, 0), coarse(0, 0, 0);
  const std::vector<Vec3> boundary = {fine, coarse};
  const std::vector<double> spacing = {0.01, np};
  GradedNodeStats st;
  const auto graded = graded_cell_nodes(cells, uniform, boundary, spacing, np, 0.5, &st);
  ASSERT_EQ(graded.size(), 1u);
  EXPECT_EQ(st.sources, 1u);
  EXPECT_GT(st.added, 10u);
  EXPECT_EQ(graded[0].size(), uniform[0].size() - st.dropped + st.added);
  // near the fine node (within 0.1) the uniform spacing has almost none; the graded ones many
  EXPECT_GT(within(graded[0], fine, 0.1), within(uniform[0], fine, 0.1) + 10);
  // away from it (beyond where the size is back to np) the nodes are the shrinking's
  std::size_t far_uniform = 0, far_graded = 0;
  for (const Vec3& p : uniform[0]) far_uniform += (p - fine).norm() > 0.4;
  for (const Vec3& p : graded[0]) far_graded += (p - fine).norm() > 0.4;
  EXPECT_EQ(far_graded, far_uniform);
  // every graded node at least half its size inside the cell, and sized by its distance
  for (std::size_t i = uniform[0].size() - st.dropped; i < graded[0].size(); ++i) {
    const Vec3& p = graded[0][i];
    const double h = std::min(np, 0.01 + 0.5 * (p - fine).norm());
    const double depth = std::min({p.x(), p.y(), p.z(), 1 - p.x(), 1 - p.y(), 1 - p.z()});
    EXPECT_GE(depth, 0.5 * h - 1e-12);
  }
  // deterministic
  EXPECT_TRUE(graded_cell_nodes(cells, uniform, boundary, spacing, np, 0.5) == graded);
}

TEST(GradedNodes, OffOrWithoutFineNodesTheShrinkingsNodesStay) {
  const double np = 0.1;
  const std::vector<Polytope> cells = {unit_box()};
  const std::vector<std::vector<Vec3>> uniform = {shrink_cell_nodes(cells[0], np)};
  EXPECT_TRUE(graded_cell_nodes(cells, uniform, {Vec3(0.5, 0.5, 0)}, {0.01}, np, 0) == uniform);
  GradedNodeStats st;
  EXPECT_TRUE(graded_cell_nodes(cells, uniform, {Vec3(0.5, 0.5, 0)}, {np}, np, 0.5, &st) == uniform);
  EXPECT_EQ(st.sources, 0u);
}

}  // namespace
}  // namespace bisect::nodes
