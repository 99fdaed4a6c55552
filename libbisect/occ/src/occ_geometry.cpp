#include "occ_geometry.hpp"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "bisect/brep_input.hpp"
#include "occ_guard.hpp"

namespace bisect::occ {
namespace {

Vec3 vec(const gp_Pnt& p) { return Vec3(p.X(), p.Y(), p.Z()); }
Vec3 vec(const gp_Vec& v) { return Vec3(v.X(), v.Y(), v.Z()); }

SurfaceEvaluator face_evaluator(const TopoDS_Face& face, Index index) {
  return guard([&] { return face_name(index); }, "OpenCASCADE could not read its surface", [&] {
    TopLoc_Location loc;
    const Handle(Geom_Surface)& s = BRep_Tool::Surface(face, loc);
    if (s.IsNull()) throw InputError(face_name(index) + ": the face has no surface (a face made of triangles only?)");
    return SurfaceEvaluator(s, loc);
  });
}

CurveEvaluator edge_evaluator(const TopoDS_Edge& edge, Index index, double* t0, double* t1) {
  return guard([&] { return edge_name(index); }, "OpenCASCADE could not read its curve", [&] {
    TopLoc_Location loc;
    const Handle(Geom_Curve) c = BRep_Tool::Curve(edge, loc, *t0, *t1);
    if (!c.IsNull()) return CurveEvaluator(c, loc);
    // no 3D curve (some IGES files): the edge is its first pcurve on that pcurve's surface
    Handle(Geom2d_Curve) pc;
    Handle(Geom_Surface) s;
    BRep_Tool::CurveOnSurface(edge, pc, s, loc, *t0, *t1);
    if (pc.IsNull() || s.IsNull()) throw InputError(edge_name(index) + ": the edge has no curve");
    return CurveEvaluator(pc, s, loc);
  });
}

Curve2dEvaluator pcurve_evaluator(const TopoDS_Edge& edge, const TopoDS_Face& face, Index e, Index f) {
  auto where = [&] { return edge_name(e) + " in " + face_name(f); };
  return guard(where, "OpenCASCADE could not read its parameter curve", [&] {
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(edge, face, first, last);
    if (c.IsNull()) throw InputError(where() + ": the edge has no parameter curve on the face");
    return Curve2dEvaluator(c);
  });
}

std::string at(double u, double v) {
  std::ostringstream s;
  s.precision(10);
  s << "(u, v) = (" << u << ", " << v << ")";
  return s.str();
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Surface

OccSurface::OccSurface(const TopoDS_Face& face, Index index) : eval_(face_evaluator(face, index)), index_(index) {
  guard([&] { return face_name(index); }, "OpenCASCADE could not take its bounds", [&] {
    const GeomAdaptor_Surface& s = eval_.info();
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    if (s.IsUPeriodic()) period_u_ = s.UPeriod();
    if (s.IsVPeriodic()) period_v_ = s.VPeriod();
    // the pcurves' boxes may overshoot a bounded surface's own range a little: keep inside it
    if (period_u_ == 0) u0 = std::max(u0, s.FirstUParameter()), u1 = std::min(u1, s.LastUParameter());
    if (period_v_ == 0) v0 = std::max(v0, s.FirstVParameter()), v1 = std::min(v1, s.LastVParameter());
    if (!(u0 < u1) || !(v0 < v1)) throw InputError(face_name(index) + ": the face has an empty parameter box");
    lo_ = Vec2(u0, v0), hi_ = Vec2(u1, v1);
    plane_ = s.GetType() == GeomAbs_Plane;
  });
}

void OccSurface::fail(const Vec2& uv, const char* what) const {
  throw MeshingError(face_name(index_) + ": OpenCASCADE could not evaluate the surface's " + what + " at " +
                     at(uv.x(), uv.y()));
}

Vec3 OccSurface::point(const Vec2& uv) const {
  try {
    gp_Pnt p;
    eval_.d0(uv.x(), uv.y(), p);
    return vec(p);
  } catch (const Standard_Failure& e) {
    fail(uv, ("point (" + describe(e) + ")").c_str());
  }
}

void OccSurface::derivatives(const Vec2& uv, Vec3* du, Vec3* dv) const {
  try {
    gp_Pnt p;
    gp_Vec a, b;
    eval_.d1(uv.x(), uv.y(), p, a, b);
    *du = vec(a), *dv = vec(b);
  } catch (const Standard_Failure& e) {
    fail(uv, ("derivatives (" + describe(e) + ")").c_str());
  }
}

void OccSurface::second_derivatives(const Vec2& uv, Vec3* duu, Vec3* duv, Vec3* dvv) const {
  try {
    gp_Pnt p;
    gp_Vec a, b, aa, bb, ab;
    eval_.d2(uv.x(), uv.y(), p, a, b, aa, bb, ab);
    *duu = vec(aa), *duv = vec(ab), *dvv = vec(bb);
  } catch (const Standard_Failure& e) {
    fail(uv, ("second derivatives (" + describe(e) + ")").c_str());
  }
}

Vec2 OccSurface::closest_point(const Vec3& p, const Vec2& guess) const {
  const bool periodic[2] = {period_u_ > 0, period_v_ > 0};
  auto clamp = [&](Vec2 q) {
    for (int i = 0; i < 2; ++i)
      if (!periodic[i]) q[i] = std::clamp(q[i], lo_[i], hi_[i]);
    return q;
  };
  const double span = (hi_ - lo_).norm();
  bool converged = false;
  Vec2 uv = clamp(guess);
  try {
    gp_Pnt x;
    gp_Vec su, sv, suu, svv, suv;
    eval_.d2(uv.x(), uv.y(), x, su, sv, suu, svv, suv);
    Vec3 r = vec(x) - p;
    double f = r.squaredNorm();
    for (int it = 0; it < 40 && !converged; ++it) {
      // Newton on f(u, v) = |x(u, v) - p|^2 / 2 with the exact Hessian; Gauss-Newton where the
      // Hessian is not positive definite (far from the answer, or past a centre of curvature)
      const Vec3 xu = vec(su), xv = vec(sv);
      const Vec2 g(xu.dot(r), xv.dot(r));
      Eigen::Matrix2d h;
      h << xu.dot(xu) + vec(suu).dot(r), xu.dot(xv) + vec(suv).dot(r), xu.dot(xv) + vec(suv).dot(r),
          xv.dot(xv) + vec(svv).dot(r);
      if (!(h(0, 0) > 0 && h.determinant() > 0)) h << xu.dot(xu), xu.dot(xv), xu.dot(xv), xv.dot(xv);
      // a parameter held at its bound by a gradient pushing out of the box stays there
      bool free[2];
      for (int i = 0; i < 2; ++i)
        free[i] = periodic[i] || !((uv[i] <= lo_[i] && g[i] > 0) || (uv[i] >= hi_[i] && g[i] < 0));
      Vec2 step(0, 0);
      if (free[0] && free[1]) {
        if (!(std::abs(h.determinant()) > 1e-300)) break;  // a degenerate point (a pole): the search decides
        step = -h.inverse() * g;
      } else {
        for (int i = 0; i < 2; ++i)
          if (free[i] && h(i, i) > 0) step[i] = -g[i] / h(i, i);
      }
      if (step.norm() > 0.25 * span) step *= 0.25 * span / step.norm();
      if (std::abs(step.x()) <= 1e-13 * (span + std::abs(uv.x())) && std::abs(step.y()) <= 1e-13 * (span + std::abs(uv.y()))) {
        converged = true;  // the Newton step is round-off
        break;
      }
      // halve the step until the distance falls; when no step does, the answer is reached to
      // within round-off (the direction is one of descent)
      bool fell = false;
      for (int k = 0; k < 60 && !fell; ++k, step *= 0.5) {
        const Vec2 next = clamp(uv + step);
        if (next == uv) break;
        eval_.d2(next.x(), next.y(), x, su, sv, suu, svv, suv);
        const Vec3 rn = vec(x) - p;
        const double fn = rn.squaredNorm();
        if (fn < f) uv = next, r = rn, f = fn, fell = true;
      }
      if (!fell) {
        converged = true;
        break;
      }
      if (it + 1 == 40) break;
    }
  } catch (const Standard_Failure&) {
    converged = false;  // the base class's search evaluates again and names the face if it fails
  }
  if (converged) return uv;
  return ParametricSurface::closest_point(p, guess);
}

// ---------------------------------------------------------------------------------------------
// Edge curve

OccCurve::OccCurve(const TopoDS_Edge& edge, Index index) : eval_(edge_evaluator(edge, index, &t0_, &t1_)), index_(index) {
  if (!(t0_ < t1_)) throw InputError(edge_name(index) + ": the edge has an empty parameter range");
}

void OccCurve::fail(double t, const char* what) const {
  std::ostringstream s;
  s.precision(10);
  s << edge_name(index_) << ": OpenCASCADE could not evaluate the curve's " << what << " at t = " << t;
  throw MeshingError(s.str());
}

Vec3 OccCurve::point(double t) const {
  try {
    gp_Pnt p;
    eval_.d0(t, p);
    return vec(p);
  } catch (const Standard_Failure& e) {
    fail(t, ("point (" + describe(e) + ")").c_str());
  }
}

Vec3 OccCurve::derivative(double t) const {
  try {
    gp_Pnt p;
    gp_Vec d;
    eval_.d1(t, p, d);
    return vec(d);
  } catch (const Standard_Failure& e) {
    fail(t, ("derivative (" + describe(e) + ")").c_str());
  }
}

Vec3 OccCurve::second_derivative(double t) const {
  try {
    gp_Pnt p;
    gp_Vec d, dd;
    eval_.d2(t, p, d, dd);
    return vec(dd);
  } catch (const Standard_Failure& e) {
    fail(t, ("second derivative (" + describe(e) + ")").c_str());
  }
}

double OccCurve::closest_parameter(const Vec3& p, double guess) const {
  const double span = t1_ - t0_;
  double t = std::clamp(guess, t0_, t1_);
  bool converged = false;
  try {
    gp_Pnt x;
    gp_Vec d1, d2;
    eval_.d2(t, x, d1, d2);
    Vec3 r = vec(x) - p;
    double f = r.squaredNorm();
    for (int it = 0; it < 30 && !converged; ++it) {
      // Newton on x'(t) . (x(t) - p) = 0; Gauss-Newton where the second-order term would make
      // the curvature negative
      const double g = vec(d1).dot(r);
      double h = vec(d1).squaredNorm() + vec(d2).dot(r);
      if (!(h > 0)) h = vec(d1).squaredNorm();
      if (!(h > 1e-300)) break;
      double step = std::clamp(-g / h, -0.25 * span, 0.25 * span);
      for (int k = 0; k < 40; ++k) {
        const double next = std::clamp(t + step, t0_, t1_);
        const double moved = std::abs(next - t);
        if (moved <= 1e-14 * (span + std::abs(t))) {
          converged = true;
          break;
        }
        eval_.d2(next, x, d1, d2);
        const Vec3 rn = vec(x) - p;
        const double fn = rn.squaredNorm();
        if (fn <= f) {
          t = next, r = rn, f = fn;
          if (moved <= 1e-11 * (span + std::abs(t))) converged = true;
          break;
        }
        step *= 0.5;
      }
    }
  } catch (const Standard_Failure&) {
    converged = false;
  }
  if (converged) return t;
  return ParametricCurve::closest_parameter(p, guess);
}

// ---------------------------------------------------------------------------------------------
// Pcurve

OccPcurve::OccPcurve(const TopoDS_Edge& edge, const TopoDS_Face& face, Index edge_index, Index face_index)
    : eval_(pcurve_evaluator(edge, face, edge_index, face_index)),
      edge_(edge_index),
      face_(face_index) {}

Vec2 OccPcurve::uv(double t) const {
  try {
    gp_Pnt2d q;
    eval_.d0(t, q);
    return Vec2(q.X(), q.Y());
  } catch (const Standard_Failure& e) {
    std::ostringstream s;
    s.precision(10);
    s << edge_name(edge_) << " in " << face_name(face_) << ": OpenCASCADE could not evaluate the parameter curve at t = "
      << t << " (" << describe(e) << ")";
    throw MeshingError(s.str());
  }
}

}  // namespace bisect::occ
