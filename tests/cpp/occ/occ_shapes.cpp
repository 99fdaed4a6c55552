#include "occ_shapes.hpp"

#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_GTransform.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Builder.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <ShapeUpgrade_ShapeDivideClosed.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_CompSolid.hxx>
#include <gp_Ax2.hxx>
#include <gp_GTrsf.hxx>

#include <cmath>
#include <stdexcept>
#include <string>

namespace bisect::test {

TopoDS_Shape make_box() { return BRepPrimAPI_MakeBox(1, 2, 3).Shape(); }

TopoDS_Shape make_touching_compound() {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  b.Add(c, BRepPrimAPI_MakeBox(2, 2, 2).Shape());
  b.Add(c, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(1, 1, 2), gp_Dir(0, 0, 1)), 0.8, 2).Shape());
  b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(4, 0, 0), 1, 1, 1).Shape());
  return c;
}

TopoDS_Shape make_cone() { return BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 100, 0, 300, 2 * M_PI).Shape(); }

TopoDS_Shape make_frustum() { return BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 10, 3, 30, 2 * M_PI).Shape(); }

TopoDS_Shape make_cylinder() { return BRepPrimAPI_MakeCylinder(1, 2).Shape(); }

TopoDS_Shape make_sphere() { return BRepPrimAPI_MakeSphere(2).Shape(); }

TopoDS_Shape make_ellipsoid() {
  gp_GTrsf scale;
  scale.SetValue(1, 1, 2.0), scale.SetValue(2, 2, 1.0), scale.SetValue(3, 3, 0.5);
  BRepBuilderAPI_GTransform ellipsoid(BRepPrimAPI_MakeSphere(10).Shape(), scale, true);
  if (!ellipsoid.IsDone()) throw std::runtime_error("the scaled sphere failed");
  return ellipsoid.Shape();
}

TopoDS_Shape make_box_minus_cylinder() {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(4, 4, 2).Shape();
  const TopoDS_Shape cyl = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(2, 2, -1), gp_Dir(0, 0, 1)), 1, 4).Shape();
  BRepAlgoAPI_Cut cut(box, cyl);
  if (!cut.IsDone()) throw std::runtime_error("box minus cylinder failed");
  return cut.Shape();
}

TopoDS_Shape make_drilled_block() {
  const double r = 1.5, point = r / std::tan(59 * M_PI / 180);  // a 118 degree point
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 10, 6).Shape();
  const TopoDS_Shape bore = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(5, 5, 2), gp_Dir(0, 0, 1)), r, 5).Shape();
  const TopoDS_Shape tip = BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(5, 5, 2 - point), gp_Dir(0, 0, 1)), 0, r, point).Shape();
  BRepAlgoAPI_Fuse drill(bore, tip);
  if (!drill.IsDone()) throw std::runtime_error("the drill's fuse failed");
  ShapeUpgrade_UnifySameDomain unify(drill.Shape());
  unify.Build();
  BRepAlgoAPI_Cut cut(box, unify.Shape());
  if (!cut.IsDone()) throw std::runtime_error("the drilled block's cut failed");
  ShapeUpgrade_ShapeDivideClosed halves(cut.Shape());
  halves.SetNbSplitPoints(1);
  if (!halves.Perform()) throw std::runtime_error("the drilled block's closed faces were not split");
  return halves.Result();
}

namespace {

// The general fuse of the shapes (touching or overlapping faces become shared ones), its solids as
// one CompSolid.
TopoDS_Shape compsolid_of(const TopoDS_Shape& a, const TopoDS_Shape& b, const char* what) {
  TopTools_ListOfShape args;
  args.Append(a);
  args.Append(b);
  BRepAlgoAPI_BuilderAlgo fuse;
  fuse.SetArguments(args);
  fuse.Build();
  if (!fuse.IsDone()) throw std::runtime_error(std::string("general fuse of ") + what + " failed");
  TopoDS_CompSolid cs;
  BRep_Builder builder;
  builder.MakeCompSolid(cs);
  for (TopExp_Explorer ex(fuse.Shape(), TopAbs_SOLID); ex.More(); ex.Next()) builder.Add(cs, ex.Current());
  return cs;
}

}  // namespace

TopoDS_Shape make_two_box_compsolid() {
  return compsolid_of(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 1, 1, 1).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(1, 0, 0), 1, 1, 1).Shape(), "two boxes");
}

TopoDS_Shape make_sphere_in_box() {
  return compsolid_of(BRepPrimAPI_MakeBox(4, 4, 4).Shape(), BRepPrimAPI_MakeSphere(gp_Pnt(2, 2, 2), 1.2).Shape(), "a box and a ball");
}

TopoDS_Shape make_box_with_cavity() {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(4, 4, 4).Shape();
  const TopoDS_Shape ball = BRepPrimAPI_MakeSphere(gp_Pnt(2, 2, 2), 1).Shape();
  BRepAlgoAPI_Cut cut(box, ball);
  if (!cut.IsDone()) throw std::runtime_error("box minus ball failed");
  return cut.Shape();
}

TopoDS_Shape make_nurbs_part() {
  BRepBuilderAPI_NurbsConvert convert(make_box_minus_cylinder());
  return convert.Shape();
}

TopoDS_Shape make_nurbs_torus() {
  BRepBuilderAPI_NurbsConvert convert(BRepPrimAPI_MakeTorus(15, 3).Shape());
  return convert.Shape();
}

TopoDS_Shape make_revolved_bspline() {
  TColgp_Array1OfPnt pts(1, 5);
  pts(1) = gp_Pnt(1, 0, 0);
  pts(2) = gp_Pnt(1.4, 0, 0.5);
  pts(3) = gp_Pnt(1.2, 0, 1.0);
  pts(4) = gp_Pnt(1.5, 0, 1.5);
  pts(5) = gp_Pnt(1, 0, 2);
  const Handle(Geom_BSplineCurve) profile = GeomAPI_PointsToBSpline(pts).Curve();
  BRepBuilderAPI_MakeWire wire;
  wire.Add(BRepBuilderAPI_MakeEdge(profile).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(1, 0, 2), gp_Pnt(0.5, 0, 2)).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(0.5, 0, 2), gp_Pnt(0.5, 0, 0)).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(0.5, 0, 0), gp_Pnt(1, 0, 0)).Edge());
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(wire.Wire(), true).Face();
  return BRepPrimAPI_MakeRevol(face, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), M_PI).Shape();
}

}  // namespace bisect::test
