// The proxy (pipeline/brep_proxy.hpp): BRepMesh's tessellation made a polyhedron the
// decomposition can take. A pole's fan that has area in (u, v) and none in space is flipped
// away (corpus/Block.brep's half cone crossed its neighbours there at every deflection).
#include <BRepPrimAPI_MakeCone.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "occ_checks.hpp"
#include "pipeline/brep_proxy.hpp"

namespace bisect {
namespace {

// twice the area under 1e-6 of the longest side squared (the proxy's own bound)
bool flat(const std::vector<Vec3>& X, Index a, Index b, Index c) {
  const double longest = std::max({(X[b] - X[a]).squaredNorm(), (X[c] - X[b]).squaredNorm(), (X[a] - X[c]).squaredNorm()});
  return (X[b] - X[a]).cross(X[c] - X[a]).norm() <= 1e-6 * longest;
}

TEST(BrepProxy, HalfConeApexFanHasNoFlatFacets) {
  // half a cone with its apex at the origin: the apex is a degenerate edge's one node, at
  // (0, 0) in (u, v) where BRepMesh fans from it to the nodes of one generatrix
  const BrepInput in = test::input_of(BRepPrimAPI_MakeCone(0, 5, 10, M_PI).Shape(), "half cone");
  Index cone = -1;
  for (std::size_t f = 0; f < in.faces.size(); ++f)
    if (!in.faces[f].planar) cone = static_cast<Index>(f);
  ASSERT_GE(cone, 0);
  const double linear = 0.05, angular = 0.2;
  const BrepTessellation raw = in.tessellate(linear, angular);
  int raw_flat = 0, raw_tris = 0;
  for (const auto& t : raw.faces[cone].tris) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
    ++raw_tris;
    raw_flat += flat(raw.nodes, t[0], t[1], t[2]);
  }
  EXPECT_GT(raw_flat, 0) << "BRepMesh no longer fans from the apex along a generatrix: this test shows nothing";
  const pipeline::BrepProxy px = pipeline::make_proxy(in, linear, angular);
  int facets = 0, proxy_flat = 0;
  for (std::size_t k = 0; k < px.input.faces.size(); ++k) {
    if (px.face_brep[k] != cone) continue;
    const auto& n = px.input.faces[k].nodes;
    ASSERT_EQ(n.size(), 3u);
    ++facets;
    proxy_flat += flat(px.input.nodes, n[0], n[1], n[2]);
  }
  EXPECT_EQ(proxy_flat, 0);
  EXPECT_EQ(facets, raw_tris) << "flips keep the count";
}

}  // namespace
}  // namespace bisect
