// The mesh validator: valid meshes pass clean, and each kind of violation is produced by a small
// broken mesh and reported with the right ids.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>

#include <string>

#include "bisect/errors.hpp"
#include "bisect/validate.hpp"
#include "tet/tet_test_meshes.hpp"

namespace bisect {
namespace {

using Ids = std::vector<std::int64_t>;

std::string describe(const std::vector<Violation>& v) {
  std::string s;
  for (const auto& x : v) s += std::string(to_string(x.kind)) + ": " + x.message + "\n";
  return s;
}

std::vector<Violation> of_kind(const std::vector<Violation>& v, ViolationKind k) {
  std::vector<Violation> out;
  for (const auto& x : v)
    if (x.kind == k) out.push_back(x);
  return out;
}

TEST(Validate, TwoTetMeshIsValid) {
  const auto v = validate(test::two_tet_mesh());
  EXPECT_TRUE(v.empty()) << describe(v);
}

TEST(Validate, EmptyMeshIsValid) { EXPECT_TRUE(validate(TetMesh()).empty()); }

TEST(Validate, CubeMeshIsValid) {
  for (int k : {1, 2, 4}) {
    const auto v = validate(test::cube_mesh(k));
    EXPECT_TRUE(v.empty()) << "k = " << k << "\n" << describe(v);
  }
}

TEST(Validate, Order2CubeMeshIsValid) {
  // Mid-edge nodes are used only in slots 4..9: they must count as used.
  const auto v = validate(test::to_order2(test::cube_mesh(2)));
  EXPECT_TRUE(v.empty()) << describe(v);
}

TEST(Validate, ReportsProgressAndStops) {
  // cube_mesh(20): 48,000 tetrahedra, order 2: the passes report in order, from 0 to 1
  const TetMesh m = test::to_order2(test::cube_mesh(20));
  std::vector<double> seen;
  const std::function<bool(double)> record = [&seen](double x) { return seen.push_back(x), true; };
  EXPECT_TRUE(validate(m, record).empty());
  ASSERT_GE(seen.size(), 9u);  // one report per pass and the end, at least
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  // a Stop inside: the check ends with Cancelled, not with a verdict
  const std::function<bool(double)> stop_after_elements = [](double x) { return x < 0.1; };
  EXPECT_THROW(validate(m, stop_after_elements), Cancelled);
}

TEST(Validate, InvertedTet) {
  TetMesh m = test::cube_mesh(2);
  std::swap(m.tets[4 * 5 + 1], m.tets[4 * 5 + 2]);  // tetrahedron index 5, id 6
  const auto v = validate(m);
  ASSERT_EQ(v.size(), 1u) << describe(v);
  EXPECT_EQ(v[0].kind, ViolationKind::InvertedTet);
  EXPECT_EQ(v[0].ids, Ids{6});
  EXPECT_NE(v[0].message.find("tetrahedron 6"), std::string::npos) << v[0].message;
}

TEST(Validate, InvertedTetReportedByFileNumber) {
  TetMesh m = test::two_tet_mesh();
  m.tet_ids = {100, 200};
  m.node_ids = {11, 12, 13, 14, 15};
  std::swap(m.tets[4], m.tets[5]);
  const auto v = validate(m);
  ASSERT_EQ(v.size(), 1u) << describe(v);
  EXPECT_EQ(v[0].kind, ViolationKind::InvertedTet);
  EXPECT_EQ(v[0].ids, Ids{200});
  // Nodes by their file numbers, with coordinates.
  EXPECT_NE(v[0].message.find("15 (0.3, 0.2, -1)"), std::string::npos) << v[0].message;
}

TEST(Validate, ZeroVolumeTet) {
  TetMesh m;
  m.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  const Index flat[4] = {0, 1, 2, 3};
  m.add_tet(flat);
  const auto v = validate(m);
  ASSERT_EQ(v.size(), 1u) << describe(v);
  EXPECT_EQ(v[0].kind, ViolationKind::ZeroVolumeTet);
  EXPECT_EQ(v[0].ids, Ids{1});
}

TEST(Validate, NearlyFlatTetIsNotZeroVolume) {
  // Exact orientation: a lift far below any floating-point tolerance still counts.
  TetMesh m;
  m.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.3, 0.3, 1e-300)};
  const Index t[4] = {0, 1, 2, 3};
  m.add_tet(t);
  EXPECT_TRUE(validate(m).empty()) << describe(validate(m));
}

TEST(Validate, BadNodeIndex) {
  TetMesh m = test::two_tet_mesh();
  m.tets[7] = 5;  // one past the last node
  m.tris = {0, 1, 2, 0, 1, -3};
  m.tri_tag = {0, 0};
  const auto v = validate(m);
  // Node 4 is now unused too; the broken tetrahedron is kept out of the face checks.
  ASSERT_EQ(v.size(), 3u) << describe(v);
  EXPECT_EQ(v[0].kind, ViolationKind::BadNodeIndex);
  EXPECT_EQ(v[1].kind, ViolationKind::BadNodeIndex);
  // Equal kind and ids keep detection order: tetrahedra before triangles.
  EXPECT_EQ(v[0].ids, Ids{2});
  EXPECT_NE(v[0].message.find("tetrahedron 2"), std::string::npos) << v[0].message;
  EXPECT_NE(v[0].message.find("5"), std::string::npos);
  EXPECT_EQ(v[1].ids, Ids{2});
  EXPECT_NE(v[1].message.find("triangle 2"), std::string::npos) << v[1].message;
  EXPECT_NE(v[1].message.find("-3"), std::string::npos);
  EXPECT_EQ(v[2].kind, ViolationKind::UnusedNode);
  EXPECT_EQ(v[2].ids, Ids{5});
}

TEST(Validate, RepeatedNode) {
  TetMesh m = test::two_tet_mesh();
  m.tets[6] = 0;  // tetrahedron 2 becomes 0 2 0 4
  const auto v = validate(m);
  ASSERT_EQ(v.size(), 1u) << describe(v);
  EXPECT_EQ(v[0].kind, ViolationKind::RepeatedNode);
  EXPECT_EQ(v[0].ids, Ids{2});
}

TEST(Validate, RemovingATetKeepsTheBoundaryClosed) {
  // Removing any tetrahedron, a corner one or one deep inside (a cavity), leaves a closed
  // boundary: the faces it shared become boundary faces of its neighbours.
  const TetMesh m = test::cube_mesh(3);
  for (std::size_t t : {std::size_t(0), std::size_t(6 * 13 + 2), m.num_tets() - 1}) {
    const auto v = validate(test::without_tet(m, t));
    EXPECT_TRUE(v.empty()) << "removed " << t << "\n" << describe(v);
  }
}

TEST(Validate, NonManifoldFaceAndOpenBoundary) {
  // Three tetrahedra on the face 0 1 2. The face is then no boundary face (used by 3), so its
  // three edges are each used by 3 boundary faces (the side faces through it): open.
  TetMesh m = test::two_tet_mesh();
  m.nodes.emplace_back(0.1, 0.1, 2);
  const Index third[4] = {0, 1, 2, 5};
  m.add_tet(third);
  const auto v = validate(m);
  ASSERT_EQ(v.size(), 4u) << describe(v);
  EXPECT_EQ(v[0].kind, ViolationKind::NonManifoldFace);
  EXPECT_EQ(v[0].ids, (Ids{1, 2, 3}));
  EXPECT_NE(v[0].message.find("1 2 3"), std::string::npos) << v[0].message;
  const auto open = of_kind(v, ViolationKind::OpenBoundary);
  ASSERT_EQ(open.size(), 3u);
  EXPECT_EQ(open[0].ids, (Ids{1, 2}));
  EXPECT_EQ(open[1].ids, (Ids{1, 3}));
  EXPECT_EQ(open[2].ids, (Ids{2, 3}));
  EXPECT_NE(open[0].message.find("3 boundary faces"), std::string::npos) << open[0].message;
}

TEST(Validate, FourTetsOnAFaceAreNonManifoldButEven) {
  TetMesh m = test::two_tet_mesh();
  m.nodes.emplace_back(0.1, 0.1, 2);
  m.nodes.emplace_back(0.1, 0.1, -2);
  const Index third[4] = {0, 1, 2, 5}, fourth[4] = {0, 2, 1, 6};
  m.add_tet(third);
  m.add_tet(fourth);
  const auto v = validate(m);
  ASSERT_EQ(v.size(), 1u) << describe(v);
  EXPECT_EQ(v[0].kind, ViolationKind::NonManifoldFace);
  EXPECT_EQ(v[0].ids, (Ids{1, 2, 3, 4}));
}

TEST(Validate, DuplicateNodeCrack) {
  // The second tetrahedron uses a copy of node 2 (index 1): the shared face splits into two
  // boundary faces, a crack only the coordinates reveal.
  TetMesh m = test::two_tet_mesh();
  m.nodes.push_back(m.nodes[1]);
  m.tets[6] = 5;
  const auto v = validate(m);
  ASSERT_EQ(v.size(), 1u) << describe(v);
  EXPECT_EQ(v[0].kind, ViolationKind::DuplicateNode);
  EXPECT_EQ(v[0].ids, (Ids{2, 6}));
  EXPECT_NE(v[0].message.find("(1, 0, 0)"), std::string::npos) << v[0].message;
}

TEST(Validate, SeparateBodiesMayTouch) {
  // two tetrahedra that share no node, the second's corner on the first's: two bodies touching
  // (an assembly's parts meshed apart), no crack; the same copy inside one body is one
  TetMesh m;
  m.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0), Vec3(1, 0, 1)};
  const Index a[4] = {0, 1, 2, 3}, b[4] = {4, 5, 6, 7};
  m.add_tet(a);
  m.add_tet(b);
  EXPECT_TRUE(validate(m).empty()) << describe(validate(m));
  const Index bridge[4] = {1, 5, 6, 7};  // joins the bodies through node 1: nodes 2 and 5 are one body's now
  m.add_tet(bridge);
  const auto dup = of_kind(validate(m), ViolationKind::DuplicateNode);
  ASSERT_EQ(dup.size(), 1u) << describe(validate(m));
  EXPECT_EQ(dup[0].ids, (Ids{2, 5}));
}

TEST(Validate, DuplicateNodesInGroupsAndNegativeZero) {
  TetMesh m = test::two_tet_mesh();
  m.node_ids = {10, 20, 30, 40, 50};
  // Two unused copies of node 10, one written with -0: the same point.
  m.nodes.emplace_back(-0.0, 0, 0);
  m.nodes.emplace_back(0, 0, 0);
  m.node_ids.push_back(5);
  m.node_ids.push_back(60);
  const auto v = validate(m);
  const auto dup = of_kind(v, ViolationKind::DuplicateNode);
  ASSERT_EQ(dup.size(), 1u) << describe(v);
  EXPECT_EQ(dup[0].ids, (Ids{5, 10, 60}));
  const auto unused = of_kind(v, ViolationKind::UnusedNode);
  ASSERT_EQ(unused.size(), 2u) << describe(v);
  EXPECT_EQ(unused[0].ids, Ids{5});
  EXPECT_EQ(unused[1].ids, Ids{60});
}

TEST(Validate, NaNCoordinatesAreNoDuplicates) {
  TetMesh m = test::two_tet_mesh();
  m.nodes.emplace_back(std::nan(""), 0, 0);
  m.nodes.emplace_back(std::nan(""), 0, 0);
  const auto v = validate(m);
  EXPECT_TRUE(of_kind(v, ViolationKind::DuplicateNode).empty()) << describe(v);
  EXPECT_EQ(of_kind(v, ViolationKind::UnusedNode).size(), 2u);
  EXPECT_EQ(of_kind(v, ViolationKind::NonFiniteNode).size(), 2u);
}

TEST(Validate, UnusedNode) {
  TetMesh m = test::two_tet_mesh();
  m.nodes.emplace_back(5, 5, 5);
  const auto v = validate(m);
  ASSERT_EQ(v.size(), 1u) << describe(v);
  EXPECT_EQ(v[0].kind, ViolationKind::UnusedNode);
  EXPECT_EQ(v[0].ids, Ids{6});
  EXPECT_NE(v[0].message.find("node 6 at (5, 5, 5)"), std::string::npos) << v[0].message;
}

TEST(Validate, BadMidNode) {
  // Order 2: tetrahedron 2 puts its own mid-node on the shared edge 0-1 (slot 4 + 2, edge 02 of
  // its numbering 0 2 1 4 is nodes 0-1).
  TetMesh m = test::to_order2(test::two_tet_mesh());
  ASSERT_EQ(m.tet_node(1, 0), 0);
  ASSERT_EQ(m.tet_node(1, 2), 1);
  const Index shared = m.tet_node(1, 4 + 2);
  ASSERT_EQ(m.tet_node(0, 4 + 0), shared);  // edge 01 of tetrahedron 1
  m.nodes.push_back(m.nodes[shared] + Vec3(0, 0, 0.01));
  m.tets[10 + 6] = Index(m.nodes.size() - 1);
  const auto v = validate(m);
  // The shared mid-node is still used by tetrahedron 1: no unused node.
  ASSERT_EQ(v.size(), 1u) << describe(v);
  EXPECT_EQ(v[0].kind, ViolationKind::BadMidNode);
  EXPECT_EQ(v[0].ids, (Ids{1, 2}));
  EXPECT_NE(v[0].message.find("edge 1-2"), std::string::npos) << v[0].message;
}

TEST(Validate, Tet10FoldedBetweenItsGaussPointsIsCaught) {
  // A unit tetrahedron whose mid-nodes of edges 03 and 23 moved (as curved boundary mid-nodes
  // can): its Jacobian is positive at the 4 corners and the 4 Gauss points (27% of the straight
  // one's at worst) and negative at an edge's middle, so it folds in between.
  TetMesh linear;
  linear.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  const Index t[4] = {0, 1, 2, 3};
  linear.add_tet(t);
  TetMesh m = test::to_order2(linear);
  m.nodes[m.tet_node(0, 4 + 3)] = Vec3(0.176, -0.365, 0.784);  // edge 03
  m.nodes[m.tet_node(0, 4 + 5)] = Vec3(-0.043, -0.662, 0.615);  // edge 23
  EXPECT_LT(tet10_jacobian_ratio(m, 0), 0);
  const auto v = of_kind(validate(m), ViolationKind::NonPositiveJacobian);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0].ids, Ids{1});
}

TEST(Validate, SortedByKindThenId) {
  TetMesh m = test::cube_mesh(2);
  std::swap(m.tets[4 * 30 + 1], m.tets[4 * 30 + 2]);  // inverted, id 31
  std::swap(m.tets[4 * 7 + 1], m.tets[4 * 7 + 2]);    // inverted, id 8
  m.nodes.emplace_back(9, 9, 9);                      // unused, id 28
  m.nodes.push_back(m.nodes[0]);                      // duplicate of node 1 and unused, id 29
  const Index flat[4] = {0, 1, 2, 3};                 // collinear grid nodes: zero volume, id 49
  m.add_tet(flat);
  const auto v = validate(m);
  ASSERT_EQ(v.size(), 6u) << describe(v);
  EXPECT_EQ(v[0].kind, ViolationKind::InvertedTet);
  EXPECT_EQ(v[0].ids, Ids{8});
  EXPECT_EQ(v[1].kind, ViolationKind::InvertedTet);
  EXPECT_EQ(v[1].ids, Ids{31});
  EXPECT_EQ(v[2].kind, ViolationKind::ZeroVolumeTet);
  EXPECT_EQ(v[2].ids, Ids{49});
  EXPECT_EQ(v[3].kind, ViolationKind::DuplicateNode);
  EXPECT_EQ(v[3].ids, (Ids{1, 29}));
  EXPECT_EQ(v[4].kind, ViolationKind::UnusedNode);
  EXPECT_EQ(v[4].ids, Ids{28});
  EXPECT_EQ(v[5].ids, Ids{29});
}

TEST(Validate, KindNames) {
  EXPECT_STREQ(to_string(ViolationKind::BadNodeIndex), "bad_node_index");
  EXPECT_STREQ(to_string(ViolationKind::RepeatedNode), "repeated_node");
  EXPECT_STREQ(to_string(ViolationKind::InvertedTet), "inverted_tet");
  EXPECT_STREQ(to_string(ViolationKind::ZeroVolumeTet), "zero_volume_tet");
  EXPECT_STREQ(to_string(ViolationKind::NonManifoldFace), "non_manifold_face");
  EXPECT_STREQ(to_string(ViolationKind::OpenBoundary), "open_boundary");
  EXPECT_STREQ(to_string(ViolationKind::DuplicateNode), "duplicate_node");
  EXPECT_STREQ(to_string(ViolationKind::UnusedNode), "unused_node");
  EXPECT_STREQ(to_string(ViolationKind::BadMidNode), "bad_mid_node");
  EXPECT_STREQ(to_string(ViolationKind::NonFiniteNode), "non_finite_node");
}

TEST(Validate, NonFiniteNodeIsNamedAndItsTetrahedraAreNotJudged) {
  // Node 2 of the two-tet mesh moved to infinity, node 3 to NaN: both are named; the
  // tetrahedra using them are neither inverted nor flat, since they have no shape at all.
  TetMesh m = test::two_tet_mesh();
  m.nodes[1].x() = std::numeric_limits<double>::infinity();
  m.nodes[2].y() = std::nan("");
  const auto v = validate(m);
  const auto bad = of_kind(v, ViolationKind::NonFiniteNode);
  ASSERT_EQ(bad.size(), 2u) << describe(v);
  EXPECT_EQ(bad[0].ids, Ids{2});
  EXPECT_EQ(bad[1].ids, Ids{3});
  EXPECT_NE(bad[0].message.find("node 2 has a non-finite coordinate (inf"), std::string::npos) << bad[0].message;
  EXPECT_TRUE(of_kind(v, ViolationKind::InvertedTet).empty()) << describe(v);
  EXPECT_TRUE(of_kind(v, ViolationKind::ZeroVolumeTet).empty()) << describe(v);
}

}  // namespace
}  // namespace bisect
