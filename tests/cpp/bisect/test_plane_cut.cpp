// The plane bisections (thesis 7.3.1 cut face, 7.3.2 splitting, 7.3.3 edge following, 7.3.4
// contour splitting) one at a time, and the reasons they reject a plane.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "bisect/edge_following.hpp"
#include "bisect/io.hpp"
#include "bisect/plane_cut.hpp"
#include "bisect/polyhedral_model.hpp"
#include "poly_shapes.hpp"

namespace bisect {
namespace {

PolyhedralModel model(const std::string& text) { return prepare_model(test::poly(text)); }
using test::prism;

double total_volume(const PolyhedralModel& m) {
  double v = 0;
  for (std::size_t r = 0; r < m.regions.size(); ++r) v += m.region_volume(static_cast<Index>(r));
  return v;
}

const std::vector<Vec2> kL = test::kLOutline;
const std::vector<Vec2> kU = {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

TEST(PlaneCut, CutFaceInsertsOnlyThePolygonAtTheEdge) {
  // the notch bottom's plane y = 1 meets both arms of the U; the cut face method takes the one at
  // the reflex edge from node 6 (1,1,0) to node 14 (1,1,1)
  PolyhedralModel m = model(prism(kU));
  const CutOutcome c = cut_region(m, 0, {Vec3(0, 1, 0), 1.0}, 5, 13, false, DecomposeOptions{});
  ASSERT_TRUE(c.ok) << c.reason;
  EXPECT_EQ(c.cut_faces, 1u);
  ASSERT_EQ(c.regions.size(), 2u);
  EXPECT_NEAR(m.region_volume(c.regions[0]) + m.region_volume(c.regions[1]), 5.0, 1e-12);
  EXPECT_NEAR(std::min(m.region_volume(c.regions[0]), m.region_volume(c.regions[1])), 1.0, 1e-12);
}

TEST(PlaneCut, SplittingInsertsEveryPolygon) {
  PolyhedralModel m = model(prism(kU));
  const CutOutcome c = cut_region(m, 0, {Vec3(0, 1, 0), 1.0}, 5, 13, true, DecomposeOptions{});
  ASSERT_TRUE(c.ok) << c.reason;
  EXPECT_EQ(c.cut_faces, 2u);
  EXPECT_EQ(c.regions.size(), 3u);  // the base and both arms
  EXPECT_NEAR(total_volume(m), 5.0, 1e-12);
}

TEST(PlaneCut, RejectsAPlaneNearAVertex) {
  std::vector<Vec2> l = kL;
  l.push_back(Vec2(0, 1.02));  // on the left wall, 0.02 above the plane y = 1
  PolyhedralModel m = model(prism(l));
  const std::size_t before = m.faces.size();
  const CutOutcome c = cut_region(m, 0, {Vec3(0, 1, 0), 1.0}, 3, 3 + 7, false, DecomposeOptions{});
  EXPECT_FALSE(c.ok);
  EXPECT_EQ(c.reason, "near_vertex");
  EXPECT_EQ(m.faces.size(), before);  // a rejected plane changes nothing
}

TEST(PlaneCut, RejectsAnAcuteCut) {
  // the diagonal x = y splits the L's convex corner edge at the origin into 45 + 45 degrees:
  // acceptable by default, acute under a 60 degree limit
  PolyhedralModel m = model(prism(kL));
  const Vec3 n = Vec3(1, -1, 0).normalized();
  DecomposeOptions strict;
  strict.min_angle_deg = 60;
  const CutOutcome c = cut_region(m, 0, {n, 0.0}, 3, 9, false, strict);
  EXPECT_FALSE(c.ok);
  EXPECT_EQ(c.reason, "acute_angle");
  const CutOutcome ok = cut_region(m, 0, {n, 0.0}, 3, 9, false, DecomposeOptions{});
  EXPECT_TRUE(ok.ok) << ok.reason;
}

TEST(PlaneCut, RejectsAPlaneThatMissesTheInterior) {
  // through the convex corner edge at (2, 0), touching the L there only
  PolyhedralModel m = model(prism(kL));
  const Vec3 n = Vec3(1, -1, 0).normalized();
  const CutOutcome c = cut_region(m, 0, {n, n.dot(Vec3(2, 0, 0))}, 1, 7, false, DecomposeOptions{});
  EXPECT_FALSE(c.ok);
  EXPECT_EQ(c.reason, "not_interior");
}

TEST(EdgeFollowing, WalksAlongEdgesAndStitchesTriangles) {
  // the plane y = 1 crosses the L's left wall mid-edge; the walk moves that crossing to an end of
  // the wall edge and stitches the interface from triangles, adding no node
  PolyhedralModel m = model(prism(kL));
  const std::size_t nodes = m.nodes.size();
  const CutOutcome c = edge_following_cut(m, 0, {Vec3(0, 1, 0), 1.0}, 3, 9, false, DecomposeOptions{});
  ASSERT_TRUE(c.ok) << c.reason;
  EXPECT_EQ(m.nodes.size(), nodes);
  EXPECT_EQ(c.cut_faces, 2u);  // the walked quadrilateral, as two triangles
  ASSERT_EQ(c.regions.size(), 2u);
  EXPECT_NEAR(total_volume(m), 3.0, 1e-12);
  EXPECT_NEAR(m.region_volume(c.regions[0]), 1.5, 1e-12);  // split along the diagonal x = y
}

TEST(EdgeFollowing, BandwidthTestRejectsANodeInTheBand) {
  // a notch in the left wall puts nodes at y = 0.8 .. 0.9 close to x = 0: inside the walked
  // loop's projection and within the band of the plane y = 1, and not joined to the loop
  std::vector<Vec2> l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0.9}, {0.05, 0.85}, {0, 0.8}};
  PolyhedralModel m = model(prism(l));
  const CutOutcome c = edge_following_cut(m, 0, {Vec3(0, 1, 0), 1.0}, 3, 12, false, DecomposeOptions{});
  EXPECT_FALSE(c.ok);
  EXPECT_EQ(c.reason, "bandwidth");
}

TEST(ContourSplitting, JoinsACavityToTheOuterSurface) {
  PolyhedralModel m = prepare_model(read_poly(std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly"));
  // the plane z = 0.5 crosses the cube and its cavity: the section is a square with a hole
  const CutOutcome c = edge_following_cut(m, 0, {Vec3(0, 0, 1), 0.5}, -1, -1, true, DecomposeOptions{});
  ASSERT_TRUE(c.ok) << c.reason;
  EXPECT_GE(c.cut_faces, 8u);  // an annulus needs at least eight triangles
  EXPECT_NEAR(total_volume(m), 1.875, 1e-12);
}

}  // namespace
}  // namespace bisect
