// Interior nodes graded from fine boundary spacing: denser near a fine boundary node, the
// shrinking's nodes unchanged far from it and when grading is off, never near the cell's faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
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


// Many sources over several cells (the size field through its k-d tree, the cell through its
// bucket grid): every graded node lies in the cell it is given to, at least half its size inside,
// the size by a scan of all sources; and it takes a fraction of a second.
TEST(GradedNodes, ManySourcesOverSeveralCells) {
  const double np = 0.1;
  std::vector<Polytope> cells;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      Polytope p = unit_box();
      for (Vec3& v : p.v) v += Vec3(i, j, 0);
      for (std::size_t f = 0; f < p.normal.size(); ++f) p.offset[f] += p.normal[f].dot(Vec3(i, j, 0));
      cells.push_back(p);
    }
  std::vector<std::vector<Vec3>> uniform;
  for (const Polytope& c : cells) uniform.push_back(shrink_cell_nodes(c, np));
  std::vector<Vec3> boundary;
  std::vector<double> spacing;
  for (int k = 0; k < 600; ++k) {  // a fine seam along the bottom, sizes from 0.005 to 0.05
    boundary.push_back(Vec3(0.1 + 1.8 * k / 599.0, 0.5 + 0.5 * std::sin(k * 0.05), 0));
    spacing.push_back(0.005 + 0.045 * ((k * 37) % 100) / 100.0);
  }
  const auto t0 = std::chrono::steady_clock::now();
  GradedNodeStats st;
  const auto graded = graded_cell_nodes(cells, uniform, boundary, spacing, np, 0.3, &st);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0);
  EXPECT_EQ(st.sources, 600u);
  EXPECT_GT(st.added, 100u);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::size_t first = uniform[c].size() - std::count_if(uniform[c].begin(), uniform[c].end(), [&](const Vec3& p) {
                                return std::find(graded[c].begin(), graded[c].end(), p) == graded[c].end();
                              });
    for (std::size_t i = first; i < graded[c].size(); ++i) {
      const Vec3& p = graded[c][i];
      double h = np;
      for (std::size_t v = 0; v < boundary.size(); ++v) h = std::min(h, spacing[v] + 0.3 * (p - boundary[v]).norm());
      double depth = 1e300;
      for (std::size_t f = 0; f < cells[c].normal.size(); ++f) depth = std::min(depth, cells[c].offset[f] - cells[c].normal[f].dot(p));
      EXPECT_GE(depth, 0.5 * h - 1e-12) << "cell " << c;
    }
  }
  EXPECT_TRUE(graded_cell_nodes(cells, uniform, boundary, spacing, np, 0.3) == graded);
}

}  // namespace
}  // namespace bisect::nodes
