// The order of the candidate planes at a reflex edge (thesis 6.4.1, plane_selection.hpp): the face
// extensions first at a sharp edge or in a polyhedral input, the bisector first at a nearly flat
// edge beside a facet of a curved surface, then the planes through a vertex it nearly meets.
#include <gtest/gtest.h>

#include <cmath>

#include "bisect/edge_wedges.hpp"
#include "bisect/plane_selection.hpp"
#include "bisect/polyhedral_model.hpp"
#include "poly_shapes.hpp"

namespace bisect {
namespace {

// The reflex wedge of the prism's vertical edge at outline point k (n points): bottom node k, top
// node n + k.
ReflexEdge reflex_at(const PolyhedralModel& m, Index k, Index n) {
  const RegionEdges edges = region_edges(m, 0);
  ReflexEdge e{k, n + k, {}};
  for (const Wedge& w : interior_wedges(m, 0, e.a, e.b, edges.at(edge_key(e.a, e.b))))
    if (w.angle > M_PI) e.wedge = w;
  return e;
}

std::vector<Index> all_nodes(const PolyhedralModel& m) {
  std::vector<Index> v(m.nodes.size());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<Index>(i);
  return v;
}

bool holds(const CutPlane& p, const Vec3& x) { return std::abs(p.n.dot(x) - p.c) < 1e-12; }

bool is_face_plane(const PolyhedralModel& m, const CutPlane& p) {
  for (const ModelFace& f : m.faces)
    if (f.alive && p.n.dot(f.normal) > 1 - 1e-12 && std::abs(p.c - f.offset) < 1e-12) return true;
  return false;
}

// A 4 x 2 block with a shallow notch in its top side: the edge at (2, 1.6) is reflex by 22.6
// degrees, as a facet edge of a hole faceted every 22.5 degrees.
const std::vector<Vec2> kNotch = {{0, 0}, {4, 0}, {4, 2}, {2, 1.6}, {0, 2}};

TEST(PlaneSelection, SharpEdgeTakesTheFaceExtensionsFirst) {
  const PolyhedralModel m = prepare_model(test::poly(test::l_prism()));
  const ReflexEdge e = reflex_at(m, 3, 6);
  ASSERT_NEAR(e.wedge.angle, 1.5 * M_PI, 1e-12);
  const std::vector<char> curved(m.faces.size(), 1);  // curved or not, 270 degrees is sharp
  EXPECT_FALSE(bisector_first(m, e, curved));
  const std::vector<CutPlane> p = candidate_planes(m, e, 7, all_nodes(m), curved);
  ASSERT_GE(p.size(), 3u);
  EXPECT_TRUE(is_face_plane(m, p[0]));
  EXPECT_TRUE(is_face_plane(m, p[1]));
  EXPECT_NEAR(std::abs(p[2].n.x()), std::sqrt(0.5), 1e-12);  // the bisector, at 45 degrees
}

TEST(PlaneSelection, NearlyFlatEdgeOfAPolyhedralInputKeepsTheThesisOrder) {
  const PolyhedralModel m = prepare_model(test::poly(test::prism(kNotch)));
  const ReflexEdge e = reflex_at(m, 3, 5);
  ASSERT_NEAR(e.wedge.angle - M_PI, 2 * std::atan(0.2), 1e-12);
  EXPECT_FALSE(bisector_first(m, e, {}));
  const std::vector<CutPlane> p = candidate_planes(m, e, 7, all_nodes(m), {});
  ASSERT_FALSE(p.empty());
  EXPECT_TRUE(is_face_plane(m, p[0]));
}

TEST(PlaneSelection, NearlyFlatEdgeOfACurvedFaceTakesTheBisectorFirst) {
  const PolyhedralModel m = prepare_model(test::poly(test::prism(kNotch)));
  const ReflexEdge e = reflex_at(m, 3, 5);
  const std::vector<char> curved(m.faces.size(), 1);
  EXPECT_TRUE(bisector_first(m, e, curved));
  const std::vector<CutPlane> p = candidate_planes(m, e, 7, all_nodes(m), curved);
  // no node lies near the bisector: the wedge's seven, bisector, quarters, extensions, eighths
  ASSERT_EQ(p.size(), 7u);
  EXPECT_NEAR(std::abs(p[0].n.x()), 1.0, 1e-12);  // x = 2, normal to both notch faces' mean
  EXPECT_TRUE(holds(p[0], Vec3(2, 1.6, 0)));
  EXPECT_FALSE(is_face_plane(m, p[1]));
  EXPECT_FALSE(is_face_plane(m, p[2]));
  EXPECT_TRUE(is_face_plane(m, p[3]));
  EXPECT_TRUE(is_face_plane(m, p[4]));
  // only the faces' sources say curved: a flat face beside a flat face keeps the thesis's order
  std::vector<char> flat(m.faces.size(), 0);
  EXPECT_FALSE(bisector_first(m, e, flat));
}

TEST(PlaneSelection, PlaneThroughAVertexTheBisectorNearlyMeets) {
  // a node on the bottom side 0.05 off the bisector's plane x = 2: the plane through the edge and
  // that node comes second
  const std::vector<Vec2> outline = {{0, 0}, {2.05, 0}, {4, 0}, {4, 2}, {2, 1.6}, {0, 2}};
  const PolyhedralModel m = prepare_model(test::poly(test::prism(outline)));
  const ReflexEdge e = reflex_at(m, 4, 6);
  const std::vector<char> curved(m.faces.size(), 1);
  const std::vector<CutPlane> p = candidate_planes(m, e, 7, all_nodes(m), curved);
  ASSERT_EQ(p.size(), 8u);  // the wedge's seven and one through the node (both its ends), not counted
  EXPECT_NEAR(std::abs(p[0].n.x()), 1.0, 1e-12);
  EXPECT_TRUE(holds(p[1], Vec3(2.05, 0, 0)));
  EXPECT_TRUE(holds(p[1], Vec3(2.05, 0, 1)));
  EXPECT_TRUE(holds(p[1], Vec3(2, 1.6, 0)));
  // without the region's nodes there is no such plane
  const std::vector<CutPlane> q = candidate_planes(m, e, 7, {}, curved);
  ASSERT_GE(q.size(), 2u);
  EXPECT_FALSE(holds(q[1], Vec3(2.05, 0, 0)));
}

}  // namespace
}  // namespace bisect
