#include "bisect/parametric_surface.hpp"

#include <algorithm>
#include <cmath>

namespace bisect {
namespace {

// A central-difference step for parameter t in [lo, hi]: small against the range, and kept
// inside it (a one-sided difference would be needed only at the very ends, where a half step
// inside is good enough for curvature estimates).
double fd_step(double lo, double hi) { return std::max(hi - lo, 1e-12) * 1e-5; }

}  // namespace

Vec3 ParametricSurface::normal(const Vec2& uv) const {
  Vec3 du, dv;
  derivatives(uv, &du, &dv);
  return du.cross(dv).normalized();
}

void ParametricSurface::second_derivatives(const Vec2& uv, Vec3* duu, Vec3* duv, Vec3* dvv) const {
  const Vec2 lo = uv_min(), hi = uv_max();
  const double hu = fd_step(lo.x(), hi.x()), hv = fd_step(lo.y(), hi.y());
  Vec3 a, b, c, d;
  derivatives(uv + Vec2(hu, 0), &a, &b);
  derivatives(uv - Vec2(hu, 0), &c, &d);
  *duu = (a - c) / (2 * hu);
  const Vec3 dvu = (b - d) / (2 * hu);
  derivatives(uv + Vec2(0, hv), &a, &b);
  derivatives(uv - Vec2(0, hv), &c, &d);
  *dvv = (b - d) / (2 * hv);
  *duv = 0.5 * (dvu + (a - c) / (2 * hv));
}

double ParametricSurface::max_curvature(const Vec2& uv0) const {
  Vec3 xu, xv, xuu, xuv, xvv;
  // At a degenerate point of the parameters (a pole of a sphere made as a B-spline: du vanishes
  // there to round-off, 5e-16 against |dv| = 17) the fundamental forms' determinant is round-off
  // too, and the curvature came out 10^15: the size field then asked for its floor round every
  // pole (a scaled sphere, an ellipsoid of 20 x 10 x 5 semi-axes, at 14,195 tetrahedra for 300
  // asked). The curvature is continuous there and its limit is reached a millionth of the
  // parameter range off the pole, so such a point is measured there, towards the box's middle.
  Vec2 uv = uv0;
  const Vec2 towards = 0.5 * (uv_min() + uv_max()) - uv0;
  double nn = 0;
  for (int step = 0;; ++step) {
    derivatives(uv, &xu, &xv);
    nn = xu.cross(xv).norm();
    if (nn > 1e-9 * (xu.squaredNorm() + xv.squaredNorm())) break;
    if (step == 3 || !(towards.norm() > 0)) return 0;
    uv = uv0 + std::pow(10.0, step - 6) * towards;
  }
  second_derivatives(uv, &xuu, &xuv, &xvv);
  const Vec3 nu = xu.cross(xv) / nn;
  // first (E F G) and second (L M N) fundamental forms; the principal curvatures are the
  // eigenvalues of the shape operator I^-1 II
  const double E = xu.dot(xu), F = xu.dot(xv), G = xv.dot(xv);
  const double L = xuu.dot(nu), M = xuv.dot(nu), N = xvv.dot(nu);
  const double det = E * G - F * F;
  if (!(det > 0)) return 0;
  const double H = (E * N - 2 * F * M + G * L) / (2 * det);  // mean curvature
  const double K = (L * N - M * M) / det;                    // Gaussian curvature
  const double disc = std::sqrt(std::max(0.0, H * H - K));
  return std::max(std::abs(H + disc), std::abs(H - disc));
}

Vec2 ParametricSurface::closest_point(const Vec3& p, const Vec2& guess) const {
  const Vec2 lo = uv_min(), hi = uv_max();
  const bool pu = period_u() > 0, pv = period_v() > 0;
  auto clamp = [&](Vec2 q) {
    if (!pu) q.x() = std::clamp(q.x(), lo.x(), hi.x());
    if (!pv) q.y() = std::clamp(q.y(), lo.y(), hi.y());
    return q;
  };
  Vec2 uv = clamp(guess);
  const double span = (hi - lo).norm();
  for (int it = 0; it < 30; ++it) {
    // Gauss-Newton on |x(u, v) - p|^2: (J^T J) d = -J^T r
    Vec3 du, dv;
    derivatives(uv, &du, &dv);
    const Vec3 r = point(uv) - p;
    Eigen::Matrix2d jtj;
    jtj << du.dot(du), du.dot(dv), du.dot(dv), dv.dot(dv);
    const Vec2 g(du.dot(r), dv.dot(r));
    if (std::abs(jtj.determinant()) < 1e-300) break;
    Vec2 step = -jtj.inverse() * g;
    // no step longer than a quarter of the box: Newton far from the answer overshoots
    const double longest = 0.25 * span;
    if (step.norm() > longest) step *= longest / step.norm();
    const Vec2 next = clamp(uv + step);
    if ((next - uv).norm() < 1e-15 * span) {
      uv = next;
      break;
    }
    uv = next;
  }
  // a stalled Newton near a fold: compare with the best point of a coarse grid around the guess
  double best = (point(uv) - p).squaredNorm();
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) {
      const Vec2 q = clamp(guess + Vec2(i, j).cwiseProduct(hi - lo) / 64.0);
      const double d = (point(q) - p).squaredNorm();
      if (d < best * (1 - 1e-9)) best = d, uv = q;
    }
  return uv;
}

Vec3 ParametricCurve::second_derivative(double t) const {
  const double h = fd_step(t_min(), t_max());
  return (derivative(t + h) - derivative(t - h)) / (2 * h);
}

double ParametricCurve::curvature(double t) const {
  const Vec3 d1 = derivative(t), d2 = second_derivative(t);
  const double s = d1.norm();
  if (!(s > 0)) return 0;
  return d1.cross(d2).norm() / (s * s * s);
}

double ParametricCurve::closest_parameter(const Vec3& p, double guess) const {
  const double lo = t_min(), hi = t_max();
  double t = std::clamp(guess, lo, hi);
  for (int it = 0; it < 30; ++it) {
    // Newton on f(t) = x'(t) . (x(t) - p) = 0
    const Vec3 r = point(t) - p, d1 = derivative(t), d2 = second_derivative(t);
    const double f = d1.dot(r), df = d1.dot(d1) + d2.dot(r);
    if (!(std::abs(df) > 1e-300)) break;
    double step = -f / df;
    const double longest = 0.25 * (hi - lo);
    step = std::clamp(step, -longest, longest);
    const double next = std::clamp(t + step, lo, hi);
    if (std::abs(next - t) < 1e-15 * (hi - lo)) {
      t = next;
      break;
    }
    t = next;
  }
  // compare with a coarse sampling around the guess (a Newton that stalled at a fold)
  double best = (point(t) - p).squaredNorm();
  for (int i = -8; i <= 8; ++i) {
    const double q = std::clamp(guess + i * (hi - lo) / 64.0, lo, hi);
    const double d = (point(q) - p).squaredNorm();
    if (d < best * (1 - 1e-9)) best = d, t = q;
  }
  return t;
}

}  // namespace bisect
