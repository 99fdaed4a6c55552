// The fold refill (optimize/inverted_refill.hpp): inverted tetrahedra cut out with their free
// nodes' stars and filled again, every tetrahedron positive afterwards, the outer boundary and
// other regions untouched, the volume whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "bisect/validate.hpp"
#include "optimize/inverted_refill.hpp"
#include "optimize/optimize_mesh.hpp"
#include "tet/tet_complex.hpp"
#include "tet/tet_test_meshes.hpp"

namespace bisect::optimize {
namespace {

using tet::Tet;
using tet::TetComplex;

double six_volume(const std::vector<Vec3>& X, const Tet& t) { return test::six_volume(X[t[0]], X[t[1]], X[t[2]], X[t[3]]); }

std::size_t inverted_count(const std::vector<Vec3>& X, const std::vector<Tet>& tets) {
  return static_cast<std::size_t>(std::count_if(tets.begin(), tets.end(), [&](const Tet& t) { return !tet::positive(X, t); }));
}

// The 4×4×4 cube mesh with its nodes on the cube's faces fixed, as a complex.
struct Cube {
  TetMesh mesh = test::cube_mesh(4);
  std::vector<Vec3> X = mesh.nodes;
  std::vector<char> fixed;
  std::vector<Tet> tets;
  Cube() {
    for (const Vec3& p : X) fixed.push_back(p.minCoeff() == 0 || p.maxCoeff() == 4);
    for (std::size_t t = 0; t < mesh.num_tets(); ++t) tets.push_back({mesh.tet_node(t, 0), mesh.tet_node(t, 1), mesh.tet_node(t, 2), mesh.tet_node(t, 3)});
  }
};

// The faces with no neighbour, as sorted node triples.
std::set<std::array<Index, 3>> outer_faces(const TetComplex& cx) {
  std::set<std::array<Index, 3>> out;
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t])
      for (int f = 0; f < 4; ++f)
        if (cx.neighbour(t, f) < 0) {
          std::array<Index, 3> k = cx.face(static_cast<Index>(t), f);
          std::sort(k.begin(), k.end());
          out.insert(k);
        }
  return out;
}

// The complex as a mesh of the nodes it uses (what the assembly hands on), for the validator.
TetMesh used_mesh(const TetComplex& cx, const std::vector<Vec3>& X) {
  TetMesh m;
  std::vector<Index> id(X.size(), -1);
  const std::vector<Tet> tets = cx.tets();
  const std::vector<Index> tags = cx.tags();
  for (std::size_t t = 0; t < tets.size(); ++t) {
    Index v[4];
    for (int i = 0; i < 4; ++i) {
      Index& k = id[tets[t][i]];
      if (k < 0) k = static_cast<Index>(m.nodes.size()), m.nodes.push_back(X[tets[t][i]]);
      v[i] = k;
    }
    m.add_tet(v, tags[t]);
  }
  return m;
}

TEST(InvertedRefill, AFoldAroundAFreeNodeIsFilledAgain) {
  Cube c;
  // the centre node pushed past its neighbour towards +x: the tetrahedra on that side turn over
  const Index centre = test::grid_node(4, 2, 2, 2);
  c.X[centre] = Vec3(3.4, 2.2, 2.1);
  ASSERT_GE(inverted_count(c.X, c.tets), 1u) << "the set-up has no fold";
  TetComplex cx(c.X);
  cx.build(c.tets);
  const auto outer = outer_faces(cx);
  const RefillCounts n = refill_inverted(cx, c.X, c.fixed);
  EXPECT_GE(n.refilled, 1u);
  EXPECT_EQ(n.remaining, 0u);
  const std::vector<Tet> after = cx.tets();
  EXPECT_EQ(inverted_count(c.X, after), 0u);
  double volume = 0;
  for (const Tet& t : after) volume += six_volume(c.X, t) / 6;
  EXPECT_NEAR(volume, 64, 1e-9);
  EXPECT_EQ(outer_faces(cx), outer) << "the cube's faces changed";
  const auto violations = validate(used_mesh(cx, c.X));
  EXPECT_TRUE(violations.empty()) << violations.front().message;
}

TEST(InvertedRefill, ANodeOutsideItsHoleDropsOut) {
  Cube c;
  // the node (1, 1, 1) pushed out through the cube's corner: no filling of its hole can hold it
  const Index v = test::grid_node(4, 1, 1, 1);
  c.X[v] = Vec3(-0.5, -0.4, -0.3);
  ASSERT_GE(inverted_count(c.X, c.tets), 1u);
  TetComplex cx(c.X);
  cx.build(c.tets);
  const RefillCounts n = refill_inverted(cx, c.X, c.fixed);
  EXPECT_EQ(n.remaining, 0u);
  for (const Tet& t : cx.tets()) EXPECT_EQ(std::count(t.begin(), t.end(), v), 0) << "the node outside is still used";
  double volume = 0;
  for (const Tet& t : cx.tets()) volume += six_volume(c.X, t) / 6;
  EXPECT_NEAR(volume, 64, 1e-9);
}

TEST(InvertedRefill, OtherRegionsAndHeldFacesStay) {
  Cube c;
  // two regions, x < 2 and x > 2, their interface held; a fold beside it in region 0
  std::vector<Index> tags;
  for (const Tet& t : c.tets) {
    double x = 0;
    for (Index v : t) x += c.X[v].x();
    tags.push_back(x < 8 ? 0 : 1);
  }
  for (std::size_t v = 0; v < c.X.size(); ++v)
    if (c.X[v].x() == 2) c.fixed[v] = 1;
  const Index free = test::grid_node(4, 1, 2, 2);
  c.X[free] = Vec3(1.9, 2.3, 2.2);
  const Index moved_apart = test::grid_node(4, 1, 2, 1);
  c.X[moved_apart] = Vec3(1.2, 2.6, 1.9);
  ASSERT_GE(inverted_count(c.X, c.tets), 1u);
  TetComplex cx(c.X);
  cx.build(c.tets, tags);
  std::unordered_set<tet::FaceKey, tet::FaceKeyHash> interface;
  std::set<Tet> region1;
  for (std::size_t t = 0; t < c.tets.size(); ++t) {
    if (tags[t] == 1) region1.insert(c.tets[t]);
    for (int f = 0; f < 4; ++f) {
      const auto fc = cx.face(static_cast<Index>(t), f);
      if (c.X[fc[0]].x() == 2 && c.X[fc[1]].x() == 2 && c.X[fc[2]].x() == 2) interface.insert(tet::face_key(fc[0], fc[1], fc[2]));
    }
  }
  cx.constrain(interface);
  const RefillCounts n = refill_inverted(cx, c.X, c.fixed);
  EXPECT_GE(n.refilled, 1u);
  EXPECT_EQ(n.remaining, 0u);
  std::set<Tet> region1_after;
  const std::vector<Tet> after = cx.tets();
  const std::vector<Index> tags_after = cx.tags();
  for (std::size_t t = 0; t < after.size(); ++t)
    if (tags_after[t] == 1) region1_after.insert(after[t]);
  EXPECT_EQ(region1_after, region1) << "region 1 was cut into";
  // every interface face is still a face of a tetrahedron of region 0
  std::size_t found = 0;
  for (std::size_t t = 0; t < after.size(); ++t)
    for (int f = 0; f < 4; ++f) {
      if (tags_after[t] != 0) continue;
      const Tet& k = after[t];
      std::array<Index, 3> fc{};
      for (int i = 0, j = 0; i < 4; ++i)
        if (i != f) fc[j++] = k[i];
      found += interface.count(tet::face_key(fc[0], fc[1], fc[2]));
    }
  EXPECT_EQ(found, interface.size());
  const auto violations = validate(used_mesh(cx, c.X));
  EXPECT_TRUE(violations.empty()) << violations.front().message;
}

TEST(InvertedRefill, AValidMeshIsLeftAsItIs) {
  Cube c;
  TetComplex cx(c.X);
  cx.build(c.tets);
  const RefillCounts n = refill_inverted(cx, c.X, c.fixed);
  EXPECT_EQ(n.refilled, 0u);
  EXPECT_EQ(n.remaining, 0u);
  EXPECT_EQ(cx.tets(), c.tets);
}

// A fold no hole mends: a node of the cube's face (fixed, never inside a hole) pushed deep into
// the cube. The refill leaves it, find_fold names where it is, and the optimisation reports it and
// runs no sliver repair over it (its Delaunay insertions broke the complex over such a fold).
TEST(InvertedRefill, AFoldOfAFixedNodeIsReportedNotRepaired) {
  Cube c;
  const Index pushed = test::grid_node(4, 0, 2, 2);
  ASSERT_TRUE(c.fixed[pushed]);
  c.X[pushed] = Vec3(2.6, 2.1, 2.05);
  ASSERT_GE(inverted_count(c.X, c.tets), 1u);
  TetComplex cx(c.X);
  cx.build(c.tets);
  std::vector<Vec3> X = c.X;
  const OptimizeCounts n = optimize_mesh(cx, X, c.fixed, OptimizeOptions{});
  EXPECT_GE(n.folds_left, 1);
  EXPECT_EQ(static_cast<std::size_t>(n.folds_left), inverted_count(X, cx.tets()));
  EXPECT_EQ(n.sliver_moves, 0);
  EXPECT_EQ(X.size(), c.X.size()) << "the sliver repair inserted nodes over the fold";
  Vec3 at;
  Index region = -1;
  ASSERT_TRUE(find_fold(cx, X, &at, &region));
  EXPECT_EQ(region, 0);
  EXPECT_TRUE(at.minCoeff() > 0 && at.maxCoeff() < 4) << "the fold's centroid " << at.transpose() << " is not in the cube";
}

TEST(InvertedRefill, NoFoldIsFoundInAValidMesh) {
  Cube c;
  TetComplex cx(c.X);
  cx.build(c.tets);
  Vec3 at;
  Index region = -1;
  EXPECT_FALSE(find_fold(cx, c.X, &at, &region));
  std::vector<Vec3> X = c.X;
  EXPECT_EQ(optimize_mesh(cx, X, c.fixed, OptimizeOptions{}).folds_left, 0);
}

}  // namespace
}  // namespace bisect::optimize
