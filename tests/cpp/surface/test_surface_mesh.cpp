// Surface meshing of thesis 5.3-5.5 on analytic surfaces: parametric Delaunay, surface Delaunay,
// surface Laplace smoothing and angle-first swapping, and the shape of Table 5.3.1.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "geom/predicates.hpp"
#include "surface/analytic_surfaces.hpp"
#include "surface/surface_mesh.hpp"

namespace bisect::surface {
namespace {

// Every triangle counter-clockwise in parameter space, every interior edge shared by two, the
// triangles covering the parameter box (area).
void expect_valid(const SurfaceMesh& m, const ParametricSurface& s) {
  double area = 0;
  std::map<std::pair<Index, Index>, int> edges;
  for (const auto& t : m.tris) {
    EXPECT_GT(geom::orient2d(m.uv[t[0]], m.uv[t[1]], m.uv[t[2]]), 0);
    const Vec2 a = m.uv[t[1]] - m.uv[t[0]], b = m.uv[t[2]] - m.uv[t[0]];
    area += 0.5 * (a.x() * b.y() - a.y() * b.x());
    for (int k = 0; k < 3; ++k) ++edges[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  }
  for (const auto& [e, n] : edges) EXPECT_LE(n, 2);
  const Vec2 box = s.uv_max() - s.uv_min();
  EXPECT_NEAR(area, box.x() * box.y(), 1e-12);
  for (std::size_t i = 0; i < m.uv.size(); ++i) EXPECT_LT((m.xyz[i] - s.point(m.uv[i])).norm(), 1e-12);
}

TEST(SurfaceMesh, ParametricDelaunayHasEmptyCircles) {
  const PlaneSurface plane(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY());
  SurfaceMesh m = grid_nodes(plane, 1);  // the four corners fix the box
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.01, 0.99);
  for (int i = 0; i < 300; ++i) {
    const Vec2 p(u(rng), u(rng));
    m.uv.push_back(p), m.xyz.push_back(plane.point(p)), m.fixed.push_back(0);
  }
  delaunay_in_parameters(m);
  expect_valid(m, plane);
  EXPECT_EQ(m.tris.size(), 2 * m.uv.size() - 2 - 4);  // 2n - 2 - hull points
  for (const auto& t : m.tris)
    for (std::size_t p = 0; p < m.uv.size(); ++p)
      EXPECT_LE(geom::incircle(m.uv[t[0]], m.uv[t[1]], m.uv[t[2]], m.uv[p]), 0);
}

TEST(SurfaceMesh, OnAPlaneSurfaceDelaunayIsPlanarDelaunay) {
  const PlaneSurface plane(Vec3(1, 2, 3), Vec3(2, 0, 0), Vec3(0, 1, 1));
  SurfaceMesh m = grid_nodes(plane, 6);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> jitter(-0.03, 0.03);
  for (std::size_t i = 0; i < m.uv.size(); ++i)
    if (!m.fixed[i]) m.uv[i] += Vec2(jitter(rng), jitter(rng)), m.xyz[i] = plane.point(m.uv[i]);
  delaunay_in_parameters(m);
  // a plane's parametrisation here is affine but not similar (x stretched by 2, tilted): the
  // surface criterion re-triangulates, and the result is Delaunay in 3D
  surface_delaunay_swaps(m);
  expect_valid(m, plane);
  const auto q = surface_quality(m, plane);
  EXPECT_LT(q.max_edge_error, 1e-12);  // flat: no surface error
  EXPECT_EQ(surface_delaunay_swaps(m), 0u);  // stable
}

TEST(SurfaceMesh, CylinderAndSphereMeshesStayOnTheSurface) {
  const CylinderSurface cyl(2.0, M_PI, 3.0);
  const SpherePatch sph(1.5, M_PI / 2, M_PI / 4);
  for (const ParametricSurface* s : {static_cast<const ParametricSurface*>(&cyl), static_cast<const ParametricSurface*>(&sph)}) {
    SurfaceMesh m = grid_nodes(*s, 12);
    delaunay_in_parameters(m);
    surface_delaunay_swaps(m);
    surface_laplace_smooth(m, *s, 5);
    surface_angle_swaps(m, *s);
    expect_valid(m, *s);
    // consistent orientation: every triangle's normal along the surface normal
    for (const auto& t : m.tris) {
      const Vec3 n = (m.xyz[t[1]] - m.xyz[t[0]]).cross(m.xyz[t[2]] - m.xyz[t[0]]);
      EXPECT_GT(n.dot(s->normal((m.uv[t[0]] + m.uv[t[1]] + m.uv[t[2]]) / 3)), 0);
    }
  }
}

TEST(SurfaceMesh, SmoothingNeverInvertsAndDoesNotLowerTheMinimumAngle) {
  const BicubicPatch patch = BicubicPatch::table_531_patch();
  SurfaceMesh m = grid_nodes(patch, 10);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(-0.035, 0.035);
  for (std::size_t i = 0; i < m.uv.size(); ++i)
    if (!m.fixed[i]) m.uv[i] += Vec2(jitter(rng), jitter(rng)), m.xyz[i] = patch.point(m.uv[i]);
  delaunay_in_parameters(m);
  const double before = surface_quality(m, patch).min_angle;
  EXPECT_GT(surface_laplace_smooth(m, patch, 5), 0u);
  expect_valid(m, patch);
  EXPECT_GE(surface_quality(m, patch).min_angle, before - 1e-12);
}

TEST(SurfaceMesh, AngleSwapsTerminateAndImprove) {
  const BicubicPatch patch = BicubicPatch::table_531_patch();
  SurfaceMesh m = grid_nodes(patch, 14);
  delaunay_in_parameters(m);
  const double before = surface_quality(m, patch).min_angle;
  surface_angle_swaps(m, patch);
  expect_valid(m, patch);
  EXPECT_GE(surface_quality(m, patch).min_angle, before);
  EXPECT_EQ(surface_angle_swaps(m, patch), 0u);  // a second run finds nothing: no cycling
}

// Table 5.3.1's shape: for 32 to 1,682 triangles on a bicubic patch, surface Delaunay's smallest
// angle is at least parametric Delaunay's, and its mean mid-edge surface error is no larger.
TEST(SurfaceMesh, Table531Shape) {
  const BicubicPatch patch = BicubicPatch::table_531_patch();
  for (int n : {4, 5, 7, 9, 10, 12, 14, 17, 20, 23, 26, 29}) {
    SurfaceMesh m = grid_nodes(patch, n);
    delaunay_in_parameters(m);
    ASSERT_EQ(m.tris.size(), static_cast<std::size_t>(2 * n * n));
    const SurfaceMeshQuality param = surface_quality(m, patch);
    surface_delaunay_swaps(m);
    expect_valid(m, patch);
    const SurfaceMeshQuality surf = surface_quality(m, patch);
    EXPECT_GE(surf.min_angle, param.min_angle - 1e-12) << 2 * n * n << " triangles";
    EXPECT_LE(surf.mean_edge_error, param.mean_edge_error * (1 + 1e-9)) << 2 * n * n << " triangles";
  }
}

}  // namespace
}  // namespace bisect::surface
