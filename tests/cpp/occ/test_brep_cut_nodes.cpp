// Where a node the cuts made inside a proxy face goes on the true face (pipeline/brep_boundary.hpp,
// cut_node_image). Beside a hole the proxy's chords cut across the hole's arc: the planar face's
// proxy polygon holds a sliver between chord and arc that the true face does not, and a cut line
// through that sliver left its nodes inside the hole (corpus/Kurbelwelle.brep folded there, on
// every proxy). Such a node moves as the chords move onto the arc, and lands on the face.
#include <gtest/gtest.h>

#include <cmath>

#include "bisect/polyhedral_model.hpp"
#include "occ_checks.hpp"
#include "occ_shapes.hpp"
#include "pipeline/brep_boundary.hpp"
#include "pipeline/brep_proxy.hpp"
#include "size/size_field.hpp"
#include "bisect/errors.hpp"

namespace bisect {
namespace {

// the box [0,4] x [0,4] x [0,2] minus a cylinder of radius 1 on (2, 2, z): its top face z = 2
// has the hole's circle as an inner wire
struct HolePlate {
  BrepInput in = test::input_of(test::make_box_minus_cylinder(), "box minus cylinder");
  // coarse chords (BRepMesh makes them 30 degrees of the circle): the sliver is 0.03 deep
  pipeline::BrepProxy px = pipeline::make_proxy(in, 0.5, M_PI / 3);
  PolyhedralModel model = prepare_model(px.input);
  pipeline::BrepBoundary bd{in, px, model};
  Index top = -1, top_proxy = -1, circle = -1;

  HolePlate() {
    for (std::size_t k = 0; k < in.faces.size(); ++k) {
      const BrepFace& f = in.faces[k];
      if (f.planar && f.wires.size() == 2 && std::abs(f.surface->point(f.surface->uv_min()).z() - 2) < 1e-9) top = static_cast<Index>(k);
    }
    for (std::size_t s = 0; s < px.face_brep.size(); ++s)
      if (px.face_brep[s] == top && px.input.faces[s].hole_of < 0) top_proxy = static_cast<Index>(s);
    if (top >= 0) circle = in.faces[top].wires[1].front().edge;
  }
  pipeline::PointOn on_top() const {
    pipeline::PointOn on;
    on.kind = pipeline::PointOn::kFace, on.id = top, on.proxy = top_proxy;
    return on;
  }
  // the radius about the hole's axis
  static double radius(const Vec3& x) { return std::hypot(x.x() - 2, x.y() - 2); }
};

TEST(BrepCutNodes, ANodeInTheSliverBetweenChordAndArcLandsOnTheFace) {
  const HolePlate plate;
  ASSERT_GE(plate.top, 0);
  ASSERT_GE(plate.top_proxy, 0);
  ASSERT_GE(plate.circle, 0);
  const auto& chain = plate.px.tess.edges[plate.circle].nodes;
  ASSERT_GE(chain.size(), 4u);  // the circle in a few chords
  int checked = 0;
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    const Vec3 a = plate.model.nodes[chain[i]], b = plate.model.nodes[chain[i + 1]];
    if (std::abs(a.z() - 2) > 1e-9) continue;  // the circle at the top
    const Vec3 mid = 0.5 * (a + b);
    const double sag = 1 - HolePlate::radius(mid);
    ASSERT_GT(sag, 0.01);
    const Vec3 out = Vec3(mid.x() - 2, mid.y() - 2, 0).normalized();
    // points of the proxy facet inside the hole: a third and two thirds of the way to the arc
    for (double f : {1.0 / 3, 2.0 / 3}) {
      const Vec3 p = mid + f * sag * out;
      ASSERT_LT(HolePlate::radius(p), 1);
      EXPECT_LT(HolePlate::radius(plate.bd.image(plate.on_top(), p)), 1) << "the surface's own nearest point stays in the hole";
      const Vec3 x = plate.bd.cut_node_image(plate.on_top(), p);
      EXPECT_NEAR(x.z(), 2, 1e-9) << "on the face's plane";
      EXPECT_GT(HolePlate::radius(x), 1 + 0.5 * f * sag) << "outside the hole, as far out as it was in from the chord";
      ++checked;
    }
    // a point on the chord itself goes onto the arc
    EXPECT_NEAR(HolePlate::radius(plate.bd.cut_node_image(plate.on_top(), mid)), 1, 1e-6);
  }
  EXPECT_GE(checked, 6);
}

TEST(BrepCutNodes, NodesAwayFromCurvedEdgesStayWhereTheyAre) {
  const HolePlate plate;
  ASSERT_GE(plate.top, 0);
  // beside the box's straight edges and farther than a chord's length from the circle
  for (const Vec3& p : {Vec3(0.3, 0.3, 2), Vec3(3.9, 2, 2), Vec3(2, 0.05, 2)}) {
    const Vec3 x = plate.bd.cut_node_image(plate.on_top(), p);
    EXPECT_NEAR((x - p).norm(), 0, 1e-12) << p.transpose();
  }
  // nearer the hole the shift fades: smaller than the sag, towards the arc
  const Vec3 near(2, 2 - 1.3, 2);
  const Vec3 shift = plate.bd.cut_node_image(plate.on_top(), near) - near;
  EXPECT_LT(shift.norm(), 0.14);
  EXPECT_LE(shift.y(), 1e-12) << "away from the hole's axis";
}

TEST(BrepCutNodes, EdgesAreDiscretisedTheSameOnEveryThreadCount) {
  // the plate's model edges at a size graded down to 0.05 at the hole's near side: inner nodes on
  // the circle's chords (on the true arc), on straight edges, and on the plate's faces; made on
  // 1, 2 and 4 threads, the same nodes in the same order, each pair of ends' inner nodes listed
  HolePlate plate;
  size::SizeField h(0.4, 0.3);
  h.add(Vec3(1, 2, 2), 0.05);
  h.finish();
  plate.bd.discretise_edges(h, {}, 1);
  const pipeline::BoundaryNodes one = plate.bd.nodes;
  const auto lists = plate.bd.edge_nodes;
  ASSERT_GT(one.x.size(), plate.model.nodes.size() + 100);  // inner nodes made
  std::size_t inner = 0;
  for (const auto& [ends, nodes] : lists) inner += nodes.size();
  EXPECT_EQ(inner, one.x.size() - plate.model.nodes.size());  // each inner node on one edge's list
  for (int threads : {2, 4}) {
    plate.bd.discretise_edges(h, {}, threads);
    EXPECT_EQ(plate.bd.edge_nodes, lists) << threads << " threads";
    ASSERT_EQ(plate.bd.nodes.x.size(), one.x.size()) << threads << " threads";
    for (std::size_t v = 0; v < one.x.size(); ++v) {
      ASSERT_EQ(plate.bd.nodes.x[v], one.x[v]) << "node " << v << ", " << threads << " threads";
      ASSERT_EQ(plate.bd.nodes.p[v], one.p[v]) << "node " << v << ", " << threads << " threads";
      ASSERT_EQ(plate.bd.nodes.on[v].kind, one.on[v].kind);
      ASSERT_EQ(plate.bd.nodes.on[v].id, one.on[v].id);
      ASSERT_EQ(plate.bd.nodes.on[v].t, one.on[v].t);
    }
  }
  // a cancelled discretisation throws, from whichever thread asks
  EXPECT_THROW(plate.bd.discretise_edges(h, [] { return true; }, 2), Cancelled);
}

}  // namespace
}  // namespace bisect
