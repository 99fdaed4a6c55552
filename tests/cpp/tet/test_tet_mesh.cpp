// TetMesh: appending tetrahedra and face adjacency.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "bisect/tet_mesh.hpp"
#include "tet/tet_test_meshes.hpp"

namespace bisect {
namespace {

std::array<Index, 3> sorted_face(const TetMesh& m, std::size_t t, int f) {
  std::array<Index, 3> v{m.tet_node(t, kTetFace[f][0]), m.tet_node(t, kTetFace[f][1]), m.tet_node(t, kTetFace[f][2])};
  std::sort(v.begin(), v.end());
  return v;
}

TEST(TetMesh, LocalNumberingFacesPointOutward) {
  // kTetFace[f] turns so that its right-hand normal points away from corner f, for the
  // positively oriented right-corner tetrahedron.
  const std::array<Vec3, 4> p{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  ASSERT_GT(test::six_volume(p[0], p[1], p[2], p[3]), 0);
  for (int f = 0; f < 4; ++f) {
    const auto& v = kTetFace[f];
    const Vec3 n = (p[v[1]] - p[v[0]]).cross(p[v[2]] - p[v[0]]);
    EXPECT_LT(n.dot(p[f] - p[v[0]]), 0) << "face " << f;
  }
}

TEST(TetMesh, AddTetAppendsNodesAndRegion) {
  TetMesh m;
  m.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
  const Index a[4] = {0, 1, 2, 3}, b[4] = {1, 2, 3, 4};
  EXPECT_EQ(m.add_tet(a), 0);
  EXPECT_EQ(m.add_tet(b, 3), 1);
  EXPECT_EQ(m.num_tets(), 2u);
  EXPECT_EQ(m.tets, (std::vector<Index>{0, 1, 2, 3, 1, 2, 3, 4}));
  EXPECT_EQ(m.region, (std::vector<Index>{0, 3}));
  EXPECT_EQ(m.tet_node(1, 3), 4);
  EXPECT_EQ(m.tet_id(1), 2);
  EXPECT_TRUE(m.tet_ids.empty());
}

TEST(TetMesh, AddTetOrder2TakesTenNodes) {
  TetMesh m;
  m.order = 2;
  const Index v[10] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  EXPECT_EQ(m.add_tet(v, 2), 0);
  EXPECT_EQ(m.add_tet(v), 1);
  EXPECT_EQ(m.tets.size(), 20u);
  EXPECT_EQ(m.num_tets(), 2u);
  EXPECT_EQ(m.tet_node(1, 9), 9);
  EXPECT_EQ(m.region, (std::vector<Index>{2, 0}));
}

TEST(TetMesh, AddTetKeepsParallelArraysAligned) {
  // A reader filled tets and file numbers but no regions: the appended tetrahedron still gets
  // region[t] and a file number after the last one.
  TetMesh m;
  m.tets = {0, 1, 2, 3};
  m.tet_ids = {41};
  const Index v[4] = {0, 1, 2, 4};
  EXPECT_EQ(m.add_tet(v, 5), 1);
  EXPECT_EQ(m.region, (std::vector<Index>{0, 5}));
  EXPECT_EQ(m.tet_ids, (std::vector<std::int64_t>{41, 42}));
  EXPECT_EQ(m.tet_id(1), 42);
}

TEST(TetMesh, NeighboursOfTwoTets) {
  const TetMesh m = test::two_tet_mesh();
  const auto n = m.neighbours();
  ASSERT_EQ(n.size(), 8u);
  // Face 3 of tet 0 (0 2 1, opposite node 3) is face 3 of tet 1 (0 1 2, opposite node 4).
  EXPECT_EQ(n[4 * 0 + 3], 4 * 1 + 3);
  EXPECT_EQ(n[4 * 1 + 3], 4 * 0 + 3);
  for (int k : {0, 1, 2, 4, 5, 6}) EXPECT_EQ(n[k], -1) << k;
}

TEST(TetMesh, NeighboursOfEmptyMesh) { EXPECT_TRUE(TetMesh().neighbours().empty()); }

TEST(TetMesh, NeighboursOfCubeMesh) {
  for (int k : {1, 3}) {
    SCOPED_TRACE(k);
    const TetMesh m = test::cube_mesh(k);
    const auto n = m.neighbours();
    ASSERT_EQ(n.size(), 4 * m.num_tets());
    std::size_t boundary = 0;
    for (std::size_t c = 0; c < n.size(); ++c) {
      if (n[c] < 0) {
        ++boundary;
        continue;
      }
      ASSERT_LT(std::size_t(n[c]), n.size());
      EXPECT_EQ(n[n[c]], Index(c));
      EXPECT_NE(n[c] / 4, Index(c / 4));
      EXPECT_EQ(sorted_face(m, c / 4, int(c % 4)), sorted_face(m, n[c] / 4, n[c] % 4));
    }
    // Every boundary square is cut into two triangles.
    EXPECT_EQ(boundary, 2u * 6 * k * k);
  }
}

TEST(TetMesh, NeighboursOfOrder2MeshIgnoreMidNodes) {
  const TetMesh linear = test::cube_mesh(2);
  EXPECT_EQ(test::to_order2(linear).neighbours(), linear.neighbours());
}

TEST(TetMesh, NeighboursOfNonManifoldFaceLinkOnlyTheFirstPair) {
  TetMesh m = test::two_tet_mesh();
  m.nodes.emplace_back(0.1, 0.1, 2);
  const Index third[4] = {0, 1, 2, 5};
  m.add_tet(third);
  const auto n = m.neighbours();
  EXPECT_EQ(n[3], 4 + 3);
  EXPECT_EQ(n[4 + 3], 3);
  EXPECT_EQ(n[8 + 3], -1);
}

TEST(TetMesh, NeighboursSkipFacesWithMissingNodes) {
  TetMesh m = test::two_tet_mesh();
  m.tets[7] = 99;  // tet 1's apex
  m.tets[4] = -1;  // and its node 0
  const auto n = m.neighbours();
  for (int k = 4; k < 8; ++k) EXPECT_EQ(n[k], -1);
  EXPECT_EQ(n[3], -1);
}

}  // namespace
}  // namespace bisect
