// BRepMesh's tessellation as a BrepTessellation: welded along edges, closed per solid, each
// corner's (u, v) on its node, seams with one (u, v) per side, poles as one node.
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "bisect/occ_checker.hpp"
#include "input_error.hpp"
#include "occ_checks.hpp"
#include "occ_shape.hpp"
#include "occ_shapes.hpp"

namespace bisect {
namespace {

using test::input_of;

struct Built {
  const char* name;
  TopoDS_Shape (*make)();
  double volume;  // 0: not known in closed form (then BRepGProp's alone is the reference)
};

class OccTessellation : public ::testing::TestWithParam<Built> {};

TEST_P(OccTessellation, IsClosedAndOnTheShape) {
  const BrepInput in = input_of(GetParam().make(), GetParam().name);
  const BrepChecker check(in);
  if (GetParam().volume > 0) {
    EXPECT_NEAR(check.volume(), GetParam().volume, 1e-6 * GetParam().volume);
  }
  const double size = test::size_of(in);
  const BrepTessellation t = in.tessellate(1e-3 * size, 0.2);
  const auto r = test::check_tessellation(in, t, check, 0.01);
  EXPECT_EQ(r.nodes_checked, t.nodes.size());
  // every vertex is one node, made first
  for (size_t v = 0; v < in.vertices.size(); ++v) {
    EXPECT_EQ(t.node_vertex[v], static_cast<Index>(v));
    EXPECT_EQ(t.nodes[v], in.vertices[v].point);
  }
}

INSTANTIATE_TEST_SUITE_P(Built, OccTessellation,
                         ::testing::Values(Built{"box", test::make_box, 6}, Built{"cylinder", test::make_cylinder, 2 * M_PI},
                                           Built{"sphere", test::make_sphere, 32 * M_PI / 3},
                                           Built{"box_minus_cylinder", test::make_box_minus_cylinder, 32 - 2 * M_PI},
                                           Built{"two_box_compsolid", test::make_two_box_compsolid, 2},
                                           Built{"box_with_cavity", test::make_box_with_cavity, 64 - 4 * M_PI / 3},
                                           Built{"nurbs_part", test::make_nurbs_part, 32 - 2 * M_PI},
                                           Built{"revolved_bspline", test::make_revolved_bspline, 0}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(OccTessellationDetail, BoxIsTwelveTrianglesOnItsCorners) {
  const BrepInput in = input_of(test::make_box(), "box");
  const BrepTessellation t = in.tessellate(0.1, 0.5);
  EXPECT_EQ(t.nodes.size(), 8u);
  size_t tris = 0;
  for (const auto& f : t.faces) tris += f.tris.size();
  EXPECT_EQ(tris, 12u);
  for (const auto& e : t.edges) EXPECT_EQ(e.nodes.size(), 2u);
}

TEST(OccTessellationDetail, SeamNodesHaveOneUVPerSide) {
  const BrepInput in = input_of(test::make_cylinder(), "cylinder");
  const BrepTessellation t = in.tessellate(0.01, 0.2);
  Index seam = -1, lateral = -1;
  for (size_t e = 0; e < in.edges.size(); ++e)
    if (in.edges[e].v0 != in.edges[e].v1) seam = static_cast<Index>(e);  // the circles are closed edges
  for (size_t f = 0; f < in.faces.size(); ++f)
    if (!in.faces[f].planar) lateral = static_cast<Index>(f);
  ASSERT_GE(seam, 0);
  ASSERT_GE(lateral, 0);
  const auto& nodes = t.edges[seam].nodes;
  ASSERT_GE(nodes.size(), 2u);
  // every node of the seam is met at u = u_min by some triangles and at u = u_max by others
  const double u0 = in.faces[lateral].surface->uv_min().x(), u1 = in.faces[lateral].surface->uv_max().x();
  for (Index n : nodes) {
    std::set<int> sides;
    const auto& tf = t.faces[lateral];
    for (size_t k = 0; k < tf.tris.size(); ++k)
      for (int c = 0; c < 3; ++c)
        if (tf.tris[k][c] == n) {
          if (std::abs(tf.uv[k][c].x() - u0) < 1e-9) sides.insert(0);
          if (std::abs(tf.uv[k][c].x() - u1) < 1e-9) sides.insert(1);
        }
    EXPECT_EQ(sides.size(), 2u) << "node " << n;
  }
}

TEST(OccTessellationDetail, PolesAreOneNode) {
  const BrepInput in = input_of(test::make_sphere(), "sphere");
  const BrepTessellation t = in.tessellate(0.01, 0.2);
  for (size_t e = 0; e < in.edges.size(); ++e) {
    if (!in.edges[e].degenerate) continue;
    ASSERT_EQ(t.edges[e].nodes.size(), 1u);
    const Index pole = t.edges[e].nodes[0];
    EXPECT_EQ(t.node_vertex[pole], in.edges[e].v0);
    int at = 0;
    for (const auto& n : t.nodes) at += (n - t.nodes[pole]).norm() < 1e-9;
    EXPECT_EQ(at, 1) << "no other node at the pole";
    int fan = 0;
    for (const auto& tri : t.faces[0].tris) fan += std::count(tri.begin(), tri.end(), pole);
    EXPECT_GE(fan, 3) << "the pole is a corner of the triangles around it";
  }
}

TEST(OccTessellationDetail, InterfaceIsMeshedOnce) {
  const BrepInput in = input_of(test::make_two_box_compsolid(), "two boxes");
  const BrepTessellation t = in.tessellate(0.05, 0.5);
  // the shared face's triangles exist once; each solid's own check counts them from its side
  std::set<std::array<Index, 3>> seen;
  for (const auto& f : t.faces)
    for (auto tri : f.tris) {
      std::sort(tri.begin(), tri.end());
      EXPECT_TRUE(seen.insert(tri).second) << "a triangle listed twice";
    }
  EXPECT_EQ(t.nodes.size(), 12u);
}

TEST(OccTessellationDetail, EachCallMeshesAfreshAndLeavesTheShapeAlone) {
  const BrepInput in = input_of(test::make_box_minus_cylinder(), "box minus cylinder");
  auto triangles = [](const BrepTessellation& t) {
    size_t n = 0;
    for (const auto& f : t.faces) n += f.tris.size();
    return n;
  };
  const size_t fine = triangles(in.tessellate(0.002, 0.1));
  const size_t coarse = triangles(in.tessellate(0.1, 0.8));
  EXPECT_LT(coarse, fine / 4) << "a coarser call does not keep the finer triangulation";
  // the same call twice gives the same tessellation (BRepMesh runs its faces in parallel)
  const BrepTessellation a = in.tessellate(0.01, 0.3), b = in.tessellate(0.01, 0.3);
  EXPECT_EQ(a.nodes, b.nodes);
  for (size_t f = 0; f < a.faces.size(); ++f) EXPECT_EQ(a.faces[f].tris, b.faces[f].tris);
  // the shape the input holds has no triangulation of its own
  for (TopExp_Explorer ex(occ::occ_shape_of(in).shape, TopAbs_FACE); ex.More(); ex.Next()) {
    TopLoc_Location loc;
    EXPECT_TRUE(BRep_Tool::Triangulation(TopoDS::Face(ex.Current()), loc).IsNull());
  }
}

TEST(OccTessellationDetail, RefusesNonPositiveDeflections) {
  const BrepInput in = input_of(test::make_box(), "Box");
  EXPECT_HAS(test::error_of([&] { in.tessellate(0, 0.5); }), "Box: the tessellation needs a positive");
  EXPECT_HAS(test::error_of([&] { in.tessellate(0.1, -1); }), "Box: the tessellation needs a positive");
}

}  // namespace
}  // namespace bisect
