// Face moves on the B-rep route (optimize/mean_shape.hpp): the mean shape's passes move nodes
// inside B-rep faces within them. On a box with a box-shaped cavity (walls 0.25 thick, like
// ../shared's two-boxes-cavity) at R = 1000: the mean α̂ rises, every boundary node stays exactly
// in its face's plane, and at order 2 the mid-nodes of the moved nodes' edges are placed from
// where the nodes went (the middle of the edge on a flat face), so every element stays positive
// at its corners and Gauss points. On a box with a spherical cavity, the nodes that move on the
// sphere stay on it, mid-nodes included (but those of straightened edges, at their chords'
// middles), the nodes of its seam and of the box's edges move along them only (their mid-nodes
// on them), and the surface's smallest angle stays at least what it was or 30 degrees.
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

// The positions of the boundary triangles' corners.
std::set<std::array<double, 3>> triangle_corners(const TetMesh& m) {
  std::set<std::array<double, 3>> out;
  for (std::size_t t = 0; t < m.num_tris(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Vec3& p = m.nodes[m.tris[m.nodes_per_tri() * t + i]];
      out.insert({p.x(), p.y(), p.z()});
    }
  return out;
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
  // corners no longer where any corner of the mesh without the moves is (positions, not ids)
  const std::set<std::array<double, 3>> corners_before = triangle_corners(m[0]);
  std::size_t moved = 0;
  const TetMesh& b = m[1];
  for (std::size_t t = 0; t < b.num_tris(); ++t) {
    const Index* v = &b.tris[6 * t];
    for (int i = 0; i < 3; ++i) {
      EXPECT_TRUE(in_a_face_plane(b.nodes[v[i]])) << "node " << v[i] << " off its face";
      moved += !corners_before.count({b.nodes[v[i]].x(), b.nodes[v[i]].y(), b.nodes[v[i]].z()});
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

TEST(BrepFaceMoves, NodesOnACurvedFaceAndItsEdgesStayOnThem) {
  BothWays both(test::input_of(test::make_box_with_cavity(), "box with a spherical cavity"), 3000);
  const TetMesh* m = both.m;
  const GenerateStats* st = both.st;
  const Vec3 centre(2, 2, 2);
  const TetMesh& b = m[1];
  // (the two meshes number their nodes differently: positions are compared as sets)
  const std::set<std::array<double, 3>> corners_before = triangle_corners(m[0]);
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
      if (i < 3) moved += !corners_before.count({p.x(), p.y(), p.z()});
    }
  EXPECT_LE(static_cast<std::int64_t>(straight.size()), st[1].straightened_edges);
  EXPECT_GT(on_sphere, 100u);
  EXPECT_GT(moved, 10u);

  // Nodes inside the B-rep edges (the box's twelve, the sphere's seam: its meridian at y = 2,
  // x > 2) move along them only, and the mid-node of a mesh edge that runs along one (between
  // two of its nodes with none of its nodes between them) lies on it, between them.
  struct OnEdge {
    int edge = -1;  // 0-11 the box's, 12 the seam; -1 none (or a vertex)
    double t = 0;   // the free coordinate on the box's, the angle from the equator on the seam
  };
  const auto edge_of = [&](const Vec3& p) {
    OnEdge on;
    int bounding = 0, free = -1, code = 0;
    for (int k = 0; k < 3; ++k) {
      if (std::abs(p[k]) < 1e-12 || std::abs(p[k] - 4) < 1e-12) ++bounding, code = 2 * code + (p[k] > 2);
      else free = k;
    }
    if (bounding == 2) on.edge = 4 * free + code, on.t = p[free];
    const Vec3 d = p - centre;
    if (std::abs(d.norm() - 1) < 1e-9 && std::abs(d.y()) < 1e-9 && d.x() > 1e-9) on.edge = 12, on.t = std::atan2(d.z(), d.x());
    return on;
  };
  // (each edge's nodes are compared as sets)
  std::array<std::vector<double>, 13> params[2];  // the corners' parameters on each edge
  std::set<std::array<double, 3>> seam_before;
  for (int w : {0, 1})
    for (std::size_t t = 0; t < m[w].num_tris(); ++t)
      for (int i = 0; i < 3; ++i) {
        const Index v = m[w].tris[6 * t + i];
        const OnEdge on = edge_of(m[w].nodes[v]);
        if (on.edge < 0) continue;
        params[w][on.edge].push_back(on.t);
        if (on.edge == 12 && w == 0) seam_before.insert({m[w].nodes[v].x(), m[w].nodes[v].y(), m[w].nodes[v].z()});
      }
  std::size_t edge_nodes = 0, seam_moved = 0, along_mids = 0;
  for (int e = 0; e < 13; ++e)
    for (auto& p : params) {
      std::sort(p[e].begin(), p[e].end());
      p[e].erase(std::unique(p[e].begin(), p[e].end()), p[e].end());
    }
  for (int e = 0; e < 13; ++e) {
    EXPECT_EQ(params[1][e].size(), params[0][e].size()) << "edge " << e << ": nodes came onto it or left it";
    edge_nodes += params[1][e].size();
  }
  std::set<Index> seam_corners;
  for (std::size_t t = 0; t < b.num_tris(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Vec3& p = b.nodes[b.tris[6 * t + i]];
      if (edge_of(p).edge == 12 && !seam_before.count({p.x(), p.y(), p.z()})) seam_corners.insert(b.tris[6 * t + i]);
    }
  seam_moved = seam_corners.size();
  for (std::size_t t = 0; t < b.num_tris(); ++t) {
    const Index* c = &b.tris[6 * t];
    for (int k = 0; k < 3; ++k) {
      const OnEdge a = edge_of(b.nodes[c[kTriEdge[k][0]]]), z = edge_of(b.nodes[c[kTriEdge[k][1]]]);
      if (a.edge < 0 || z.edge != a.edge || straight.count(c[3 + k])) continue;
      const double lo = std::min(a.t, z.t), hi = std::max(a.t, z.t);
      if (std::any_of(params[1][a.edge].begin(), params[1][a.edge].end(), [&](double u) { return u > lo + 1e-12 && u < hi - 1e-12; })) continue;
      ++along_mids;
      const OnEdge mid = edge_of(b.nodes[c[3 + k]]);
      EXPECT_EQ(mid.edge, a.edge) << "mid-node " << c[3 + k];
      EXPECT_TRUE(mid.t > lo && mid.t < hi) << "mid-node " << c[3 + k] << " is not between its corners";
    }
  }
  EXPECT_GT(edge_nodes, 20u);
  EXPECT_GT(along_mids, 20u);
  EXPECT_GT(seam_moved, 0u);
  RecordProperty("seam_nodes_moved", std::to_string(seam_moved));
  EXPECT_GE(surface_min_angle_deg(m[1]), std::min(surface_min_angle_deg(m[0]), 30.0) - 1e-9);
  RecordProperty("surface_min_angle", std::to_string(surface_min_angle_deg(m[0])) + " -> " + std::to_string(surface_min_angle_deg(m[1])));
}

}  // namespace
}  // namespace bisect
