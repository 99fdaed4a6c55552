// Analytic surfaces for tests and benchmarks: plane, cylinder, sphere patch and a bicubic Bezier
// patch, each with exact first derivatives.
#pragma once
#include <array>

#include "bisect/parametric_surface.hpp"

namespace bisect::surface {

using bisect::ParametricSurface;

// origin + u * a + v * b
class PlaneSurface : public ParametricSurface {
 public:
  PlaneSurface(const Vec3& origin, const Vec3& a, const Vec3& b) : o_(origin), a_(a), b_(b) {}
  Vec3 point(const Vec2& uv) const override { return o_ + uv.x() * a_ + uv.y() * b_; }
  void derivatives(const Vec2&, Vec3* du, Vec3* dv) const override { *du = a_, *dv = b_; }

 private:
  Vec3 o_, a_, b_;
};

// Radius r about the z axis; u in [0, 1] is the angle over `sweep` radians, v in [0, 1] the height
// over `height`.
class CylinderSurface : public ParametricSurface {
 public:
  CylinderSurface(double r, double sweep, double height) : r_(r), sweep_(sweep), h_(height) {}
  Vec3 point(const Vec2& uv) const override;
  void derivatives(const Vec2& uv, Vec3* du, Vec3* dv) const override;

 private:
  double r_, sweep_, h_;
};

// Radius r; u in [0, 1] is longitude over `lon` radians, v in [0, 1] latitude from -lat to +lat.
class SpherePatch : public ParametricSurface {
 public:
  SpherePatch(double r, double lon, double lat) : r_(r), lon_(lon), lat_(lat) {}
  Vec3 point(const Vec2& uv) const override;
  void derivatives(const Vec2& uv, Vec3* du, Vec3* dv) const override;

 private:
  double r_, lon_, lat_;
};

// A bicubic Bezier patch: sum B_i(u) B_j(v) P[i][j].
class BicubicPatch : public ParametricSurface {
 public:
  explicit BicubicPatch(const std::array<std::array<Vec3, 4>, 4>& control) : p_(control) {}
  Vec3 point(const Vec2& uv) const override;
  void derivatives(const Vec2& uv, Vec3* du, Vec3* dv) const override;
  // The strongly curved, unevenly parametrised patch the Table 5.3.1 test and bench use (the
  // thesis's own patch is not given in its text).
  static BicubicPatch table_531_patch();

 private:
  std::array<std::array<Vec3, 4>, 4> p_;
};

}  // namespace bisect::surface
