// Evaluation of OpenCASCADE surfaces and curves that may run on several threads at once and
// gives the same value whatever was evaluated before (ARCHITECTURE.md: output the same for every
// thread count).
//
// B-spline and Bezier geometry goes through adaptors, whose span caches make repeated nearby
// evaluations 2-4 times faster than Geom_*::D0 (measured on corpus B-spline faces), one adaptor
// per thread (adaptor_pool.hpp) and the parameter snapped off the knots' rounding window
// (knot_snap.hpp). Everything else is evaluated on the Geom_* object itself: elementary surfaces
// and curves in closed form, offset surfaces and surfaces of revolution or extrusion through the
// evaluators Geom_* builds on their basis Geom_* (no cache; GeomAdaptor's would nest one).
#pragma once
#include <Adaptor2d_Curve2d.hxx>
#include <Adaptor3d_Curve.hxx>
#include <Adaptor3d_Surface.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <TopLoc_Location.hxx>
#include <gp_Trsf.hxx>

#include <memory>

#include "adaptor_pool.hpp"
#include "knot_snap.hpp"

namespace bisect::occ {

class SurfaceEvaluator {
 public:
  // `surface` placed by `location` (a face's BRep_Tool::Surface(face, location)).
  SurfaceEvaluator(const Handle(Geom_Surface)& surface, const TopLoc_Location& location);
  void d0(double u, double v, gp_Pnt& p) const;
  void d1(double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) const;
  void d2(double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv, gp_Vec& duu, gp_Vec& dvv, gp_Vec& duv) const;
  // Type, natural bounds and periods (never evaluated).
  const GeomAdaptor_Surface& info() const { return *info_; }

 private:
  void place(gp_Pnt& p) const {
    if (moved_) p.Transform(trsf_);
  }
  void place(gp_Vec& v) const {
    if (moved_) v.Transform(trsf_);
  }
  Handle(Geom_Surface) direct_;
  std::unique_ptr<AdaptorPool<Adaptor3d_Surface>> cached_;
  KnotSnap snap_u_, snap_v_;
  Handle(GeomAdaptor_Surface) info_;
  gp_Trsf trsf_;
  bool moved_ = false;
};

class Curve2dEvaluator {
 public:
  explicit Curve2dEvaluator(const Handle(Geom2d_Curve)& curve);
  void d0(double t, gp_Pnt2d& p) const;
  void d1(double t, gp_Pnt2d& p, gp_Vec2d& d) const;
  void d2(double t, gp_Pnt2d& p, gp_Vec2d& d, gp_Vec2d& dd) const;

 private:
  Handle(Geom2d_Curve) direct_;
  std::unique_ptr<AdaptorPool<Adaptor2d_Curve2d>> cached_;
  KnotSnap snap_;
};

class CurveEvaluator {
 public:
  // A 3D curve placed by `location` (an edge's BRep_Tool::Curve(edge, location, ...)).
  CurveEvaluator(const Handle(Geom_Curve)& curve, const TopLoc_Location& location);
  // An edge with no 3D curve: the point of `surface` at the pcurve's (u, v).
  CurveEvaluator(const Handle(Geom2d_Curve)& pcurve, const Handle(Geom_Surface)& surface, const TopLoc_Location& location);
  void d0(double t, gp_Pnt& p) const;
  void d1(double t, gp_Pnt& p, gp_Vec& d) const;
  void d2(double t, gp_Pnt& p, gp_Vec& d, gp_Vec& dd) const;

 private:
  void place(gp_Pnt& p) const {
    if (moved_) p.Transform(trsf_);
  }
  void place(gp_Vec& v) const {
    if (moved_) v.Transform(trsf_);
  }
  Handle(Geom_Curve) direct_;
  std::unique_ptr<AdaptorPool<Adaptor3d_Curve>> cached_;
  KnotSnap snap_;
  std::unique_ptr<Curve2dEvaluator> on_pcurve_;  // no 3D curve: composed with on_surface_
  std::unique_ptr<SurfaceEvaluator> on_surface_;
  gp_Trsf trsf_;
  bool moved_ = false;
};

}  // namespace bisect::occ
