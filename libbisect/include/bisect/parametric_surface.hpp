// Surfaces and curves given by parametrisations (thesis ch. 5): what the surface mesher, the size
// field and the tet10 mid-nodes work against. The B-rep adapter (libbisect/occ) implements them
// with OpenCASCADE; src/surface/analytic_surfaces.hpp implements them in closed form for tests.
#pragma once
#include "bisect/types.hpp"

namespace bisect {

class ParametricSurface {
 public:
  virtual ~ParametricSurface() = default;
  virtual Vec3 point(const Vec2& uv) const = 0;
  // First derivatives d x / d u and d x / d v.
  virtual void derivatives(const Vec2& uv, Vec3* du, Vec3* dv) const = 0;
  // Second derivatives; by default central differences of derivatives() (exact surfaces
  // override it).
  virtual void second_derivatives(const Vec2& uv, Vec3* duu, Vec3* duv, Vec3* dvv) const;
  // The parameter box: the face's bounds for a trimmed B-rep face (the trimming loops lie
  // inside it).
  virtual Vec2 uv_min() const { return Vec2(0, 0); }
  virtual Vec2 uv_max() const { return Vec2(1, 1); }
  // The period in u and in v; 0 when the surface is not periodic in that parameter. A periodic
  // surface's point(uv) is the same for uv and uv + period, and uv may leave the box by periods.
  virtual double period_u() const { return 0; }
  virtual double period_v() const { return 0; }
  // The parameters of the surface point nearest p, by Gauss-Newton on the squared distance
  // from `guess`, kept inside the parameter box (periodic parameters are not clamped: the
  // answer is the one nearest the guess); falls back to a coarse search when Newton stalls.
  virtual Vec2 closest_point(const Vec3& p, const Vec2& guess) const;
  Vec3 normal(const Vec2& uv) const;  // unit, du x dv
  // The largest absolute principal curvature at uv (1 / radius), from the first and second
  // fundamental forms; at a degenerate point of the parameters (a pole) the limit beside it; 0
  // where the surface is flat, or where the parametrisation degenerates with no regular point
  // beside it.
  double max_curvature(const Vec2& uv) const;
};

class ParametricCurve {
 public:
  virtual ~ParametricCurve() = default;
  virtual Vec3 point(double t) const = 0;
  virtual Vec3 derivative(double t) const = 0;
  // By default central differences of derivative().
  virtual Vec3 second_derivative(double t) const;
  virtual double t_min() const = 0;
  virtual double t_max() const = 0;
  // The parameter of the curve point nearest p, by Newton from `guess`, kept in [t_min, t_max].
  virtual double closest_parameter(const Vec3& p, double guess) const;
  double curvature(double t) const;  // |x' x x''| / |x'|^3; 0 where x' vanishes
};

// A curve in a surface's parameter plane (a B-rep edge's pcurve on one of its faces).
class ParameterCurve {
 public:
  virtual ~ParameterCurve() = default;
  virtual Vec2 uv(double t) const = 0;
};

}  // namespace bisect
