// The check that a cell's boundary crosses itself (tet/boundary_crossing.hpp), which names why
// no fill can take a cell when every fill has failed.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "tet/boundary_crossing.hpp"

namespace bisect::tet {
namespace {

// The surface of the tetrahedron (a, b, c, d), positively oriented, counter-clockwise from outside.
void add_tet(std::vector<Vec3>* X, std::vector<std::array<Index, 3>>* tris, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Index o = static_cast<Index>(X->size());
  X->insert(X->end(), {a, b, c, d});
  tris->push_back({o + 1, o + 2, o + 3});
  tris->push_back({o, o + 3, o + 2});
  tris->push_back({o, o + 1, o + 3});
  tris->push_back({o, o + 2, o + 1});
}

TEST(BoundaryCrossing, AClosedSurfaceDoesNotCrossItself) {
  std::vector<Vec3> X;
  std::vector<std::array<Index, 3>> tris;
  add_tet(&X, &tris, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
  EXPECT_FALSE(boundary_crossing(X, tris));
  // a second, apart from the first: still no crossing
  add_tet(&X, &tris, Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(2, 1, 0), Vec3(2, 0, 1));
  EXPECT_FALSE(boundary_crossing(X, tris));
}

TEST(BoundaryCrossing, FindsAnEdgeThroughAnotherTriangleAndWhere) {
  std::vector<Vec3> X;
  std::vector<std::array<Index, 3>> tris;
  add_tet(&X, &tris, Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 4, 0), Vec3(0, 0, 4));
  // a small tetrahedron whose vertical edge at (1, 1) passes through the first's bottom z = 0
  add_tet(&X, &tris, Vec3(1, 1, -1), Vec3(1.5, 1, -1), Vec3(1, 1.5, -1), Vec3(1, 1, 1));
  const auto x = boundary_crossing(X, tris);
  ASSERT_TRUE(x);
  // only the small one's three edges from (1, 1, 1) cross anything: the big one's bottom, z = 0,
  // inside the small one's shadow
  EXPECT_EQ(x->crossed, 3u) << "the big tetrahedron's bottom";
  EXPECT_GE(x->edge_triangle, 4u) << "an edge of the small tetrahedron";
  EXPECT_NEAR(x->at.z(), 0, 1e-12);
  EXPECT_GE(x->at.x(), 1 - 1e-12);
  EXPECT_GE(x->at.y(), 1 - 1e-12);
  EXPECT_LE(x->at.x() + x->at.y(), 2.5 + 1e-12);
}

}  // namespace
}  // namespace bisect::tet
