#include "evaluators.hpp"

#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec2d.hxx>

namespace bisect::occ {
namespace {

// Trimming changes no parameter: evaluate the basis (and find its B-spline cache) directly.
Handle(Geom_Surface) basis_of(Handle(Geom_Surface) s) {
  for (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s); !t.IsNull();
       t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s))
    s = t->BasisSurface();
  return s;
}

Handle(Geom_Curve) basis_of(Handle(Geom_Curve) c) {
  for (auto t = Handle(Geom_TrimmedCurve)::DownCast(c); !t.IsNull(); t = Handle(Geom_TrimmedCurve)::DownCast(c))
    c = t->BasisCurve();
  return c;
}

Handle(Geom2d_Curve) basis_of(Handle(Geom2d_Curve) c) {
  for (auto t = Handle(Geom2d_TrimmedCurve)::DownCast(c); !t.IsNull(); t = Handle(Geom2d_TrimmedCurve)::DownCast(c))
    c = t->BasisCurve();
  return c;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

SurfaceEvaluator::SurfaceEvaluator(const Handle(Geom_Surface)& surface, const TopLoc_Location& location) {
  const Handle(Geom_Surface) s = basis_of(surface);
  info_ = new GeomAdaptor_Surface(s);
  if (const auto bs = Handle(Geom_BSplineSurface)::DownCast(s); !bs.IsNull()) {
    cached_ = std::make_unique<AdaptorPool<Adaptor3d_Surface>>(new GeomAdaptor_Surface(s));
    snap_u_ = KnotSnap(bs->UKnotSequence(), bs->UDegree(), bs->IsUPeriodic());
    snap_v_ = KnotSnap(bs->VKnotSequence(), bs->VDegree(), bs->IsVPeriodic());
  } else if (!Handle(Geom_BezierSurface)::DownCast(s).IsNull()) {
    cached_ = std::make_unique<AdaptorPool<Adaptor3d_Surface>>(new GeomAdaptor_Surface(s));  // one span
  } else {
    direct_ = s;
  }
  moved_ = !location.IsIdentity();
  trsf_ = location.Transformation();
}

void SurfaceEvaluator::d0(double u, double v, gp_Pnt& p) const {
  if (cached_)
    cached_->acquire()->D0(snap_u_(u), snap_v_(v), p);
  else
    direct_->D0(u, v, p);
  place(p);
}

void SurfaceEvaluator::d1(double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) const {
  if (cached_)
    cached_->acquire()->D1(snap_u_(u), snap_v_(v), p, du, dv);
  else
    direct_->D1(u, v, p, du, dv);
  place(p), place(du), place(dv);
}

void SurfaceEvaluator::d2(double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv, gp_Vec& duu, gp_Vec& dvv,
                          gp_Vec& duv) const {
  if (cached_)
    cached_->acquire()->D2(snap_u_(u), snap_v_(v), p, du, dv, duu, dvv, duv);
  else
    direct_->D2(u, v, p, du, dv, duu, dvv, duv);
  place(p), place(du), place(dv), place(duu), place(dvv), place(duv);
}

// ---------------------------------------------------------------------------------------------

Curve2dEvaluator::Curve2dEvaluator(const Handle(Geom2d_Curve)& curve) {
  const Handle(Geom2d_Curve) c = basis_of(curve);
  if (const auto bs = Handle(Geom2d_BSplineCurve)::DownCast(c); !bs.IsNull()) {
    cached_ = std::make_unique<AdaptorPool<Adaptor2d_Curve2d>>(new Geom2dAdaptor_Curve(c));
    snap_ = KnotSnap(bs->KnotSequence(), bs->Degree(), bs->IsPeriodic());
  } else if (!Handle(Geom2d_BezierCurve)::DownCast(c).IsNull()) {
    cached_ = std::make_unique<AdaptorPool<Adaptor2d_Curve2d>>(new Geom2dAdaptor_Curve(c));
  } else {
    direct_ = c;
  }
}

void Curve2dEvaluator::d0(double t, gp_Pnt2d& p) const {
  if (cached_)
    cached_->acquire()->D0(snap_(t), p);
  else
    direct_->D0(t, p);
}

void Curve2dEvaluator::d1(double t, gp_Pnt2d& p, gp_Vec2d& d) const {
  if (cached_)
    cached_->acquire()->D1(snap_(t), p, d);
  else
    direct_->D1(t, p, d);
}

void Curve2dEvaluator::d2(double t, gp_Pnt2d& p, gp_Vec2d& d, gp_Vec2d& dd) const {
  if (cached_)
    cached_->acquire()->D2(snap_(t), p, d, dd);
  else
    direct_->D2(t, p, d, dd);
}

// ---------------------------------------------------------------------------------------------

CurveEvaluator::CurveEvaluator(const Handle(Geom_Curve)& curve, const TopLoc_Location& location) {
  const Handle(Geom_Curve) c = basis_of(curve);
  if (const auto bs = Handle(Geom_BSplineCurve)::DownCast(c); !bs.IsNull()) {
    cached_ = std::make_unique<AdaptorPool<Adaptor3d_Curve>>(new GeomAdaptor_Curve(c));
    snap_ = KnotSnap(bs->KnotSequence(), bs->Degree(), bs->IsPeriodic());
  } else if (!Handle(Geom_BezierCurve)::DownCast(c).IsNull()) {
    cached_ = std::make_unique<AdaptorPool<Adaptor3d_Curve>>(new GeomAdaptor_Curve(c));
  } else {
    direct_ = c;
  }
  moved_ = !location.IsIdentity();
  trsf_ = location.Transformation();
}

CurveEvaluator::CurveEvaluator(const Handle(Geom2d_Curve)& pcurve, const Handle(Geom_Surface)& surface,
                               const TopLoc_Location& location)
    : on_pcurve_(std::make_unique<Curve2dEvaluator>(pcurve)),
      on_surface_(std::make_unique<SurfaceEvaluator>(surface, location)) {}

void CurveEvaluator::d0(double t, gp_Pnt& p) const {
  if (on_surface_) {
    gp_Pnt2d q;
    on_pcurve_->d0(t, q);
    on_surface_->d0(q.X(), q.Y(), p);
    return;
  }
  if (cached_)
    cached_->acquire()->D0(snap_(t), p);
  else
    direct_->D0(t, p);
  place(p);
}

void CurveEvaluator::d1(double t, gp_Pnt& p, gp_Vec& d) const {
  if (on_surface_) {
    gp_Pnt2d q;
    gp_Vec2d dq;
    gp_Vec su, sv;
    on_pcurve_->d1(t, q, dq);
    on_surface_->d1(q.X(), q.Y(), p, su, sv);
    d = dq.X() * su + dq.Y() * sv;
    return;
  }
  if (cached_)
    cached_->acquire()->D1(snap_(t), p, d);
  else
    direct_->D1(t, p, d);
  place(p), place(d);
}

void CurveEvaluator::d2(double t, gp_Pnt& p, gp_Vec& d, gp_Vec& dd) const {
  if (on_surface_) {
    // chain rule: x(t) = S(u(t), v(t))
    gp_Pnt2d q;
    gp_Vec2d dq, ddq;
    gp_Vec su, sv, suu, svv, suv;
    on_pcurve_->d2(t, q, dq, ddq);
    on_surface_->d2(q.X(), q.Y(), p, su, sv, suu, svv, suv);
    const double a = dq.X(), b = dq.Y();
    d = a * su + b * sv;
    dd = (a * a) * suu + (2 * a * b) * suv + (b * b) * svv + ddq.X() * su + ddq.Y() * sv;
    return;
  }
  if (cached_)
    cached_->acquire()->D2(snap_(t), p, d, dd);
  else
    direct_->D2(t, p, d, dd);
  place(p), place(d), place(dd);
}

}  // namespace bisect::occ
