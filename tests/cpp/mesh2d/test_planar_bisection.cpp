// Recursive bisection triangulation (thesis 4.3): valid triangulations of polygons with nodes
// inside, every node used, the area covered exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "geom/predicates.hpp"
#include "mesh2d/bisect2d.hpp"
#include "mesh2d/shrink_nodes.hpp"

namespace bisect::mesh2d {
namespace {

void expect_triangulates(const std::vector<Vec2>& X, const std::vector<Index>& loop, const std::vector<Index>& inside) {
  std::vector<std::array<Index, 3>> tris;
  try {
    bisection_triangulate(X, loop, inside, tris);
  } catch (const std::exception& e) {
    FAIL() << e.what();
  }
  double area = 0, want = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2 &p = X[loop[i]], &q = X[loop[(i + 1) % loop.size()]];
    want += 0.5 * (p.x() * q.y() - q.x() * p.y());
  }
  std::map<std::pair<Index, Index>, int> edges;
  std::set<Index> used;
  for (const auto& t : tris) {
    EXPECT_GT(geom::orient2d(X[t[0]], X[t[1]], X[t[2]]), 0);
    const Vec2 a = X[t[1]] - X[t[0]], b = X[t[2]] - X[t[0]];
    area += 0.5 * (a.x() * b.y() - a.y() * b.x());
    for (int k = 0; k < 3; ++k) {
      ++edges[{t[k], t[(k + 1) % 3]}];
      used.insert(t[k]);
    }
  }
  EXPECT_NEAR(area, want, 1e-12 * want);
  for (const auto& [e, c] : edges) {
    EXPECT_EQ(c, 1);  // no directed edge twice: no overlap
    (void)e;
  }
  // every boundary edge is an edge of a triangle, the way round the loop goes
  for (std::size_t i = 0; i < loop.size(); ++i) EXPECT_EQ(edges.count({loop[i], loop[(i + 1) % loop.size()]}), 1u);
  EXPECT_EQ(used.size(), loop.size() + inside.size());
  // with n nodes, b of them on the boundary: 2 n - b - 2 triangles
  EXPECT_EQ(tris.size(), 2 * (loop.size() + inside.size()) - loop.size() - 2);
}

// A polygon's boundary resampled at spacing h, plus its shrinking nodes.
void sample(const std::vector<Vec2>& poly, double h, std::vector<Vec2>* X, std::vector<Index>* loop, std::vector<Index>* inside) {
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    const int steps = std::max(1, static_cast<int>(std::lround((b - a).norm() / h)));
    for (int s = 0; s < steps; ++s) {
      X->push_back(a + (b - a) * (static_cast<double>(s) / steps));
      loop->push_back(static_cast<Index>(X->size() - 1));
    }
  }
  for (const Vec2& p : shrink_nodes(poly, h, std::sqrt(3.0) / 4 * h * h)) {
    X->push_back(p);
    inside->push_back(static_cast<Index>(X->size() - 1));
  }
}

TEST(RecursiveBisection, ConvexPolygonsWithShrinkingNodes) {
  for (double h : {0.5, 0.2, 0.05}) {
    std::vector<Vec2> X;
    std::vector<Index> loop, inside;
    sample({{0, 0}, {3, 0}, {4, 2}, {2, 3.5}, {-0.5, 2}}, h, &X, &loop, &inside);
    expect_triangulates(X, loop, inside);
  }
}

TEST(RecursiveBisection, ConcavePolygonWithoutInsideNodes) {
  // a comb: vertex removal and splits between teeth
  std::vector<Vec2> X = {{0, 0}, {5, 0}, {5, 2}, {4, 2}, {4, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  std::vector<Index> loop;
  for (std::size_t i = 0; i < X.size(); ++i) loop.push_back(static_cast<Index>(i));
  expect_triangulates(X, loop, {});
}

TEST(RecursiveBisection, RandomInsideNodes) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  std::vector<Vec2> X = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<Index> loop{0, 1, 2, 3}, inside;
  for (int i = 0; i < 200; ++i) {
    X.push_back(Vec2(u(rng), u(rng)));
    inside.push_back(static_cast<Index>(X.size() - 1));
  }
  expect_triangulates(X, loop, inside);
}

}  // namespace
}  // namespace bisect::mesh2d
