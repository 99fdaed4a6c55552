// A surface seen through a plane: the chart q -> the point of the surface whose projection onto
// the plane is q. For a piece of a surface that its own parameters draw badly — next to a pole,
// where a whole segment of (u, v) is one point and straight segments of (u, v) bend round it —
// but that is a graph over a plane (its normals within some tens of degrees of the plane's), the
// plane is a better chart: the region mesher then works in it, isotropic there up to the
// surface's tilt, which its metric accounts for.
#pragma once
#include "bisect/parametric_surface.hpp"

namespace bisect::surface {

class ProjectedChart : public ParametricSurface {
 public:
  // origin, e1, e2: the plane (e1, e2 orthonormal); the surface point for a chart point is found
  // by Newton from the parameters `seed` of a surface point over the piece.
  ProjectedChart(const ParametricSurface& s, const Vec3& origin, const Vec3& e1, const Vec3& e2, const Vec2& seed);

  Vec2 chart_of(const Vec3& x) const { return {(x - o_).dot(e1_), (x - o_).dot(e2_)}; }
  // The surface's parameters at chart point q (Newton on the two in-plane equations, from the
  // nearest of the guesses it has seen); throws MeshingError when the surface folds over the
  // plane there.
  Vec2 surface_uv(const Vec2& q) const;

  Vec3 point(const Vec2& q) const override { return s_.point(surface_uv(q)); }
  void derivatives(const Vec2& q, Vec3* dq1, Vec3* dq2) const override;
  Vec2 uv_min() const override { return lo_; }
  Vec2 uv_max() const override { return hi_; }
  // Seeds Newton near these parameters (a boundary node's) for chart points near their own.
  void add_seed(const Vec2& uv);

 private:
  const ParametricSurface& s_;
  Vec3 o_, e1_, e2_;
  Vec2 lo_, hi_;
  std::vector<Vec2> seeds_uv_, seeds_q_;
};

}  // namespace bisect::surface
