// PolyhedralModel's operations (thesis 7.2.1) and the polygon split under them.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "bisect/io.hpp"
#include "bisect/polyhedral_model.hpp"
#include "domain/face_split.hpp"
#include "poly_shapes.hpp"

namespace bisect {
namespace {

PolyhedralModel square_model(std::vector<Vec3> pts, std::vector<std::vector<Index>> loops) {
  PolyhedralModel m;
  for (const Vec3& p : pts) m.add_node(p);
  ModelFace f;
  f.loops = std::move(loops);
  f.normal = Vec3::UnitZ();
  m.regions.push_back({});
  f.back = 0;
  m.regions[0].faces.push_back(m.add_face(f));
  return m;
}

TEST(PolyhedralModel, VertexGoesIntoEveryFaceOfTheEdge) {
  std::istringstream in(test::unit_cube());
  PolyhedralModel m = prepare_model(read_poly(in, "cube.poly"));
  const Index v = m.insert_vertex_in_edge(0, 1, Vec3(0.5, 0, 0));
  int with = 0;
  for (const ModelFace& f : m.faces) {
    const auto& l = f.loops[0];
    const bool has = std::find(l.begin(), l.end(), v) != l.end();
    with += has;
    if (has) {
      EXPECT_EQ(l.size(), 5u);
    }
  }
  EXPECT_EQ(with, 2);
  EXPECT_EQ(m.faces_of_node(v).size(), 2u);
  EXPECT_NEAR(m.region_volume(0), 1.0, 1e-15);
}

TEST(PolyhedralModel, SplitFaceKeepsNormalSidesAndArea) {
  PolyhedralModel m = square_model({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 4, 1, 2, 5, 3}});
  m.faces[0].source = 7;
  const auto pieces = m.split_face(0, {{{4, 5}}});
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_FALSE(m.faces[0].alive);
  for (Index p : pieces) {
    EXPECT_NEAR(m.face_area(p), 1.0, 1e-15);
    EXPECT_EQ(m.faces[p].source, 7);
    EXPECT_EQ(m.faces[p].back, 0);
    EXPECT_EQ(m.faces[p].normal, Vec3::UnitZ());
  }
  EXPECT_EQ(m.live_faces(0).size(), 2u);
}

TEST(FaceSplit, ChordsThroughAHoleLeaveNoHole) {
  // a 4x4 square with a 2x2 hole, cut by the line x = 2 through both
  std::vector<Vec2> p = {{0, 0}, {2, 0}, {4, 0}, {4, 4}, {2, 4}, {0, 4}, {1, 1}, {2, 1}, {3, 1}, {3, 3}, {2, 3}, {1, 3}};
  auto pos = [&](Index v) { return p[v]; };
  const std::vector<std::vector<Index>> loops = {{0, 1, 2, 3, 4, 5}, {6, 11, 10, 9, 8, 7}};
  const auto pieces = split_polygon_by_chords(loops, {{{1, 7}}, {{10, 4}}}, pos);
  ASSERT_EQ(pieces.size(), 2u);
  for (const auto& piece : pieces) {
    EXPECT_EQ(piece.size(), 1u);  // no hole left
    EXPECT_NEAR(loop_area2(piece[0], pos), 2 * 6.0, 1e-12);
  }
}

TEST(FaceSplit, UntouchedHoleGoesToThePieceAroundIt) {
  std::vector<Vec2> p = {{0, 0}, {4, 0}, {4, 2}, {4, 4}, {0, 4}, {0, 2}, {1, 0.5}, {1, 1.5}, {2, 1.5}, {2, 0.5}};
  auto pos = [&](Index v) { return p[v]; };
  const auto pieces = split_polygon_by_chords({{0, 1, 2, 3, 4, 5}, {6, 7, 8, 9}}, {{{2, 5}}}, pos);
  ASSERT_EQ(pieces.size(), 2u);
  std::size_t holes = 0;
  for (const auto& piece : pieces) holes += piece.size() - 1;
  EXPECT_EQ(holes, 1u);
  for (const auto& piece : pieces) {
    if (piece.size() == 2) {  // the hole sits in the lower piece
      EXPECT_LT(pos(piece[0][0]).y() + pos(piece[0][1]).y() + pos(piece[0][2]).y(), 6.5);
    }
  }
}

TEST(FaceSplit, TurningAngleSumTellsOuterFromInner) {
  const std::vector<Vec2> ccw = {{0, 0}, {2, 0}, {2, 2}, {1, 0.5}, {0, 2}};  // concave, CCW
  std::vector<Vec2> cw(ccw.rbegin(), ccw.rend());
  EXPECT_NEAR(turning_angle_sum(ccw), 2 * M_PI, 1e-12);
  EXPECT_NEAR(turning_angle_sum(cw), -2 * M_PI, 1e-12);
}

}  // namespace
}  // namespace bisect
