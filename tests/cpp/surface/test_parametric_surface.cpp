// The defaults every parametric surface and curve gets: curvature from the fundamental forms,
// second derivatives by differences, closest points (clamped, or nearest the guess on a
// periodic parameter).
#include <gtest/gtest.h>

#include <cmath>

#include "bisect/parametric_surface.hpp"
#include "surface/analytic_surfaces.hpp"

namespace bisect {
namespace {

// A full circle of radius r in the z = 0 plane, t the angle.
class Circle : public ParametricCurve {
 public:
  explicit Circle(double r) : r_(r) {}
  Vec3 point(double t) const override { return r_ * Vec3(std::cos(t), std::sin(t), 0); }
  Vec3 derivative(double t) const override { return r_ * Vec3(-std::sin(t), std::cos(t), 0); }
  double t_min() const override { return 0; }
  double t_max() const override { return 2 * M_PI; }

 private:
  double r_;
};

// A cylinder of radius r whose angle u is periodic (2 pi) and whose height v runs over [0, 1].
class PeriodicCylinder : public ParametricSurface {
 public:
  explicit PeriodicCylinder(double r) : r_(r) {}
  Vec3 point(const Vec2& uv) const override { return Vec3(r_ * std::cos(uv.x()), r_ * std::sin(uv.x()), uv.y()); }
  void derivatives(const Vec2& uv, Vec3* du, Vec3* dv) const override {
    *du = Vec3(-r_ * std::sin(uv.x()), r_ * std::cos(uv.x()), 0);
    *dv = Vec3(0, 0, 1);
  }
  Vec2 uv_max() const override { return Vec2(2 * M_PI, 1); }
  double period_u() const override { return 2 * M_PI; }

 private:
  double r_;
};

TEST(ParametricSurface, CurvatureIsOneOverTheRadius) {
  const surface::CylinderSurface cyl(2.0, M_PI, 3.0);
  EXPECT_NEAR(cyl.max_curvature(Vec2(0.3, 0.6)), 0.5, 1e-6);
  const surface::SpherePatch sphere(4.0, 1.0, 0.5);
  EXPECT_NEAR(sphere.max_curvature(Vec2(0.5, 0.5)), 0.25, 1e-6);
  const surface::PlaneSurface plane(Vec3::Zero(), Vec3(1, 2, 0), Vec3(0, 1, 3));
  EXPECT_NEAR(plane.max_curvature(Vec2(0.2, 0.9)), 0.0, 1e-9);
}

// A whole sphere of radius r by longitude u and latitude v in [-pi/2, pi/2]: du vanishes at the
// poles, to cos(pi / 2) = 6e-17 in doubles (a B-spline sphere's does the same).
class PolarSphere : public ParametricSurface {
 public:
  explicit PolarSphere(double r) : r_(r) {}
  Vec3 point(const Vec2& uv) const override {
    return r_ * Vec3(std::cos(uv.y()) * std::cos(uv.x()), std::cos(uv.y()) * std::sin(uv.x()), std::sin(uv.y()));
  }
  void derivatives(const Vec2& uv, Vec3* du, Vec3* dv) const override {
    const double u = uv.x(), v = uv.y();
    *du = r_ * Vec3(-std::cos(v) * std::sin(u), std::cos(v) * std::cos(u), 0);
    *dv = r_ * Vec3(-std::sin(v) * std::cos(u), -std::sin(v) * std::sin(u), std::cos(v));
  }
  Vec2 uv_min() const override { return Vec2(0, -M_PI / 2); }
  Vec2 uv_max() const override { return Vec2(2 * M_PI, M_PI / 2); }
  double period_u() const override { return 2 * M_PI; }

 private:
  double r_;
};

TEST(ParametricSurface, CurvatureAtAPoleIsTheLimitBesideIt) {
  // the value at a degenerate point of the parameters, and beside it. (This analytic sphere's
  // differences straddle the pole evenly and its curvature came out right there before too; the
  // B-spline sphere's, which came out at 10^15, is BrepPoles' test.)
  const PolarSphere sphere(2.0);
  for (const Vec2& pole : {Vec2(0.4, M_PI / 2), Vec2(3.0, -M_PI / 2), Vec2(0, M_PI / 2)})
    EXPECT_NEAR(sphere.max_curvature(pole), 0.5, 1e-6) << pole.transpose();
  EXPECT_NEAR(sphere.max_curvature(Vec2(1.0, 0.3)), 0.5, 1e-6);
}

TEST(ParametricSurface, ClosestPointOnAPeriodicParameterStaysNearTheGuess) {
  const PeriodicCylinder cyl(1.0);
  // a point just past the seam, guessed from the far side of the box: the answer keeps to the
  // guess's side, one period away from the box's own value
  const Vec3 p = 1.5 * Vec3(std::cos(0.05), std::sin(0.05), 0) + Vec3(0, 0, 0.4);
  const Vec2 uv = cyl.closest_point(p, Vec2(2 * M_PI - 0.02, 0.5));
  EXPECT_NEAR(uv.x(), 2 * M_PI + 0.05, 1e-9);
  EXPECT_NEAR(uv.y(), 0.4, 1e-9);
  // a non-periodic parameter is clamped to the box
  const Vec2 high = cyl.closest_point(Vec3(1, 0, 5), Vec2(0.1, 0.9));
  EXPECT_NEAR(high.y(), 1.0, 1e-12);
}

TEST(ParametricCurve, CurvatureAndClosestParameter) {
  const Circle c(2.5);
  EXPECT_NEAR(c.curvature(1.2), 0.4, 1e-6);
  EXPECT_NEAR(c.closest_parameter(Vec3(std::cos(2.0), std::sin(2.0), 0.3) * 7, 1.8), 2.0, 1e-9);
  EXPECT_NEAR(c.closest_parameter(Vec3(1, -1e-3, 0), 0.1), 0.0, 1e-12);  // clamped at t_min
}

}  // namespace
}  // namespace bisect
