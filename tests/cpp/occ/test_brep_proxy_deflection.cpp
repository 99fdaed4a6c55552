// The proxy's linear deflection where it, not the angle, governs a curved face
// (pipeline::angle_keeping_deflection). BRepMesh keeps to the angle on a cylinder, whatever the
// linear deflection; on a torus made of B-splines a deflection of a twentieth of the diagonal
// makes a proxy that stands far inside the face (a helical spring's wire was refused so).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <BRepPrimAPI_MakeCylinder.hxx>

#include "occ_checks.hpp"
#include "occ_shapes.hpp"
#include "pipeline/brep_proxy.hpp"

namespace bisect {
namespace {

// the volume the proxy's faces enclose (each face a fan from its first node, all of them turned
// the same way, as the triangles of the tessellation are; the torus has no planar face)
double proxy_volume(const pipeline::BrepProxy& px) {
  double v = 0;
  for (const PolyFace& f : px.input.faces)
    for (std::size_t i = 1; i + 1 < f.nodes.size(); ++i)
      v += px.input.nodes[f.nodes[0]].dot(px.input.nodes[f.nodes[i]].cross(px.input.nodes[f.nodes[i + 1]]));
  return std::abs(v) / 6;
}

constexpr double kAngle = M_PI / 3;

TEST(BrepProxyDeflection, ACylinderKeepsTheAngleAtAnyLinearDeflection) {
  const BrepInput in = test::input_of(BRepPrimAPI_MakeCylinder(3, 90).Shape(), "rod");
  const double linear = 0.05 * (in.bbox_max - in.bbox_min).norm();  // 4.6, over the rod's radius
  const pipeline::BrepProxy px = pipeline::make_proxy(in, linear, kAngle);
  EXPECT_EQ(pipeline::angle_keeping_deflection(in, px), linear);
}

TEST(BrepProxyDeflection, ABSplineTorusIsMadeAgainAtTheAnglesChordHeight) {
  const BrepInput in = test::input_of(test::make_nurbs_torus(), "B-spline torus");
  const double linear = 0.05 * (in.bbox_max - in.bbox_min).norm();
  const pipeline::BrepProxy coarse = pipeline::make_proxy(in, linear, kAngle);
  const double keeping = pipeline::angle_keeping_deflection(in, coarse);
  // the chord height of 60 degrees on radius 3
  EXPECT_NEAR(keeping, 3 * (1 - std::cos(kAngle / 2)), 1e-3 * 3);
  const pipeline::BrepProxy kept = pipeline::make_proxy(in, keeping, kAngle);
  EXPECT_EQ(pipeline::angle_keeping_deflection(in, kept), keeping);
  // 2 pi^2 R r^2; an inscribed hexagon round the tube holds (3 sqrt 3 / 2) / pi = 0.827 of it
  const double torus = 2 * M_PI * M_PI * 15 * 9, before = proxy_volume(coarse) / torus, after = proxy_volume(kept) / torus;
  std::printf("proxy volume / torus: %.4f at %.3g, %.4f at %.3g\n", before, linear, after, keeping);
  EXPECT_GE(after, 0.82) << before;
  EXPECT_LE(after, 1.0 + 1e-9);
  EXPECT_LT(before, after - 0.05);
}

}  // namespace
}  // namespace bisect
