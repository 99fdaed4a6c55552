// The adapter's topology: FreeCAD's numbering, edges and their vertices, faces with their wires,
// pcurves and orientation, solids (shared faces, cavities, shells made solids), and the shapes
// it refuses.
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <gp_Pln.hxx>
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include "bisect/occ_checker.hpp"
#include "input_error.hpp"
#include "occ_checks.hpp"
#include "occ_shapes.hpp"

namespace bisect {
namespace {

using test::input_of;

int count(const TopoDS_Shape& s, TopAbs_ShapeEnum type) {
  TopTools_IndexedMapOfShape m;
  TopExp::MapShapes(s, type, m);
  return m.Extent();
}

// The outward normal of face f at the middle of its parameter box.
Vec3 outward_normal(const BrepFace& face) {
  const Vec2 mid = 0.5 * (face.surface->uv_min() + face.surface->uv_max());
  return (face.reversed ? -1.0 : 1.0) * face.surface->normal(mid);
}

TEST(OccTopology, BoxHasFreeCADsCountsAndOutwardFaces) {
  const TopoDS_Shape box = test::make_box();
  const BrepInput in = input_of(box, "box");
  EXPECT_EQ(in.vertices.size(), 8u);
  EXPECT_EQ(in.edges.size(), 12u);
  EXPECT_EQ(in.faces.size(), 6u);
  ASSERT_EQ(in.solids.size(), 1u);
  EXPECT_EQ(in.solids[0].faces.size(), 6u);
  const Vec3 centre(0.5, 1, 1.5);
  int reversed = 0;
  for (const BrepFace& f : in.faces) {
    EXPECT_TRUE(f.planar);
    EXPECT_EQ(f.wires.size(), 1u);
    EXPECT_EQ(f.wires[0].size(), 4u);
    const Vec3 p = f.surface->point(0.5 * (f.surface->uv_min() + f.surface->uv_max()));
    EXPECT_GT(outward_normal(f).dot(p - centre), 0) << "the face's own normal points out of the box";
    reversed += f.reversed;
  }
  EXPECT_GT(reversed, 0) << "OpenCASCADE's box has reversed faces: the flag must be read, not assumed";
  EXPECT_NEAR((in.bbox_max - in.bbox_min - Vec3(1, 2, 3)).norm(), 0, 1e-6);
  // vertex k is FreeCAD's Vertex<k+1>: the order of TopExp::MapShapes
  TopTools_IndexedMapOfShape vs;
  TopExp::MapShapes(box, TopAbs_VERTEX, vs);
  for (int i = 1; i <= vs.Extent(); ++i) {
    const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vs(i)));
    EXPECT_NEAR((in.vertices[i - 1].point - Vec3(p.X(), p.Y(), p.Z())).norm(), 0, 1e-15);
    EXPECT_GT(in.vertices[i - 1].tolerance, 0);
  }
  test::check_wires(in);
}

TEST(OccTopology, EdgesRunFromV0ToV1) {
  const BrepInput in = input_of(test::make_box_minus_cylinder(), "box minus cylinder");
  for (size_t e = 0; e < in.edges.size(); ++e) {
    const BrepEdge& edge = in.edges[e];
    ASSERT_TRUE(edge.curve) << edge_name(e);
    EXPECT_LT((edge.curve->point(edge.curve->t_min()) - in.vertices[edge.v0].point).norm(), 1e-7) << edge_name(e);
    EXPECT_LT((edge.curve->point(edge.curve->t_max()) - in.vertices[edge.v1].point).norm(), 1e-7) << edge_name(e);
    EXPECT_GT(edge.tolerance, 0);
  }
}

TEST(OccTopology, CylinderSeamIsUsedTwiceWithTwoPcurves) {
  const BrepInput in = input_of(test::make_cylinder(), "cylinder");
  EXPECT_EQ(in.vertices.size(), 2u);
  EXPECT_EQ(in.edges.size(), 3u);
  ASSERT_EQ(in.faces.size(), 3u);
  int lateral = -1;
  for (size_t f = 0; f < in.faces.size(); ++f)
    if (!in.faces[f].planar) lateral = static_cast<int>(f);
  ASSERT_GE(lateral, 0);
  const BrepFace& face = in.faces[lateral];
  EXPECT_NEAR(face.surface->period_u(), 2 * M_PI, 1e-12);
  EXPECT_EQ(face.surface->period_v(), 0);
  EXPECT_NEAR(face.surface->uv_max().x() - face.surface->uv_min().x(), 2 * M_PI, 1e-9);
  EXPECT_NEAR(face.surface->max_curvature(Vec2(1, 1)), 1.0, 1e-9);
  ASSERT_EQ(face.wires.size(), 1u);
  const auto& wire = face.wires[0];
  ASSERT_EQ(wire.size(), 4u);
  // the seam: the one edge used twice, in opposite directions, on opposite sides of the box
  std::vector<const BrepEdgeUse*> seam;
  for (const auto& use : wire)
    for (const auto& other : wire)
      if (&use != &other && use.edge == other.edge) seam.push_back(&use);
  ASSERT_EQ(seam.size(), 2u);
  EXPECT_NE(seam[0]->reversed, seam[1]->reversed);
  EXPECT_NE(seam[0]->pcurve, seam[1]->pcurve);
  const BrepEdge& edge = in.edges[seam[0]->edge];
  const double t = 0.5 * (edge.curve->t_min() + edge.curve->t_max());
  const Vec2 a = seam[0]->pcurve->uv(t), b = seam[1]->pcurve->uv(t);
  EXPECT_NEAR(std::abs(a.x() - b.x()), 2 * M_PI, 1e-9);
  EXPECT_NEAR(a.y(), b.y(), 1e-12);
  EXPECT_LT((face.surface->point(a) - face.surface->point(b)).norm(), 1e-12);
  test::check_wires(in);
}

TEST(OccTopology, SphereHasDegeneratePoleEdges) {
  const BrepInput in = input_of(test::make_sphere(), "sphere");
  ASSERT_EQ(in.faces.size(), 1u);
  EXPECT_EQ(in.vertices.size(), 2u);
  EXPECT_EQ(in.edges.size(), 3u);
  int degenerate = 0;
  for (const BrepEdge& e : in.edges) {
    if (!e.degenerate) continue;
    ++degenerate;
    EXPECT_FALSE(e.curve);
    EXPECT_EQ(e.v0, e.v1);
    EXPECT_NEAR(std::abs(in.vertices[e.v0].point.z()), 2, 1e-9) << "a pole";
  }
  EXPECT_EQ(degenerate, 2);
  EXPECT_EQ(in.faces[0].wires[0].size(), 4u);  // pole, seam, pole, seam
  // (at an umbilic the principal curvatures come from sqrt(H^2 - K) of a round-off: 1e-8)
  EXPECT_NEAR(in.faces[0].surface->max_curvature(Vec2(1, 0.3)), 0.5, 1e-7);
  test::check_wires(in);
}

TEST(OccTopology, CompSolidListsTheSharedFaceInBothSolids) {
  const BrepInput in = input_of(test::make_two_box_compsolid(), "two boxes");
  ASSERT_EQ(in.solids.size(), 2u);
  EXPECT_EQ(in.faces.size(), 11u);
  EXPECT_EQ(in.vertices.size(), 12u);
  EXPECT_EQ(in.solids[0].faces.size(), 6u);
  EXPECT_EQ(in.solids[1].faces.size(), 6u);
  std::vector<Index> shared;
  for (Index f : in.solids[0].faces)
    if (std::count(in.solids[1].faces.begin(), in.solids[1].faces.end(), f)) shared.push_back(f);
  ASSERT_EQ(shared.size(), 1u);
  const BrepFace& face = in.faces[shared[0]];
  const Vec3 p = face.surface->point(0.5 * (face.surface->uv_min() + face.surface->uv_max()));
  EXPECT_NEAR(p.x(), 1, 1e-12);
  // its orientation is the first solid's: the normal leaves the box [0,1]^3
  EXPECT_GT(outward_normal(face).x(), 0);
  const BrepChecker check(in);
  EXPECT_NEAR(check.solid_volume(0), 1, 1e-9);
  EXPECT_NEAR(check.solid_volume(1), 1, 1e-9);
  EXPECT_NEAR(check.volume(), 2, 1e-9);
}

TEST(OccTopology, CompoundOfSolidsKeepsItsInterfaces) {
  // FreeCAD's BooleanFragments: a compound (not a CompSolid) of solids sharing faces
  const TopoDS_Shape cs = test::make_two_box_compsolid();
  TopoDS_Compound c;
  BRep_Builder b;
  b.MakeCompound(c);
  for (TopExp_Explorer ex(cs, TopAbs_SOLID); ex.More(); ex.Next()) b.Add(c, ex.Current());
  const BrepInput in = input_of(c, "fragments");
  EXPECT_EQ(in.solids.size(), 2u);
  EXPECT_EQ(in.faces.size(), 11u);
}

TEST(OccTopology, OverlappingSolidsAreRefusedNamingBoth) {
  // a compound of three unit-ish boxes: the first two apart, the third through the second
  TopoDS_Compound c;
  BRep_Builder b;
  b.MakeCompound(c);
  b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(-5, 0, 0), 2, 2, 2).Shape());
  b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 2, 2, 2).Shape());
  b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(1, 1, 1), 2, 2, 2).Shape());
  EXPECT_EQ(test::error_of([&] { input_of(c, "assembly"); }),
            "assembly: Solid2 and Solid3 overlap (a common volume of 1 around (1.5, 1.5, 1.5)): meshed apart they would fill that "
            "space twice; fuse them, or make them BooleanFragments so that they share their faces");
  // touching along a face, not sharing it (an assembly's parts side by side): no volume in common
  TopoDS_Compound side;
  b.MakeCompound(side);
  b.Add(side, BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 2, 2, 2).Shape());
  b.Add(side, BRepPrimAPI_MakeBox(gp_Pnt(2, 0, 0), 2, 2, 2).Shape());
  EXPECT_EQ(input_of(side, "side by side").solids.size(), 2u);
}

TEST(OccTopology, ShellListedBesideItsSolidIsNoSecondSolid) {
  // as corpus/x_cube_sphere_cube_compound.brep has it: the compound holds the solid and its shell
  const TopoDS_Shape box = test::make_box();
  TopoDS_Compound c;
  BRep_Builder b;
  b.MakeCompound(c);
  for (TopExp_Explorer ex(box, TopAbs_SHELL); ex.More(); ex.Next()) b.Add(c, ex.Current());
  for (TopExp_Explorer ex(box, TopAbs_SOLID); ex.More(); ex.Next()) b.Add(c, ex.Current());
  const BrepInput in = input_of(c, "solid and shell");
  EXPECT_EQ(in.solids.size(), 1u);
  EXPECT_EQ(in.faces.size(), 6u);
}

TEST(OccTopology, CavityShellIsListedInTheSolid) {
  const TopoDS_Shape shape = test::make_box_with_cavity();
  ASSERT_EQ(count(shape, TopAbs_SHELL), 2);
  const BrepInput in = input_of(shape, "box with cavity");
  ASSERT_EQ(in.solids.size(), 1u);
  EXPECT_EQ(in.solids[0].faces.size(), in.faces.size());
  EXPECT_EQ(in.faces.size(), 7u);
  const BrepChecker check(in);
  EXPECT_NEAR(check.solid_volume(0), 64 - 4 * M_PI / 3, 1e-6);
  EXPECT_EQ(check.classify(0, Vec3(2, 2, 2), 1e-7), PointState::outside) << "the cavity is not material";
  EXPECT_EQ(check.classify(0, Vec3(0.5, 0.5, 0.5), 1e-7), PointState::inside);
  // the sphere's normal points into the cavity (out of the material)
  for (const BrepFace& f : in.faces)
    if (!f.planar) {
      const Vec2 uv(1, 0.2);
      EXPECT_LT(((f.reversed ? -1.0 : 1.0) * f.surface->normal(uv)).dot(f.surface->point(uv) - Vec3(2, 2, 2)), 0);
    }
}

TEST(OccTopology, ClosedShellBecomesASolid) {
  TopoDS_Shape shell;
  for (TopExp_Explorer ex(test::make_box(), TopAbs_SHELL); ex.More(); ex.Next()) shell = ex.Current();
  for (const TopoDS_Shape& s : {shell, shell.Reversed()}) {
    const BrepInput in = input_of(s, "shell");
    ASSERT_EQ(in.solids.size(), 1u);
    EXPECT_EQ(in.solids[0].faces.size(), 6u);
    const BrepChecker check(in);
    EXPECT_NEAR(check.solid_volume(0), 6, 1e-9) << "oriented outward even when the shell came inside out";
    for (const BrepFace& f : in.faces) {
      const Vec3 p = f.surface->point(0.5 * (f.surface->uv_min() + f.surface->uv_max()));
      EXPECT_GT(outward_normal(f).dot(p - Vec3(0.5, 1, 1.5)), 0);
    }
  }
}

TEST(OccTopology, OpenShellHasNoSolidToMesh) {
  BRep_Builder b;
  TopoDS_Shell open;
  b.MakeShell(open);
  int n = 0;
  const TopoDS_Shape box = test::make_box();
  for (TopExp_Explorer ex(box, TopAbs_FACE); ex.More() && n < 5; ex.Next(), ++n) b.Add(open, ex.Current());
  const std::string m = test::error_of([&] { input_of(open, "Shell001"); });
  // where it is open, as FreeCAD numbers the edges and faces: the missing sixth face's edges
  const std::string head = "Shell001: the shape has no solid to mesh (it holds 5 faces and no closed shell: 4 edges bound one face only, where the shell is open (";
  ASSERT_EQ(m.substr(0, head.size()), head) << m;
  TopoDS_Shape sixth;
  n = 0;
  for (TopExp_Explorer ex(box, TopAbs_FACE); ex.More(); ex.Next(), ++n)
    if (n == 5) sixth = ex.Current();
  TopTools_IndexedMapOfShape edges, faces, missing;
  TopExp::MapShapes(open, TopAbs_EDGE, edges);
  TopExp::MapShapes(open, TopAbs_FACE, faces);
  TopExp::MapShapes(sixth, TopAbs_EDGE, missing);
  const std::regex named(R"(Edge(\d+) of Face(\d+))");
  int listed = 0;
  for (std::sregex_iterator it(m.begin(), m.end(), named), end; it != end; ++it, ++listed) {
    const int e = std::stoi((*it)[1]), f = std::stoi((*it)[2]);
    ASSERT_TRUE(e >= 1 && e <= edges.Extent() && f >= 1 && f <= faces.Extent()) << m;
    EXPECT_TRUE(missing.Contains(edges(e))) << "Edge" << e << " is not on the missing face: " << m;
    TopTools_IndexedMapOfShape of_face;
    TopExp::MapShapes(faces(f), TopAbs_EDGE, of_face);
    EXPECT_TRUE(of_face.Contains(edges(e))) << m;
  }
  EXPECT_EQ(listed, 3) << m;
  EXPECT_EQ(m.substr(m.size() - 7), ", ...))") << m;
  const TopoDS_Face one = BRepBuilderAPI_MakeFace(gp_Pln(), 0, 1, 0, 1).Face();
  EXPECT_EQ(test::error_of([&] { input_of(one, "Face"); }),
            "Face: the shape has no solid to mesh (it holds 1 face and no closed shell: 4 edges bound one face only, where the shell "
            "is open (Edge1 of Face1, Edge2 of Face1, Edge3 of Face1, ...))");
}

TEST(OccTopology, PlacedShapeIsEvaluatedWhereItIs) {
  // a location on the shape (not baked into the geometry): points come out moved
  gp_Trsf move;
  move.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), M_PI / 2);
  move.SetTranslationPart(gp_Vec(10, 0, 0));
  const TopoDS_Shape placed = BRepBuilderAPI_Transform(test::make_cylinder(), move, false).Shape();
  ASSERT_FALSE(placed.Location().IsIdentity());
  const BrepInput in = input_of(placed, "placed cylinder");
  const BrepChecker check(in);
  for (size_t f = 0; f < in.faces.size(); ++f) {
    const ParametricSurface& s = *in.faces[f].surface;
    const Vec3 p = s.point(0.5 * (s.uv_min() + s.uv_max()));
    EXPECT_LT(check.distance_to_face(f, p), 1e-9) << face_name(f);
    EXPECT_NEAR(p.x(), 10, 1 + 1e-9);
  }
  for (size_t e = 0; e < in.edges.size(); ++e) {
    const ParametricCurve& c = *in.edges[e].curve;
    EXPECT_LT(check.distance_to_edge(e, c.point(0.3 * c.t_min() + 0.7 * c.t_max())), 1e-9) << edge_name(e);
  }
  test::check_wires(in);
}

TEST(OccChecker, MeasuresDistancesVolumesAndAreas) {
  const BrepInput in = input_of(test::make_box(), "box");
  const BrepChecker check(in);
  EXPECT_NEAR(check.volume(), 6, 1e-9);
  double area = 0;
  for (size_t f = 0; f < in.faces.size(); ++f) area += check.face_area(f);
  EXPECT_NEAR(area, 2 * (1 * 2 + 2 * 3 + 1 * 3), 1e-9);
  // a point beyond a corner: its distance to every face is to that face's nearest boundary point
  const Vec3 p(2, 3, 4);
  double nearest_face = 1e9, nearest_vertex = 1e9;
  for (size_t f = 0; f < in.faces.size(); ++f) nearest_face = std::min(nearest_face, check.distance_to_face(f, p));
  for (size_t v = 0; v < in.vertices.size(); ++v) nearest_vertex = std::min(nearest_vertex, check.distance_to_vertex(v, p));
  EXPECT_NEAR(nearest_face, std::sqrt(3.0), 1e-9);
  EXPECT_NEAR(nearest_vertex, std::sqrt(3.0), 1e-9);
  EXPECT_EQ(check.classify(0, Vec3(0.5, 1, 1.5), 1e-7), PointState::inside);
  EXPECT_EQ(check.classify(0, Vec3(0.5, 1, 3), 1e-7), PointState::on);
  EXPECT_EQ(check.classify(0, p, 1e-7), PointState::outside);
  EXPECT_HAS(test::error_of([&] { check.distance_to_face(6, p); }), "there is no face 7");
  BrepInput analytic;
  analytic.source = "analytic";
  EXPECT_HAS(test::error_of([&] { BrepChecker c(analytic); }), "analytic: the input holds no OpenCASCADE shape");
}

}  // namespace
}  // namespace bisect
