// A surface given by a parametrisation (u, v) -> x (thesis ch. 5), the interface the surface
// meshers work against: the B-rep adapter implements it with OpenCASCADE, the analytic surfaces
// of analytic_surfaces.hpp implement it for tests.
#pragma once
#include "bisect/types.hpp"

namespace bisect::surface {

class ParametricSurface {
 public:
  virtual ~ParametricSurface() = default;
  virtual Vec3 point(const Vec2& uv) const = 0;
  // First derivatives d x / d u and d x / d v.
  virtual void derivatives(const Vec2& uv, Vec3* du, Vec3* dv) const = 0;
  virtual Vec2 uv_min() const { return Vec2(0, 0); }
  virtual Vec2 uv_max() const { return Vec2(1, 1); }
  // The parameters of the surface point nearest p, by Newton's method on the squared distance
  // from `guess`, kept inside the parameter box; falls back to a coarse search when Newton stalls.
  virtual Vec2 closest_point(const Vec3& p, const Vec2& guess) const;
  Vec3 normal(const Vec2& uv) const;  // unit, du x dv
};

}  // namespace bisect::surface
