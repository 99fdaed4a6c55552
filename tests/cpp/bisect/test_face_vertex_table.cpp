// The face-vertex list of thesis 7.2.2 on an L-shaped prism and on two cubes sharing a face.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>

#include "bisect/io.hpp"
#include "bisect/face_vertex_table.hpp"
#include "poly_shapes.hpp"

namespace bisect {
namespace {

PolyhedralModel model(const std::string& text) { return prepare_model(test::poly(text)); }

TEST(FaceVertexTable, LoopsNeighboursAndAnglesStoredOnce) {
  const PolyhedralModel m = model(test::l_prism());
  const FaceVertexTable t = build_face_vertex_table(m, 0);
  ASSERT_EQ(t.entries.size(), 2u * 6 + 6u * 4);
  std::size_t stored = 0, reflex = 0;
  for (std::size_t e = 0; e < t.entries.size(); ++e) {
    const FaceVertex& fv = t.entries[e];
    EXPECT_EQ(t.entries[fv.succ].pred, static_cast<Index>(e));
    ASSERT_GE(fv.adj_cw, 0);
    // the neighbour is another face on the same edge (in its own direction: .poly faces keep
    // the direction the file gave)
    const FaceVertex& nb = t.entries[fv.adj_cw];
    EXPECT_NE(nb.face, fv.face);
    const std::set<Index> mine{fv.node, t.entries[fv.succ].node}, theirs{nb.node, t.entries[nb.succ].node};
    EXPECT_EQ(mine, theirs);
    if (!std::isnan(fv.angle)) ++stored;
    const double a = t.edge_angle(static_cast<Index>(e));
    ASSERT_FALSE(std::isnan(a));
    if (a > M_PI + 1e-9) {
      ++reflex;
      EXPECT_NEAR(a, 1.5 * M_PI, 1e-12);
    } else {
      EXPECT_NEAR(a, 0.5 * M_PI, 1e-12);
    }
  }
  EXPECT_EQ(stored, 18u);  // 18 edges, one angle each
  EXPECT_EQ(reflex, 2u);   // the reflex edge, seen from both of its faces
}

TEST(FaceVertexTable, InterfaceFaceHasANeighbourInEachRegion) {
  const PolyhedralModel m = model(R"(11 12 2 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
2 0 0
2 1 0
2 1 1
2 0 1
4 1 2 3 4
4 5 6 7 8
4 1 2 6 5
4 3 4 8 7
4 4 1 5 8
4 2 3 7 6
4 2 9 10 3
4 6 12 11 7
4 2 9 12 6
4 3 10 11 7
4 9 10 11 12
6 1 2 3 4 5 6
6 6 7 8 9 10 11
)");
  const FaceVertexTable t = build_face_vertex_table(m, 0);
  for (const FaceVertex& fv : t.entries) {
    if (m.faces[fv.face].source != 5) continue;  // the shared face x = 1
    ASSERT_GE(fv.adj_cw, 0);
    ASSERT_GE(fv.adj_ccw, 0);
    EXPECT_NE(t.entries[fv.adj_cw].face, t.entries[fv.adj_ccw].face);
  }
}

}  // namespace
}  // namespace bisect
