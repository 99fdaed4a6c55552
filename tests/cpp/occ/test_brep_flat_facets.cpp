// Proxy facets flat in space (pipeline/brep_proxy.cpp, follow_surface; the retries in
// pipeline/brep_generate.cpp). The flips that take a curved face's facets towards the surface
// may make triangles whose three nodes lie on one line: on a cone they lie on the surface, so
// nothing stopped them. Round a half cone's apex they lie over each other, and the proxy's check
// refuses corpus/Block.brep for it; round a drilled hole's conical point they left a reflex edge
// no plane resolved. A proxy made with mend_flat has none of them, and the route makes one when
// every other has failed in its cuts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bisect/generate.hpp"
#include "bisect/quality.hpp"
#include "bisect/validate.hpp"
#include "occ_checks.hpp"
#include "occ_shapes.hpp"
#include "pipeline/brep_proxy.hpp"

namespace bisect {
namespace {

// the triangles of curved faces whose corners lie on one line (three distinct nodes), counted
// here from the facets themselves
std::size_t flat_triangles(const pipeline::BrepProxy& px) {
  std::size_t n = 0;
  for (std::size_t f = 0; f < px.face_tri.size(); ++f) {
    if (px.face_tri[f] < 0) continue;
    const auto& v = px.input.faces[f].nodes;
    const Vec3 &a = px.input.nodes[v[0]], &b = px.input.nodes[v[1]], &c = px.input.nodes[v[2]];
    const double longest = std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
    n += (b - a).cross(c - a).norm() <= 1e-9 * longest;
  }
  return n;
}

TEST(BrepFlatFacets, AMendedProxyOfADrilledPointHasNone) {
  const BrepInput in = test::input_through_string(test::make_drilled_block(), "drilled block");
  const double linear = 0.05 * (in.bbox_max - in.bbox_min).norm();
  // at the proxy angles of 24 and 48 curvature elements (30 and 15 degrees): measured 4 and 9
  // flat facets as the flips leave them, none mended; at the default 60 degrees none either way
  for (const double degrees : {30.0, 15.0}) {
    const pipeline::BrepProxy as_is = pipeline::make_proxy(in, linear, degrees * M_PI / 180);
    const pipeline::BrepProxy mended = pipeline::make_proxy(in, linear, degrees * M_PI / 180, true);
    EXPECT_GT(flat_triangles(as_is), 0u) << degrees;
    EXPECT_EQ(as_is.flat_facets, flat_triangles(as_is)) << degrees;
    EXPECT_EQ(flat_triangles(mended), 0u) << degrees;
    EXPECT_EQ(mended.flat_facets, 0u) << degrees;
    // the flips keep the faces' triangles: as many, on the same nodes
    EXPECT_EQ(mended.input.faces.size(), as_is.input.faces.size()) << degrees;
    EXPECT_EQ(mended.input.nodes.size(), as_is.input.nodes.size()) << degrees;
  }
  const pipeline::BrepProxy coarse = pipeline::make_proxy(in, linear, M_PI / 3);
  EXPECT_EQ(coarse.flat_facets, 0u);
}

TEST(BrepFlatFacets, ADrilledPointMeshesAtFineCurvatureBounds) {
  // every proxy as the flips leave it failed to cut (exit 3: "no bisection plane resolves the
  // reflex edge from node 13 (5, 5, 1.09871)", the apex); the last round's mended one meshes
  const BrepInput in = test::input_through_string(test::make_drilled_block(), "drilled block");
  const double point = 1.5 / std::tan(59 * M_PI / 180);
  const double volume = 600 - M_PI * 1.5 * 1.5 * (4 + point / 3);
  // at 24 curvature elements (48 too, measured: 46,575 tetrahedra, 10.5 degrees, 7 s; left out
  // for the suite's time)
  GenerateOptions opt;
  opt.sizing.elements = 5000;
  opt.sizing.curvature_elements = 24;
  GenerateStats st;
  const TetMesh m = generate_brep_mesh(in, opt, &st);
  const std::vector<Violation> bad = validate(m);
  ASSERT_TRUE(bad.empty()) << bad.size() << " violations, first: " << to_string(bad.front().kind);
  EXPECT_NEAR(test::corner_volume(m), volume, 0.01 * volume);
  // measured: 24,550 tetrahedra (the curvature's floor), 10.1 degrees
  EXPECT_GE(summarize_quality(element_quality(m)).dihedral_min.min, 8.0);
  // the three proxies as they are, then the mended one
  EXPECT_EQ(st.proxy_attempts, 4) << st.proxy_retry_reason;
}

}  // namespace
}  // namespace bisect
