// A B-rep face's surface, an edge's 3D curve and an edge use's pcurve as the core's
// ParametricSurface / ParametricCurve / ParameterCurve, evaluated exactly by OpenCASCADE
// (D0, D1, D2), in the shape's placement, safe to call from several threads at once and
// independent of what ran before (evaluators.hpp).
#pragma once
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include "bisect/parametric_surface.hpp"
#include "evaluators.hpp"

namespace bisect::occ {

class OccSurface : public ParametricSurface {
 public:
  // The surface of face `face` (FreeCAD's Face<face+1>; a forward-oriented copy, with its
  // location) over the face's (u, v) bounds.
  OccSurface(const TopoDS_Face& face, Index index);
  Vec3 point(const Vec2& uv) const override;
  void derivatives(const Vec2& uv, Vec3* du, Vec3* dv) const override;
  void second_derivatives(const Vec2& uv, Vec3* duu, Vec3* duv, Vec3* dvv) const override;
  Vec2 uv_min() const override { return lo_; }
  Vec2 uv_max() const override { return hi_; }
  double period_u() const override { return period_u_; }
  double period_v() const override { return period_v_; }
  // Newton on the squared distance with the exact second derivatives; the base class's search
  // where Newton does not converge.
  Vec2 closest_point(const Vec3& p, const Vec2& guess) const override;
  bool is_plane() const { return plane_; }

 private:
  [[noreturn]] void fail(const Vec2& uv, const char* what) const;
  SurfaceEvaluator eval_;
  Index index_;
  Vec2 lo_, hi_;
  double period_u_ = 0, period_v_ = 0;
  bool plane_ = false;
};

class OccCurve : public ParametricCurve {
 public:
  // The 3D curve of edge `edge` (with its location) over the edge's range; an edge without one
  // is evaluated on its first pcurve.
  OccCurve(const TopoDS_Edge& edge, Index index);
  Vec3 point(double t) const override;
  Vec3 derivative(double t) const override;
  Vec3 second_derivative(double t) const override;
  double t_min() const override { return t0_; }
  double t_max() const override { return t1_; }
  double closest_parameter(const Vec3& p, double guess) const override;

 private:
  [[noreturn]] void fail(double t, const char* what) const;
  double t0_ = 0, t1_ = 0;  // before eval_, which sets them
  CurveEvaluator eval_;
  Index index_;
};

class OccPcurve : public ParameterCurve {
 public:
  // The pcurve of the oriented `edge` on the forward-oriented `face` (for a seam edge the
  // orientation picks the side); throws InputError when the edge has none there.
  OccPcurve(const TopoDS_Edge& edge, const TopoDS_Face& face, Index edge_index, Index face_index);
  Vec2 uv(double t) const override;

 private:
  Curve2dEvaluator eval_;
  Index edge_, face_;
};

}  // namespace bisect::occ
