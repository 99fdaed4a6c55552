// Face moves on the B-rep route (optimize/mean_shape.hpp): the mean shape's passes move nodes
// inside B-rep faces within them. On a box with a box-shaped cavity (walls 0.25 thick, like
// ../shared's two-boxes-cavity) at R = 1000: the mean α̂ rises, every boundary node stays exactly
// in its face's plane, and at order 2 the mid-nodes of the moved nodes' edges are placed from
// where the nodes went (the middle of the edge on a flat face), so every element stays positive
// at its corners and Gauss points. On a box with a spherical cavity, the nodes that move on the
// sphere stay on it, mid-nodes included (but those of straightened edges, at their chords'
// middles), and the surface's smallest angle stays at least what it was or 30 degrees.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

#include "bisect/generate.hpp"
#include "bisect/quality.hpp"
#include "bisect/validate.hpp"
#include "occ_checks.hpp"
#include "occ_shapes.hpp"

namespace bisect {
namespace {

// [0,2] x [0,1] x [0,1] less [0.25,1.75] x [0.25,0.75] x [0.25,0.75]: the planes of its faces
BrepInput hollow_box() {
  const TopoDS_Shape outer = BRepPrimAPI_MakeBox(2, 1, 1).Shape();
  const TopoDS_Shape inner = BRepPrimAPI_MakeBox(gp_Pnt(0.25, 0.25, 0.25), 1.5, 0.5, 0.5).Shape();
  return test::input_of(BRepAlgoAPI_Cut(outer, inner).Shape(), "hollow box");
}
const std::array<std::vector<double>, 3> kPlanes = {{{0, 0.25, 1.75, 2}, {0, 0.25, 0.75, 1}, {0, 0.25, 0.75, 1}}};

bool in_a_face_plane(const Vec3& p) {
  for (int k = 0; k < 3; ++k)
    if (std::find(kPlanes[k].begin(), kPlanes[k].end(), p[k]) != kPlanes[k].end()) return true;
  return false;
}

// The shape at R, order 2, without the face moves (m[0]) and with them (m[1]), each validated.
struct BothWays {
  TetMesh m[2];
  GenerateStats st[2];
  BothWays(const BrepInput& in, std::int64_t elements) {
    for (int moves : {0, 1}) {
      GenerateOptions opt;
      opt.sizing.elements = elements;
      opt.order = 2;
      opt.optimize.face_moves = moves == 1;
      m[moves] = generate_brep_mesh(in, opt, &st[moves]);
      EXPECT_TRUE(validate(m[moves]).empty()) << moves;
    }
  }
};

TEST(BrepFaceMoves, NodesSlideInTheirPlanesAndTheMidNodesFollow) {
  BothWays both(hollow_box(), 1000);
  const TetMesh* m = both.m;
  // the corners (mid-nodes come after them; their count follows the edges, which the passes'
  // transformations change): the same ids in both
  Index corners[2] = {0, 0};
  for (int k : {0, 1})
    for (std::size_t t = 0; t < m[k].num_tets(); ++t)
      for (int i = 0; i < 4; ++i) corners[k] = std::max(corners[k], m[k].tet_node(t, i) + 1);
  ASSERT_EQ(corners[0], corners[1]);
  const QualitySummary q0 = summarize_quality(element_quality(m[0])), q1 = summarize_quality(element_quality(m[1]));
  // measured 0.2471 -> 0.2504
  EXPECT_GT(q1.alpha.mean, q0.alpha.mean + 0.002);
  EXPECT_GE(q1.alpha.mean, 0.24);
  EXPECT_GE(q1.dihedral_min.min, std::min(q0.dihedral_min.min, 10.5));
  RecordProperty("alpha_mean", std::to_string(q0.alpha.mean) + " -> " + std::to_string(q1.alpha.mean));
  std::size_t moved = 0;
  const TetMesh& b = m[1];
  for (std::size_t t = 0; t < b.num_tris(); ++t) {
    const Index* v = &b.tris[6 * t];
    for (int i = 0; i < 3; ++i) {
      EXPECT_TRUE(in_a_face_plane(b.nodes[v[i]])) << "node " << v[i] << " off its face";
      moved += b.nodes[v[i]] != m[0].nodes[v[i]];
    }
    // each mid-node at the middle of its edge: on a flat face the true surface's mid-point is
    // the chord's
    for (int e = 0; e < 3; ++e) {
      const Vec3 middle = 0.5 * (b.nodes[v[kTriEdge[e][0]]] + b.nodes[v[kTriEdge[e][1]]]);
      EXPECT_LT((b.nodes[v[3 + e]] - middle).norm(), 1e-12) << "boundary triangle " << t << ", mid-node " << v[3 + e];
    }
  }
  EXPECT_GT(moved, 20u);
}

TEST(BrepFaceMoves, NodesOnACurvedFaceStayOnIt) {
  BothWays both(test::input_of(test::make_box_with_cavity(), "box with a spherical cavity"), 3000);
  const TetMesh* m = both.m;
  const GenerateStats* st = both.st;
  const Vec3 centre(2, 2, 2);
  const TetMesh& b = m[1];
  std::size_t on_sphere = 0, moved = 0;  // corners of triangles, counted once per triangle
  std::set<Index> straight;  // mid-nodes of edges made straight to keep the Jacobian positive
  for (std::size_t t = 0; t < b.num_tris(); ++t)
    for (int i = 0; i < 6; ++i) {
      const Index v = b.tris[6 * t + i];
      const Vec3& p = b.nodes[v];
      const bool on_box = std::min({p.minCoeff(), 4 - p.maxCoeff()}) < 1e-9;
      if (on_box) continue;
      ++on_sphere;
      if (i >= 3 && std::abs((p - centre).norm() - 1) > 1e-9) {
        // not on the sphere: at the middle of its chord, one of the edges the stats count
        const Index* c = &b.tris[6 * t];
        const Index e0 = c[kTriEdge[i - 3][0]], e1 = c[kTriEdge[i - 3][1]];
        EXPECT_LT((p - 0.5 * (b.nodes[e0] + b.nodes[e1])).norm(), 1e-12) << "mid-node " << v;
        straight.insert(v);
        continue;
      }
      EXPECT_NEAR((p - centre).norm(), 1.0, 1e-9) << "node " << v << (i < 3 ? "" : " (a mid-node)");
      if (i >= 3) {  // over its own edge: within 8 sagittas (L^2 / 8 each on the unit sphere) of the chord's middle
        const Index* c = &b.tris[6 * t];
        const Vec3 &a = b.nodes[c[kTriEdge[i - 3][0]]], &z = b.nodes[c[kTriEdge[i - 3][1]]];
        EXPECT_LT((p - 0.5 * (a + z)).norm(), (z - a).squaredNorm()) << "mid-node " << v << " is not over its edge";
      }
      if (i < 3 && static_cast<std::size_t>(v) < m[0].nodes.size()) moved += p != m[0].nodes[v];
    }
  EXPECT_LE(static_cast<std::int64_t>(straight.size()), st[1].straightened_edges);
  EXPECT_GT(on_sphere, 100u);
  EXPECT_GT(moved, 10u);
  EXPECT_GE(surface_min_angle_deg(m[1]), std::min(surface_min_angle_deg(m[0]), 30.0) - 1e-9);
  RecordProperty("surface_min_angle", std::to_string(surface_min_angle_deg(m[0])) + " -> " + std::to_string(surface_min_angle_deg(m[1])));
}

}  // namespace
}  // namespace bisect
