#include "surface/projected_chart.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "bisect/errors.hpp"

namespace bisect::surface {

ProjectedChart::ProjectedChart(const ParametricSurface& s, const Vec3& origin, const Vec3& e1, const Vec3& e2, const Vec2& seed)
    : s_(s), o_(origin), e1_(e1), e2_(e2) {
  add_seed(seed);
}

void ProjectedChart::add_seed(const Vec2& uv) {
  const Vec2 q = chart_of(s_.point(uv));
  if (seeds_q_.empty()) lo_ = hi_ = q;
  lo_ = lo_.cwiseMin(q), hi_ = hi_.cwiseMax(q);
  seeds_uv_.push_back(uv);
  seeds_q_.push_back(q);
}

Vec2 ProjectedChart::surface_uv(const Vec2& q) const {
  std::size_t best = 0;
  for (std::size_t i = 1; i < seeds_q_.size(); ++i)
    if ((seeds_q_[i] - q).squaredNorm() < (seeds_q_[best] - q).squaredNorm()) best = i;
  Vec2 uv = seeds_uv_[best];
  const Vec2 lo = s_.uv_min(), hi = s_.uv_max();
  const double scale = std::max((hi_ - lo_).norm(), 1e-300);
  for (int it = 0; it < 60; ++it) {
    const Vec3 x = s_.point(uv);
    const Vec2 f = chart_of(x) - q;
    if (f.norm() < 1e-13 * scale) return uv;
    Vec3 du, dv;
    s_.derivatives(uv, &du, &dv);
    Eigen::Matrix2d J;
    J << e1_.dot(du), e1_.dot(dv), e2_.dot(du), e2_.dot(dv);
    if (!(std::abs(J.determinant()) > 1e-300)) break;
    Vec2 step = -J.inverse() * f;
    // a damped step: never further than a tenth of the parameter box at once
    const double longest = 0.1 * std::max((hi - lo).norm(), 1e-300);
    if (step.norm() > longest) step *= longest / step.norm();
    uv += step;
    if (s_.period_u() <= 0) uv.x() = std::clamp(uv.x(), lo.x(), hi.x());
    if (s_.period_v() <= 0) uv.y() = std::clamp(uv.y(), lo.y(), hi.y());
  }
  if ((chart_of(s_.point(uv)) - q).norm() < 1e-9 * scale) return uv;
  throw MeshingError("surface region: the surface does not lie over its projection plane at (" + std::to_string(q.x()) + ", " +
                     std::to_string(q.y()) + ")");
}

void ProjectedChart::derivatives(const Vec2& q, Vec3* dq1, Vec3* dq2) const {
  const Vec2 uv = surface_uv(q);
  Vec3 du, dv;
  s_.derivatives(uv, &du, &dv);
  Eigen::Matrix2d J;
  J << e1_.dot(du), e1_.dot(dv), e2_.dot(du), e2_.dot(dv);
  const Eigen::Matrix2d inv = J.inverse();
  *dq1 = inv(0, 0) * du + inv(1, 0) * dv;
  *dq2 = inv(0, 1) * du + inv(1, 1) * dv;
}

}  // namespace bisect::surface
