// Random CSG solids for the decomposition's randomized test, built by OpenCASCADE: a modelling
// kernel that shares nothing with the code under test.
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <sstream>

#include "generated_solids.hpp"

namespace bisect::testing {
namespace {

// splitmix64: small, fast and the same on every machine
struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53; }
  int integer(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }
};

TopoDS_Shape random_box(Rng& g, std::ostringstream& what) {
  const gp_Pnt p(g.uniform(-0.3, 0.8), g.uniform(-0.3, 0.8), g.uniform(-0.3, 0.8));
  const double dx = g.uniform(0.3, 1.0), dy = g.uniform(0.3, 1.0), dz = g.uniform(0.3, 1.0);
  what << " box";
  return BRepPrimAPI_MakeBox(p, dx, dy, dz).Shape();
}

TopoDS_Shape random_prism(Rng& g, std::ostringstream& what) {
  // a convex polygon in z = 0, extruded, rotated about a random axis through the origin and moved
  const int n = g.integer(3, 6);
  const double rad = g.uniform(0.25, 0.5);
  BRepBuilderAPI_MakePolygon poly;
  double a0 = g.uniform(0, 2 * M_PI);
  for (int i = 0; i < n; ++i) {
    const double a = a0 + 2 * M_PI * (i + g.uniform(-0.25, 0.25)) / n;
    poly.Add(gp_Pnt(rad * std::cos(a), rad * std::sin(a), 0));
  }
  poly.Close();
  const TopoDS_Face base = BRepBuilderAPI_MakeFace(poly.Wire(), true).Face();
  const TopoDS_Shape prism = BRepPrimAPI_MakePrism(base, gp_Vec(0, 0, g.uniform(0.6, 1.4))).Shape();
  gp_Trsf rot, move;
  const gp_Dir axis(g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(0.1, 1));
  rot.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), axis), g.uniform(0, M_PI));
  move.SetTranslation(gp_Vec(g.uniform(0, 0.7), g.uniform(0, 0.7), g.uniform(0, 0.7)));
  what << " prism" << n;
  return BRepBuilderAPI_Transform(prism, move * rot, true).Shape();
}

int count(const TopoDS_Shape& s, TopAbs_ShapeEnum type) {
  int n = 0;
  for (TopExp_Explorer e(s, type); e.More(); e.Next()) ++n;
  return n;
}

// The planar faces of a one-solid shape as a PolyInput, or false when a face is not planar.
bool to_poly(const TopoDS_Shape& shape, PolyInput* out) {
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(shape, TopAbs_VERTEX, vertices);
  PolyInput in;
  for (int i = 1; i <= vertices.Extent(); ++i) {
    const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertices(i)));
    in.nodes.push_back(Vec3(p.X(), p.Y(), p.Z()));
  }
  PolyRegion region;
  for (TopExp_Explorer fe(shape, TopAbs_FACE); fe.More(); fe.Next()) {
    const TopoDS_Face face = TopoDS::Face(fe.Current());
    if (BRepAdaptor_Surface(face).GetType() != GeomAbs_Plane) return false;
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    const Index parent = static_cast<Index>(in.faces.size());
    auto add_wire = [&](const TopoDS_Wire& w, Index hole_of) {
      PolyFace pf;
      pf.hole_of = hole_of;
      for (BRepTools_WireExplorer we(w, face); we.More(); we.Next())
        pf.nodes.push_back(static_cast<Index>(vertices.FindIndex(we.CurrentVertex()) - 1));
      if (pf.nodes.size() < 3) return false;
      in.faces.push_back(pf);
      region.faces.push_back(static_cast<Index>(in.faces.size() - 1));
      return true;
    };
    if (!add_wire(outer, -1)) return false;
    for (TopExp_Explorer we(face, TopAbs_WIRE); we.More(); we.Next())
      if (!we.Current().IsSame(outer) && !add_wire(TopoDS::Wire(we.Current()), parent)) return false;
  }
  in.regions.push_back(region);
  *out = std::move(in);
  return true;
}

}  // namespace

PolyInput random_csg_polyhedron(std::uint64_t seed, std::string* description, bool* has_cavity, double* volume) {
  Rng g{seed * 0x2545F4914F6CDD1Dull + 1};
  for (int attempt = 0; attempt < 50; ++attempt) {
    std::ostringstream what;
    what << "seed " << seed << ":";
    try {
      // the first part is a box that holds the origin's neighbourhood: the cavity goes in it
      TopoDS_Shape solid = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), g.uniform(0.8, 1.2), g.uniform(0.8, 1.2), g.uniform(0.8, 1.2)).Shape();
      what << " box";
      const int parts = g.integer(1, 4);
      for (int i = 0; i < parts; ++i) {
        const TopoDS_Shape part = g.uniform(0, 1) < 0.5 ? random_box(g, what) : random_prism(g, what);
        BRepAlgoAPI_Fuse fuse(solid, part);
        if (!fuse.IsDone()) throw Standard_Failure("fuse failed");
        solid = fuse.Shape();
      }
      const bool cavity = g.next() % 4 == 0;
      if (cavity) {
        const double s = g.uniform(0.15, 0.3);
        const gp_Pnt c(g.uniform(0.2, 0.75 - s), g.uniform(0.2, 0.75 - s), g.uniform(0.2, 0.75 - s));
        BRepAlgoAPI_Cut cut(solid, BRepPrimAPI_MakeBox(c, s, s, s).Shape());
        if (!cut.IsDone()) throw Standard_Failure("cut failed");
        solid = cut.Shape();
        what << " cavity";
      }
      ShapeUpgrade_UnifySameDomain unify(solid, true, true, false);
      unify.Build();
      solid = unify.Shape();
      if (count(solid, TopAbs_SOLID) != 1) continue;  // the parts fell apart: draw again
      PolyInput in;
      if (!to_poly(solid, &in)) continue;
      in.source = "csg-" + std::to_string(seed);
      if (description) *description = what.str();
      if (has_cavity) *has_cavity = cavity;
      if (volume) {
        GProp_GProps props;
        BRepGProp::VolumeProperties(solid, props);
        *volume = props.Mass();
      }
      return in;
    } catch (const Standard_Failure&) {
      continue;
    }
  }
  return {};
}

}  // namespace bisect::testing
