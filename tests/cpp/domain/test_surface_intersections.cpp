// Self-intersecting inputs are found exactly and named (thesis 6.12); valid ones pass.
#include <gtest/gtest.h>

#include <chrono>
#include <sstream>

#include "bisect/io.hpp"
#include "bisect/polyhedral_model.hpp"
#include "domain/surface_intersections.hpp"
#include "input_error.hpp"

namespace bisect {
namespace {

// A box's six faces appended to `in` (nodes too), as one region's faces.
void add_box(PolyInput& in, const Vec3& lo, const Vec3& hi, PolyRegion& region) {
  const Index b = static_cast<Index>(in.nodes.size());
  for (int i = 0; i < 8; ++i)
    in.nodes.push_back(Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()));
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    in.faces.push_back({{b + q[0], b + q[1], b + q[2], b + q[3]}, -1});
    region.faces.push_back(static_cast<Index>(in.faces.size() - 1));
  }
}

PolyInput boxes(const std::vector<std::pair<Vec3, Vec3>>& list) {
  PolyInput in;
  in.source = "boxes";
  PolyRegion r;
  for (const auto& [lo, hi] : list) add_box(in, lo, hi, r);
  in.regions.push_back(r);
  return in;
}

TEST(SurfaceIntersections, ValidSolidsHaveNone) {
  EXPECT_TRUE(find_surface_intersections(boxes({{Vec3(0, 0, 0), Vec3(1, 1, 1)}})).empty());
  // a box inside a box (a cavity, as STL gives it): nested, not touching
  EXPECT_TRUE(find_surface_intersections(boxes({{Vec3(0, 0, 0), Vec3(3, 3, 3)}, {Vec3(1, 1, 1), Vec3(2, 2, 2)}})).empty());
  for (const char* f : {"cube-cavity-adjacent-cube.poly", "reentry-box.poly"})
    EXPECT_TRUE(find_surface_intersections(read_poly(std::string(BISECT_TEST_DATA) + "/" + f)).empty()) << f;
}

TEST(SurfaceIntersections, InterpenetratingBoxesCross) {
  const PolyInput in = boxes({{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(0.5, 0.37, 0.61), Vec3(1.5, 1.4, 1.3)}});
  const auto hits = find_surface_intersections(in);
  ASSERT_FALSE(hits.empty());
  EXPECT_EQ(hits[0].kind, "crossing");
  EXPECT_LT(hits[0].face_a, 6);
  EXPECT_GE(hits[0].face_b, 6);  // one face of each box
  const std::string e = test::error_of([&] { prepare_model(in); });
  EXPECT_NE(e.find("boxes: faces "), std::string::npos) << e;
  EXPECT_NE(e.find(" intersect at ("), std::string::npos) << e;
}

TEST(SurfaceIntersections, LabelledFacesAreNamedByTheirLabels) {
  // a B-rep proxy labels its facets with their B-rep faces: the message names those, never the
  // proxy's own numbers (corpus/Block.brep: "faces 35345 and 35378 intersect")
  PolyInput in = boxes({{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(0.5, 0.37, 0.61), Vec3(1.5, 1.4, 1.3)}});
  for (int f = 0; f < 12; ++f) in.face_label.push_back(f < 6 ? "Face1" : "Face2");
  std::string e = test::error_of([&] { prepare_model(in); });
  EXPECT_NE(e.find("boxes: the tessellations of Face1 and Face2 intersect at ("), std::string::npos) << e;
  std::fill(in.face_label.begin(), in.face_label.end(), "Face7");
  e = test::error_of([&] { prepare_model(in); });
  EXPECT_NE(e.find("boxes: Face7's tessellation folds: two of its facets intersect at ("), std::string::npos) << e;
}

TEST(SurfaceIntersections, CornerPushedThroughTheBottom) {
  PolyInput in = boxes({{Vec3(0, 0, 0), Vec3(1, 1, 1)}});
  in.nodes[7] = Vec3(0.6, 0.6, -0.5);  // the top corner (1,1,1) below the bottom face
  const auto hits = find_surface_intersections(in);
  ASSERT_FALSE(hits.empty());
  bool bottom = false;
  for (const auto& h : hits) bottom |= h.face_a == 0 || h.face_b == 0;
  EXPECT_TRUE(bottom);
}

TEST(SurfaceIntersections, CoplanarOverlapAndTouching) {
  // a box standing on another's top face, not sharing its nodes: the faces touch, coplanar
  PolyInput in = boxes({{Vec3(0, 0, 0), Vec3(2, 2, 1)}, {Vec3(0.5, 0.5, 1), Vec3(1, 1, 2)}});
  auto hits = find_surface_intersections(in);
  ASSERT_FALSE(hits.empty());
  EXPECT_EQ(hits[0].kind, "coplanar_overlap");
  // a pyramid's apex on the middle of a box's top face
  PolyInput apex = boxes({{Vec3(0, 0, 0), Vec3(2, 2, 1)}});
  const Index b = static_cast<Index>(apex.nodes.size());
  apex.nodes.push_back(Vec3(1, 1, 1));
  for (const Vec3& p : {Vec3(0.5, 0.5, 2), Vec3(1.5, 0.5, 2), Vec3(1, 1.5, 2)}) apex.nodes.push_back(p);
  apex.faces.push_back({{b, b + 1, b + 2}, -1});
  apex.faces.push_back({{b, b + 2, b + 3}, -1});
  apex.faces.push_back({{b, b + 3, b + 1}, -1});
  apex.faces.push_back({{b + 1, b + 3, b + 2}, -1});
  hits = find_surface_intersections(apex);
  ASSERT_EQ(hits.size(), 3u);  // each of the three faces at the apex touches the top face
  for (const auto& h : hits) {
    EXPECT_EQ(h.kind, "touching");
    EXPECT_EQ(h.face_a, 1);
    EXPECT_NEAR((h.point - Vec3(1, 1, 1)).norm(), 0, 1e-12);
  }
}

TEST(SurfaceIntersections, SharedNodesAreNoIntersection) {
  // two boxes sharing a corner node by id
  PolyInput in = boxes({{Vec3(0, 0, 0), Vec3(1, 1, 1)}});
  PolyRegion& r = in.regions[0];
  const Index base = static_cast<Index>(in.nodes.size());
  add_box(in, Vec3(1, 1, 1), Vec3(2, 2, 2), r);
  for (std::size_t f = 6; f < in.faces.size(); ++f)
    for (Index& v : in.faces[f].nodes)
      if (v == base) v = 7;  // the second box's corner (1,1,1) is the first's node 8
  EXPECT_TRUE(find_surface_intersections(in).empty());
}

TEST(SurfaceIntersections, DecidedExactlyOneUlpAway) {
  // the apex a hair above the top face: not touching; exactly on it: touching
  for (double z : {std::nextafter(1.0, 2.0), 1.0}) {
    PolyInput in = boxes({{Vec3(0, 0, 0), Vec3(2, 2, 1)}});
    const Index b = static_cast<Index>(in.nodes.size());
    in.nodes.push_back(Vec3(1, 1, z));
    for (const Vec3& p : {Vec3(0.5, 0.5, 2), Vec3(1.5, 0.5, 2), Vec3(1, 1.5, 2)}) in.nodes.push_back(p);
    in.faces.push_back({{b, b + 1, b + 2}, -1});
    in.faces.push_back({{b, b + 2, b + 3}, -1});
    in.faces.push_back({{b, b + 3, b + 1}, -1});
    in.faces.push_back({{b + 1, b + 3, b + 2}, -1});
    EXPECT_EQ(find_surface_intersections(in).empty(), z > 1.0) << z;
  }
}

}  // namespace
}  // namespace bisect
