// A face piece's grid against its proxy cell (pipeline/piece_against_proxy.hpp): no grid triangle
// or inner grid edge left lying in a cut face's plane, and inner nodes' proxy positions on the
// piece's proxy faces.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "pipeline/piece_against_proxy.hpp"
#include "surface/analytic_surfaces.hpp"

namespace bisect::pipeline {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A cylinder of radius 1 (u: a quarter turn, v: height 1) cut by the oblique plane z = 0.5 x + 0.2:
// the cut curve v = 0.5 cos(pi u / 2) + 0.2 bends in (u, v), and the piece lies under it. Three
// nodes of that curve (a, b, c) joined by one triangle lie in the cut plane.
struct CutCylinder {
  surface::CylinderSurface surf{1.0, kPi / 2, 1.0};
  surface::RegionMesh rm;
  static double cut_v(double u) { return 0.5 * std::cos(kPi / 2 * u) + 0.2; }
  Index add(const Vec2& uv) {
    rm.uv.push_back(uv);
    rm.xyz.push_back(surf.point(uv));
    return static_cast<Index>(rm.uv.size() - 1);
  }
  double cut_plane_offset(Index v) const { return rm.xyz[v].z() - 0.5 * rm.xyz[v].x() - 0.2; }
};

TEST(PieceAgainstProxy, AnEarOnOneCutIsFlippedWithItsNeighbour) {
  CutCylinder c;
  const Index a = c.add({0.2, CutCylinder::cut_v(0.2)}), b = c.add({0.5, CutCylinder::cut_v(0.5)}),
              d = c.add({0.8, CutCylinder::cut_v(0.8)});
  const Index e = c.add({0.5, 0.0});  // on the piece's other boundary (a B-rep edge)
  ASSERT_NEAR(c.cut_plane_offset(a), 0, 1e-12);
  ASSERT_NEAR(c.cut_plane_offset(b), 0, 1e-12);
  c.rm.tris = {{a, d, b}, {d, a, e}};  // counter-clockwise in (u, v)
  const std::vector<std::vector<Index>> cuts = {{7}, {7}, {7}, {}};
  EXPECT_EQ(mend_cut_ears(c.surf, c.rm, cuts, 4), 1);
  ASSERT_EQ(c.rm.tris.size(), 2u);
  EXPECT_EQ(c.rm.uv.size(), 4u);  // no node added
  double area = 0;
  for (const auto& t : c.rm.tris) {
    // every triangle now has the node off the cut: none lies in the cut plane
    EXPECT_TRUE(t[0] == e || t[1] == e || t[2] == e);
    const Vec2 p = c.rm.uv[t[1]] - c.rm.uv[t[0]], q = c.rm.uv[t[2]] - c.rm.uv[t[0]];
    const double a2 = p.x() * q.y() - p.y() * q.x();
    EXPECT_GT(a2, 0);  // still counter-clockwise
    area += a2 / 2;
  }
  // the same quadrilateral covered
  const auto tri_area = [&](Index i, Index j, Index k) {
    const Vec2 p = c.rm.uv[j] - c.rm.uv[i], q = c.rm.uv[k] - c.rm.uv[i];
    return (p.x() * q.y() - p.y() * q.x()) / 2;
  };
  EXPECT_NEAR(area, tri_area(a, d, b) + tri_area(d, a, e), 1e-12);
}

TEST(PieceAgainstProxy, AnEarWithNoNeighbourIsSplitOffTheCutPlane) {
  CutCylinder c;
  const Index a = c.add({0.2, CutCylinder::cut_v(0.2)}), b = c.add({0.5, CutCylinder::cut_v(0.5)}),
              d = c.add({0.8, CutCylinder::cut_v(0.8)});
  c.rm.tris = {{a, d, b}};
  const std::vector<std::vector<Index>> cuts = {{3, 7}, {7}, {7, 9}};
  EXPECT_EQ(mend_cut_ears(c.surf, c.rm, cuts, 3), 1);
  ASSERT_EQ(c.rm.uv.size(), 4u);
  EXPECT_EQ(c.rm.tris.size(), 3u);
  // the new node is on the surface, on the piece's side of the cut (under the plane)
  EXPECT_NEAR((c.rm.xyz[3] - c.surf.point(c.rm.uv[3])).norm(), 0, 1e-12);
  EXPECT_LT(c.cut_plane_offset(3), -1e-3);
  for (const auto& t : c.rm.tris) EXPECT_TRUE(t[0] == 3 || t[1] == 3 || t[2] == 3);
}

TEST(PieceAgainstProxy, TrianglesOffAnyOneCutAreLeftAlone) {
  CutCylinder c;
  const Index a = c.add({0.2, CutCylinder::cut_v(0.2)}), b = c.add({0.5, CutCylinder::cut_v(0.5)}),
              d = c.add({0.8, CutCylinder::cut_v(0.8)});
  const Index inner = c.add({0.5, 0.3});
  c.rm.tris = {{a, d, b}, {d, a, inner}};
  // a and d on cut 7, b on another cut (8): no cut face holds all three corners
  const std::vector<std::vector<Index>> cuts = {{7}, {8}, {7}};
  const auto before = c.rm.tris;
  EXPECT_EQ(mend_cut_ears(c.surf, c.rm, cuts, 3), 0);
  EXPECT_EQ(c.rm.tris, before);
  // an inner node (past `boundary`) is on no cut, whatever node_cuts would say
  EXPECT_EQ(mend_cut_ears(c.surf, c.rm, {{7}, {7}, {7}, {7}}, 3), 1);
}

// A chord: nodes a and b of the cut curve joined by an inner edge, with c above it (between the
// chord and the cut curve, off the cut) and d under it.
struct Chord : CutCylinder {
  Index a = add({0.2, cut_v(0.2)}), b = add({0.8, cut_v(0.8)}), c = add({0.5, 0.54}), d = add({0.5, 0.2});
  std::vector<std::vector<Index>> cuts = {{7}, {7}, {}, {}};
  std::vector<Vec3> p = rm.xyz;  // proxy positions: the true ones unless a test moves one
  bool splits = true;            // false: every point counts as on the cut plane, so no split is taken
  Chord() { rm.tris = {{a, d, b}, {b, c, a}}; }  // counter-clockwise in (u, v)
  int mend() {
    const auto on_surface = [this](const Vec2& uv, const Vec3&) { return surf.point(uv); };
    const auto off_cut = [this](Index f, const Vec3& q) {
      EXPECT_EQ(f, 7);
      return splits ? std::abs(q.z() - 0.5 * q.x() - 0.2) / std::sqrt(1.25) : 0.0;
    };
    return mend_cut_chords(surf, rm, cuts, 2, p, on_surface, off_cut);
  }
  bool holds_chord() const {
    for (const auto& t : rm.tris)
      for (int k = 0; k < 3; ++k)
        if ((t[k] == a && t[(k + 1) % 3] == b) || (t[k] == b && t[(k + 1) % 3] == a)) return true;
    return false;
  }
  double uv_area(const std::array<Index, 3>& t) const {
    const Vec2 e = rm.uv[t[1]] - rm.uv[t[0]], f = rm.uv[t[2]] - rm.uv[t[0]];
    return (e.x() * f.y() - e.y() * f.x()) / 2;
  }
};

TEST(PieceAgainstProxy, AChordIsFlippedAcrossItsQuadrilateral) {
  Chord ch;
  ASSERT_NEAR(ch.cut_plane_offset(ch.a), 0, 1e-12);
  ASSERT_NEAR(ch.cut_plane_offset(ch.b), 0, 1e-12);
  const double area = ch.uv_area(ch.rm.tris[0]) + ch.uv_area(ch.rm.tris[1]);
  EXPECT_EQ(ch.mend(), 1);
  EXPECT_FALSE(ch.holds_chord());
  EXPECT_EQ(ch.rm.uv.size(), 4u);
  ASSERT_EQ(ch.rm.tris.size(), 2u);
  for (const auto& t : ch.rm.tris) EXPECT_GT(ch.uv_area(t), 0);
  EXPECT_NEAR(ch.uv_area(ch.rm.tris[0]) + ch.uv_area(ch.rm.tris[1]), area, 1e-12);
  EXPECT_EQ(ch.mend(), 0);  // nothing left to mend
}

TEST(PieceAgainstProxy, AChordWhoseFlipTurnsOverOnTheProxyIsSplitOffTheCutPlane) {
  Chord ch;
  // c's proxy position past b: the quadrilateral is not convex at b on the proxy, so the flip's
  // triangle (c, d, b) would turn over there, though it is fine on the surface
  ch.p[ch.c] = ch.surf.point({0.95, 0.38});
  EXPECT_EQ(ch.mend(), 1);
  EXPECT_FALSE(ch.holds_chord());
  ASSERT_EQ(ch.rm.uv.size(), 5u);
  ASSERT_EQ(ch.p.size(), 5u);
  EXPECT_EQ(ch.rm.tris.size(), 4u);
  const Index m = 4;
  EXPECT_NEAR((ch.rm.xyz[m] - ch.surf.point(ch.rm.uv[m])).norm(), 0, 1e-12);
  EXPECT_NEAR((ch.p[m] - ch.rm.xyz[m]).norm(), 0, 1e-12);  // its proxy position from the callback
  // under the cut plane by more than a twentieth of the chord
  EXPECT_LT(ch.cut_plane_offset(m) / std::sqrt(1.25), -0.05 * (ch.rm.xyz[ch.a] - ch.rm.xyz[ch.b]).norm());
  for (const auto& t : ch.rm.tris) {
    EXPECT_TRUE(t[0] == m || t[1] == m || t[2] == m);
    EXPECT_GT(ch.uv_area(t), 0);
  }
}

TEST(PieceAgainstProxy, AChordWhoseMendsLeaveANeedleIsLeftAlone) {
  Chord ch;
  // in the cylinder's developed chart (pi/2 u, v), c and d square to the chord at a, on either
  // side of it, and d a hair towards b: the two triangles have right angles at a, and the flip's
  // triangle (c, a, d) is a needle with its wide corner at a
  const Vec2 a(kPi / 2 * 0.2, CutCylinder::cut_v(0.2)), b(kPi / 2 * 0.8, CutCylinder::cut_v(0.8));
  const Vec2 along = (b - a).normalized(), across(-along.y(), along.x());
  auto chart = [](const Vec2& w) { return Vec2(w.x() / (kPi / 2), w.y()); };
  const Vec2 c = chart(a + 0.4 * across), d = chart(a - 0.4 * across + 0.01 * along);
  ch.rm.uv[ch.c] = c, ch.rm.xyz[ch.c] = ch.p[ch.c] = ch.surf.point(c);
  ch.rm.uv[ch.d] = d, ch.rm.xyz[ch.d] = ch.p[ch.d] = ch.surf.point(d);
  ch.splits = false;
  const auto before = ch.rm.tris;
  EXPECT_EQ(ch.mend(), 0);
  EXPECT_EQ(ch.rm.tris, before);
  // with the split allowed, the node between them mends it without a needle
  ch.splits = true;
  EXPECT_EQ(ch.mend(), 1);
  EXPECT_FALSE(ch.holds_chord());
  EXPECT_EQ(ch.rm.uv.size(), 5u);
}

TEST(PieceAgainstProxy, AnEdgeWithOneEndOffTheCutIsNoChord) {
  Chord ch;
  ch.cuts = {{7}, {8}, {}, {}};  // a and b on different cuts
  const auto before = ch.rm.tris;
  EXPECT_EQ(ch.mend(), 0);
  EXPECT_EQ(ch.rm.tris, before);
  ch.cuts = {{7}, {7}, {}, {}};
  EXPECT_EQ(ch.mend(), 1);
}

TEST(PieceAgainstProxy, NearestPointOfTheProxyFaces) {
  PolyhedralModel m;
  // two unit squares meeting at a right angle along the x axis: z = 0 (y >= 0) and y = 0 (z <= 0)
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(1, 0, -1), Vec3(0, 0, -1)}) m.add_node(p);
  ModelFace top;
  top.loops = {{0, 1, 2, 3}};
  top.normal = Vec3(0, 0, 1), top.offset = 0, top.source = 4;
  ModelFace side;
  side.loops = {{0, 5, 4, 1}};  // counter-clockwise around -y
  side.normal = Vec3(0, -1, 0), side.offset = 0, side.source = 9;
  const Index f0 = m.add_face(top), f1 = m.add_face(side);
  const std::vector<std::pair<Index, bool>> faces = {{f0, false}, {f1, false}};
  Index source = -1;
  // above the top square: straight down onto it
  EXPECT_LT((nearest_on_faces(m, faces, Vec3(0.3, 0.6, 0.2), &source) - Vec3(0.3, 0.6, 0)).norm(), 1e-12);
  EXPECT_EQ(source, 4);
  // in front of the side square
  EXPECT_LT((nearest_on_faces(m, faces, Vec3(0.4, -0.1, -0.5), &source) - Vec3(0.4, 0, -0.5)).norm(), 1e-12);
  EXPECT_EQ(source, 9);
  // past both squares' far edge: onto the top square's edge x = 1
  EXPECT_LT((nearest_on_faces(m, faces, Vec3(1.5, 0.5, 0.1), &source) - Vec3(1, 0.5, 0)).norm(), 1e-12);
}

}  // namespace
}  // namespace bisect::pipeline
