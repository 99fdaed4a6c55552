// Shapes the OpenCASCADE adapter's tests build with OpenCASCADE's own modelling (BRepPrimAPI,
// booleans, NURBS conversion), with what is known of them in closed form.
#pragma once
#include <TopoDS_Shape.hxx>

#include <cmath>

namespace bisect::test {

// [0,1] x [0,2] x [0,3]: 6 planar faces, 12 edges, 8 vertices; volume 6
TopoDS_Shape make_box();
// radius 1, height 2 on the z axis: a lateral face with a seam edge, two discs; volume 2 pi
TopoDS_Shape make_cylinder();
// radius 100 at z = 0 to the apex at (0, 0, 300), as FreeCAD's Part.makeCone(100, 0, 300) makes
// it: a conical face with a seam and a degenerate edge at the apex, a disc; volume pi * 10^6
TopoDS_Shape make_cone();
// a frustum, radius 10 at z = 0 to radius 3 at z = 30, as FreeCAD's Part.makeCone(10, 3, 30): a
// conical face with a seam, two discs; volume 30 pi (100 + 30 + 9) / 3 = 1390 pi
TopoDS_Shape make_frustum();
// radius 2 at the origin: one face, one seam edge and two degenerate pole edges; volume 32 pi / 3
TopoDS_Shape make_sphere();
// a sphere of radius 10 scaled by 2, 1 and 0.5 along x, y and z (BRepBuilderAPI_GTransform, as
// FreeCAD's transformGeometry): an ellipsoid of semi-axes 20, 10, 5 on one B-spline face with
// degenerate edges at its poles (0, 0, +-5); volume 4000 pi / 3. Its smallest radius of
// curvature is 1.25, at (+-20, 0, 0).
TopoDS_Shape make_ellipsoid();
// the box [0,4] x [0,4] x [0,2] minus a cylinder of radius 1 through it on (2, 2, z): volume 32 - 2 pi
TopoDS_Shape make_box_minus_cylinder();
// the box [0,10] x [0,10] x [0,6] with a blind hole drilled from its top on (5, 5, z): radius
// 1.5 down to z = 2, then a 118 degree point to its apex at z = 2 - 1.5 / tan 59; its closed
// faces split in halves (ShapeUpgrade_ShapeDivideClosed), as STEP files often have them, so the
// point is two half cones meeting at a degenerate apex edge; volume 600 - pi 1.5^2 (4 + point / 3)
TopoDS_Shape make_drilled_block();
// the boxes [0,1]^3 and [1,2] x [0,1] x [0,1] as a CompSolid sharing the face x = 1 (general fuse)
TopoDS_Shape make_two_box_compsolid();
// the box [0,4]^3 with a spherical cavity of radius 1 at its centre: one solid, two shells;
// volume 64 - 4 pi / 3
TopoDS_Shape make_box_with_cavity();
// the box [0,4]^3 and a ball of radius 1.2 at its centre as a CompSolid of two solids sharing the
// sphere (general fuse), as ../shared's sphere-in-box; volumes 64 - 2.304 pi and 2.304 pi
TopoDS_Shape make_sphere_in_box();
// a compound of three solids that share no face: the box [0,2]^3, a cylinder of radius 0.8 and
// height 2 standing on its top face at (1, 1, 2) (touching it, not fused), and the box
// [4,5] x [0,1] x [0,1] apart; volumes 8, 1.28 pi, 1
TopoDS_Shape make_touching_compound();
// make_box_minus_cylinder with every surface and curve converted to B-splines
TopoDS_Shape make_nurbs_part();
// a torus of radii 15 and 3 about the z axis, its surface and curves converted to B-splines
// (BRepMesh tessellates such a face by its linear deflection as much as by its angle): volume
// 2 pi^2 15 3^2
TopoDS_Shape make_nurbs_torus();
// a B-spline profile revolved half a turn about the z axis: surfaces of revolution over a
// B-spline curve (whose adaptors nest a curve adaptor with its own cache)
TopoDS_Shape make_revolved_bspline();

}  // namespace bisect::test
