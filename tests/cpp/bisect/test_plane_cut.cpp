// The plane bisections (thesis 7.3.1 cut face, 7.3.2 splitting, 7.3.3 edge following, 7.3.4
// contour splitting) one at a time, and the reasons they reject a plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "bisect/edge_following.hpp"
#include "bisect/io.hpp"
#include "bisect/plane_cut.hpp"
#include "bisect/polyhedral_model.hpp"
#include "bisect/section.hpp"
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

TEST(PlaneCut, ASectionFromTheRegionsSnapshotIsTheSectionWorkedOutAlone) {
  // the U and the L with a node near y = 1: planes in several directions, through nodes, near
  // them and between them, whole or at the notch's edge. The snapshot (made once while planes
  // are tried) gives each node the same distance, side and shortest edge, and the same pieces,
  // loops and verdict, as the section that measures everything itself.
  std::vector<Vec2> l = kL;
  l.push_back(Vec2(0, 1.02));
  std::size_t compared = 0, rejected = 0;
  for (const std::string& text : {prism(kU), prism(l)}) {
    const PolyhedralModel m = model(text);
    const RegionSnapshot snap = region_snapshot(m, 0);
    EXPECT_EQ(snap.faces, m.live_faces(0));
    // the edges at each node: every edge of the table under both its nodes, and nothing else
    ASSERT_EQ(snap.edge_keys.size(), snap.edges.size());
    ASSERT_EQ(snap.edge_start.size(), snap.nodes.size() + 1);
    EXPECT_EQ(snap.edge_at.size(), 2 * snap.edge_keys.size());
    double length = 0;
    for (std::size_t e = 0; e < snap.edge_keys.size(); ++e) {
      const std::uint64_t key = snap.edge_keys[e];
      EXPECT_EQ(snap.edges.count(key), 1u);
      length += (m.nodes[key_lo(key)] - m.nodes[key_hi(key)]).norm();
      for (const Index v : {key_lo(key), key_hi(key)}) {
        const int k = snap.slot[v];
        ASSERT_GE(k, 0);
        EXPECT_EQ(std::count(snap.edge_at.begin() + snap.edge_start[k], snap.edge_at.begin() + snap.edge_start[k + 1],
                             static_cast<int>(e)), 1);
      }
    }
    EXPECT_NEAR(snap.edge_length_sum, length, 1e-12 * length);
    // every face's nodes lie within its sphere
    for (std::size_t i = 0; i < snap.faces.size(); ++i)
      for (const auto& loop : m.faces[snap.faces[i]].loops)
        for (const Index v : loop) EXPECT_LE((m.nodes[v] - snap.face_centre[i]).norm(), snap.face_radius[i] * (1 + 1e-12));
    for (const Vec3& dir : {Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(1, 1, 0), Vec3(1, 2, 0.5)})
      for (const double at : {0.25, 0.5, 1.0, 1.01, 1.5, 2.0})
        for (const bool whole : {false, true}) {
          const Vec3 n = dir.normalized();
          const CutPlane pl{n, at};
          const SectionResult alone = build_section(m, 0, pl, whole, DecomposeOptions{});
          const SectionResult kept = build_section(m, 0, pl, whole, DecomposeOptions{}, &snap);
          ++compared;
          ASSERT_EQ(alone.reject == nullptr, kept.reject == nullptr);
          if (alone.reject) {
            ++rejected;
            EXPECT_STREQ(alone.reject, kept.reject);
          }
          std::vector<std::pair<Index, NodeInfo>> a(alone.info.begin(), alone.info.end()), b(kept.info.begin(), kept.info.end());
          ASSERT_EQ(a.size(), b.size());
          for (std::size_t k = 0; k < a.size(); ++k) {
            EXPECT_EQ(a[k].first, b[k].first);
            EXPECT_EQ(a[k].second.d, b[k].second.d);
            EXPECT_EQ(a[k].second.side, b[k].second.side);
            EXPECT_EQ(a[k].second.min_len, b[k].second.min_len);
          }
          EXPECT_EQ(alone.near, kept.near);
          std::vector<int> on_plane;  // the entries on the plane, in the table's order
          for (std::size_t k = 0; k < b.size(); ++k)
            if (b[k].second.side == 0 && static_cast<int>(k) < kept.measured) on_plane.push_back(static_cast<int>(k));
          EXPECT_EQ(kept.on_plane, on_plane);
          EXPECT_EQ(alone.on_plane, kept.on_plane);
          ASSERT_EQ(alone.sec.pieces.size(), kept.sec.pieces.size());
          for (std::size_t k = 0; k < alone.sec.pieces.size(); ++k) {
            EXPECT_EQ(alone.sec.pieces[k].from, kept.sec.pieces[k].from);
            EXPECT_EQ(alone.sec.pieces[k].to, kept.sec.pieces[k].to);
            EXPECT_EQ(alone.sec.pieces[k].face, kept.sec.pieces[k].face);
          }
          EXPECT_EQ(alone.loops, kept.loops);
          EXPECT_EQ(alone.polys, kept.polys);
        }
  }
  EXPECT_EQ(compared, 120u);
  EXPECT_GT(rejected, 0u);             // some planes fail (near a node, along a face)
  EXPECT_LT(rejected, compared / 2);   // most make a section
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
