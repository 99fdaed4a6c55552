// Planar grid improvement (thesis 4.4): vertex swapping and guarded Laplace smoothing keep the
// mesh valid, keep boundaries and interfaces, and raise the smallest angle.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "geom/predicates.hpp"
#include "mesh2d/quads.hpp"
#include "mesh2d/smooth.hpp"
#include "mesh2d/swap.hpp"
#include "mesh2d/tri_quality.hpp"

namespace bisect::mesh2d {
namespace {

// An n x n grid of squares over [0, n]^2, each split along a random diagonal, interior nodes
// moved by up to `jitter`; cells with x < split belong to region 0, the rest to region 1; the
// cells listed in `holes` are left out.
TriMesh2 grid(int n, double jitter, unsigned seed, int split = 1 << 30, std::set<std::pair<int, int>> holes = {}) {
  TriMesh2 m;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool edge = i == 0 || j == 0 || i == n || j == n;
      m.nodes.push_back(Vec2(i + (edge ? 0 : u(rng)), j + (edge ? 0 : u(rng))));
      m.fixed.push_back(edge);
    }
  auto id = [&](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (holes.count({i, j})) continue;
      const Index a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      const Index region = i < split ? 0 : 1;
      if (rng() % 2) {
        m.tris.push_back({a, b, c}), m.tris.push_back({a, c, d});
      } else {
        m.tris.push_back({a, b, d}), m.tris.push_back({b, c, d});
      }
      m.tri_region.push_back(region), m.tri_region.push_back(region);
    }
  return m;
}

// Boundary and interface edges (one triangle, or two regions).
std::set<std::pair<Index, Index>> fixed_edges(const TriMesh2& m) {
  std::map<std::pair<Index, Index>, std::vector<Index>> e;
  for (std::size_t t = 0; t < m.tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index a = m.tris[t][k], b = m.tris[t][(k + 1) % 3];
      e[{std::min(a, b), std::max(a, b)}].push_back(m.tri_region[t]);
    }
  std::set<std::pair<Index, Index>> out;
  for (const auto& [k, r] : e)
    if (r.size() != 2 || r[0] != r[1]) out.insert(k);
  return out;
}

void expect_valid(const TriMesh2& m, double area) {
  std::map<std::pair<Index, Index>, int> e;
  for (const auto& t : m.tris) {
    EXPECT_GT(geom::orient2d(m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]]), 0);
    for (int k = 0; k < 3; ++k) ++e[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  }
  for (const auto& q : m.quads)
    for (int k = 0; k < 4; ++k) {
      EXPECT_GT(geom::orient2d(m.nodes[q[(k + 3) % 4]], m.nodes[q[k]], m.nodes[q[(k + 1) % 4]]), 0);  // convex
      ++e[{std::min(q[k], q[(k + 1) % 4]), std::max(q[k], q[(k + 1) % 4])}];
    }
  for (const auto& [k, c] : e) EXPECT_LE(c, 2);
  EXPECT_NEAR(total_area(m), area, 1e-12 * area);
}

TEST(VertexSwap, RaisesTheSmallestAngleAndKeepsBoundaries) {
  TriMesh2 m = grid(20, 0.3, 1);
  const double area = total_area(m), before = min_angle_deg(m);
  const auto kept = fixed_edges(m);
  const SwapStats st = swap_edges(m);
  EXPECT_GT(st.swaps, 0);
  EXPECT_GT(min_angle_deg(m), before);
  expect_valid(m, area);
  EXPECT_EQ(fixed_edges(m), kept);
  // the result is locally optimal: no swap improves it any further
  EXPECT_EQ(swap_edges(m).swaps, 0);
}

TEST(VertexSwap, NeighbourFirstNeedsNoMorePasses) {
  TriMesh2 a = grid(30, 0.35, 5), b = a;
  SwapOptions plain;
  plain.neighbour_first = false;
  const SwapStats sa = swap_edges(a), sb = swap_edges(b, plain);
  EXPECT_LE(sa.passes, sb.passes);
  EXPECT_NEAR(min_angle_deg(a), min_angle_deg(b), 5.0);  // both end max-min optimal or near it
}

TEST(VertexSwap, CocircularSquaresTerminate) {
  TriMesh2 m = grid(12, 0.0, 2);  // every quad is a square: both diagonals equally good
  const SwapStats st = swap_edges(m);
  EXPECT_EQ(st.swaps, 0);
  EXPECT_NEAR(min_angle_deg(m), 45.0, 1e-12);
}

TEST(VertexSwap, InterfacesAndHolesStay) {
  TriMesh2 m = grid(16, 0.3, 3, 8, {{5, 5}, {5, 6}, {6, 5}, {6, 6}});
  const double area = total_area(m);
  const auto kept = fixed_edges(m);
  swap_edges(m);
  expect_valid(m, area);
  EXPECT_EQ(fixed_edges(m), kept);
}

TEST(LaplaceSmoothing, ImprovesAPerturbedGridWithoutInverting) {
  TriMesh2 m = grid(20, 0.4, 4);
  swap_edges(m);
  const double area = total_area(m), before = min_angle_deg(m);
  const SmoothStats st = smooth_laplace(m);
  EXPECT_GT(st.moves, 0);
  expect_valid(m, area);
  EXPECT_GE(min_angle_deg(m), before);
  for (std::size_t v = 0; v < m.nodes.size(); ++v)
    if (m.fixed[v]) {
      EXPECT_EQ(m.nodes[v], grid(20, 0.4, 4).nodes[v]);
    }
}

TEST(LaplaceSmoothing, ConcaveRegionAndHoleStayValid) {
  // an L: the upper right quarter of the grid removed; and a hole in the lower left
  std::set<std::pair<int, int>> cut;
  for (int i = 8; i < 16; ++i)
    for (int j = 8; j < 16; ++j) cut.insert({i, j});
  cut.insert({2, 2}), cut.insert({3, 2});
  TriMesh2 m = grid(16, 0.45, 6, 1 << 30, cut);
  const double area = total_area(m);
  const auto kept = fixed_edges(m);
  swap_edges(m);
  smooth_laplace(m, {10});
  swap_edges(m);
  expect_valid(m, area);
  EXPECT_EQ(fixed_edges(m), kept);
  EXPECT_GT(min_angle_deg(m), 20.0);
}

TEST(WalkingQuads, NoAngleUnderTwentyDegreesAreaKept) {
  TriMesh2 m = grid(20, 0.3, 8, 10, {{4, 4}, {4, 5}});
  swap_edges(m);
  const double area = total_area(m);
  const std::size_t tris = m.tris.size();
  const QuadStats st = make_quads(m);
  EXPECT_GT(st.quads, static_cast<std::int64_t>(tris / 4));  // most triangles pair up
  EXPECT_EQ(static_cast<std::size_t>(2 * st.quads + st.triangles_left), tris);
  expect_valid(m, area);
  for (const auto& q : m.quads) {
    TriMesh2 one;
    one.nodes = m.nodes;
    one.quads = {q};
    EXPECT_GE(min_angle_deg(one), 20.0);
  }
  // no quad mixes the two regions (cells with x < 10 are region 0; nodes moved by under 0.3)
  ASSERT_EQ(m.quads.size(), m.quad_region.size());
  for (std::size_t q = 0; q < m.quads.size(); ++q) {
    Vec2 c = Vec2::Zero();
    for (Index v : m.quads[q]) c += m.nodes[v] / 4;
    if (m.quad_region[q] == 0) EXPECT_LT(c.x(), 10.3);
    else EXPECT_GT(c.x(), 9.7);
  }
}

TEST(WalkingQuads, StructuredGridBecomesAllQuads) {
  TriMesh2 m = grid(10, 0.0, 9);
  const QuadStats st = make_quads(m, {20, 0});
  EXPECT_EQ(st.quads, 100);  // every pair of triangles is a unit square
  EXPECT_EQ(st.triangles_left, 0);
  EXPECT_NEAR(st.min_angle_deg, 90.0, 1e-9);
}

}  // namespace
}  // namespace bisect::mesh2d
