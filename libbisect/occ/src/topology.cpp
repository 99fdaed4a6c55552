// A TopoDS_Shape as a BrepInput: vertices, edges, faces with their wires and pcurves, solids, all
// numbered as FreeCAD numbers them.
#include <BRepAlgoAPI_Common.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cstdio>
#include <unordered_set>

#include "occ_geometry.hpp"
#include "occ_guard.hpp"
#include "occ_shape.hpp"
#include "pcurve_deviation.hpp"

namespace bisect::occ {
namespace {

bool is_boundary(const TopoDS_Shape& s) {
  return s.Orientation() == TopAbs_FORWARD || s.Orientation() == TopAbs_REVERSED;
}

std::string count_of(int n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

// Where a shape with faces but no closed shell is open: the edges that bound one face only (a
// seam, bounding its face twice, and a degenerate edge are not open), named as FreeCAD numbers
// them, the first three listed. corpus/cube_filet.brep (a cube's fillets and corner spheres, its
// planar faces missing) was refused as "no closed shell" with nothing for the user to look at.
std::string open_edges(const TopoDS_Shape& shape, const OccShape& m) {
  TopTools_IndexedDataMapOfShapeListOfShape faces_of;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, faces_of);
  std::vector<std::string> named;
  int open = 0;
  for (int i = 1; i <= faces_of.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(faces_of.FindKey(i));
    if (BRep_Tool::Degenerated(e)) continue;
    TopTools_IndexedMapOfShape distinct;
    for (const TopoDS_Shape& f : faces_of(i)) distinct.Add(f);
    if (distinct.Extent() != 1 || BRep_Tool::IsClosed(e, TopoDS::Face(distinct(1)))) continue;
    if (++open <= 3) named.push_back(edge_name(m.edges.FindIndex(e) - 1) + " of " + face_name(m.faces.FindIndex(distinct(1)) - 1));
  }
  if (open == 0) return "";
  std::string text = count_of(open, "edge") + " bound one face only, where the shell is open (";
  for (std::size_t k = 0; k < named.size(); ++k) text += (k ? ", " : "") + named[k];
  if (open > 3) text += ", ...";
  return text + ")";
}

// The shape's solids, then its closed shells that no solid holds, made solids (as Gmsh does);
// open shells are left out (their faces keep their numbers and belong to no solid). A compound
// may list a solid's shell beside the solid (corpus/x_cube_sphere_cube_compound.brep): that
// shell is the solid's, not another solid.
std::vector<TopoDS_Solid> solids_of(const TopoDS_Shape& shape) {
  std::vector<TopoDS_Solid> out;
  TopTools_IndexedMapOfShape solids, shells, held;
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  for (int i = 1; i <= solids.Extent(); ++i) {
    out.push_back(TopoDS::Solid(solids(i)));
    TopExp::MapShapes(solids(i), TopAbs_SHELL, held);
  }
  for (TopExp_Explorer ex(shape, TopAbs_SHELL, TopAbs_SOLID); ex.More(); ex.Next())
    if (!held.Contains(ex.Current())) shells.Add(ex.Current());
  for (int i = 1; i <= shells.Extent(); ++i) {
    const TopoDS_Shell& shell = TopoDS::Shell(shells(i));
    if (!BRep_Tool::IsClosed(shell)) continue;
    BRepBuilderAPI_MakeSolid make(shell);
    if (!make.IsDone()) continue;
    TopoDS_Solid solid = make.Solid();
    BRepLib::OrientClosedSolid(solid);  // outward normals: a shell may come inside out
    out.push_back(solid);
  }
  return out;
}

BrepVertex vertex_of(const TopoDS_Vertex& v) {
  const gp_Pnt p = BRep_Tool::Pnt(v);
  return BrepVertex{Vec3(p.X(), p.Y(), p.Z()), BRep_Tool::Tolerance(v)};
}

BrepEdge edge_of(const TopoDS_Edge& e, Index index, const OccShape& m) {
  const TopoDS_Edge fwd = TopoDS::Edge(e.Oriented(TopAbs_FORWARD));
  BrepEdge out;
  TopoDS_Vertex v0, v1;
  TopExp::Vertices(fwd, v0, v1);  // the forward vertex sits at the first parameter
  if (v0.IsNull() || v1.IsNull()) throw InputError(edge_name(index) + ": the edge has no vertex at one end");
  out.v0 = m.vertices.FindIndex(v0) - 1;
  out.v1 = m.vertices.FindIndex(v1) - 1;
  out.degenerate = BRep_Tool::Degenerated(fwd);
  out.tolerance = BRep_Tool::Tolerance(fwd);
  if (!out.degenerate) out.curve = std::make_shared<OccCurve>(fwd, index);
  return out;
}

// The uses of the wire's edges in order along it. BRepTools_WireExplorer orders them by
// connection (a seam edge comes twice, once per side); on a wire it cannot chain it skips
// edges, and then the wire's own order is kept.
std::vector<BrepEdgeUse> wire_of(const TopoDS_Wire& wire, const TopoDS_Face& face, Index fi, const OccShape& m) {
  std::vector<TopoDS_Edge> order, stored;
  for (TopoDS_Iterator it(wire); it.More(); it.Next())
    if (is_boundary(it.Value()) && it.Value().ShapeType() == TopAbs_EDGE) stored.push_back(TopoDS::Edge(it.Value()));
  for (BRepTools_WireExplorer ex(wire, face); ex.More(); ex.Next())
    if (is_boundary(ex.Current())) order.push_back(ex.Current());
  if (order.size() != stored.size()) order = stored;
  std::vector<BrepEdgeUse> uses;
  for (const TopoDS_Edge& e : order) {
    BrepEdgeUse use;
    use.edge = m.edges.FindIndex(e) - 1;
    use.reversed = e.Orientation() == TopAbs_REVERSED;
    use.pcurve = std::make_shared<OccPcurve>(e, face, use.edge, fi);
    uses.push_back(std::move(use));
  }
  return uses;
}

// Solids of one shape that overlap (a compound of a box and a cylinder through it, not fused and
// not made BooleanFragments): each would be meshed on its own and the two meshes would fill the
// same space twice, which CalculiX takes as twice the material. Refused, naming both. Pairs whose
// boxes meet and that share no face are intersected (BRepAlgoAPI_Common); a common volume over
// a millionth of the smaller solid's is an overlap (touching solids have none).
void refuse_overlaps(const BrepInput& in, const OccShape& m) {
  const std::size_t n = m.solids.size();
  // solids joined by shared faces (BooleanFragments, a CompSolid) are one conforming body: they
  // meet only on those faces and are not compared
  std::vector<std::size_t> group(n);
  const std::vector<std::vector<Index>> bodies = connected_solids(in);
  for (std::size_t b = 0; b < bodies.size(); ++b)
    for (Index s : bodies[b]) group[s] = b;
  for (std::size_t s = 0; s < n; ++s)
    for (std::size_t t = s + 1; t < n; ++t) {
      const BrepSolid &a = in.solids[s], &b = in.solids[t];
      // boxes that meet in a slab thinner than a thousandth of the smaller box (parts stacked face
      // to face, whose boxes BRepBndLib widens by their tolerances) hold no common volume worth a
      // boolean. The rest cost: x_as1_tu_203 (an assembly of 18 solids in contact) has 34 such
      // pairs, 3.2 s of intersections beside 25 s of meshing at R = 2e4
      const Vec3 lo = a.bbox_min.cwiseMax(b.bbox_min), hi = a.bbox_max.cwiseMin(b.bbox_max);
      const double smaller = std::min((a.bbox_max - a.bbox_min).norm(), (b.bbox_max - b.bbox_min).norm());
      if ((hi - lo).minCoeff() <= 1e-3 * smaller) continue;
      if (group[s] == group[t]) continue;
      const std::string pair = solid_name(static_cast<Index>(s)) + " and " + solid_name(static_cast<Index>(t));
      GProp_GProps common;
      const bool done = guard([&] { return in.source + ": " + pair; }, "OpenCASCADE could not intersect them", [&] {
        BRepAlgoAPI_Common op;
        TopTools_ListOfShape args, tools;
        args.Append(m.solids[s]);
        tools.Append(m.solids[t]);
        op.SetArguments(args);
        op.SetTools(tools);
        op.SetRunParallel(Standard_True);
        op.SetNonDestructive(Standard_True);
        op.Build();
        if (!op.IsDone()) return false;
        BRepGProp::VolumeProperties(op.Shape(), common);
        return true;
      });
      const double volume = done ? std::abs(common.Mass()) : 0;
      if (!(volume > 1e-6 * std::min(a.volume, b.volume))) continue;
      const gp_Pnt c = common.CentreOfMass();
      char amount[32];
      std::snprintf(amount, sizeof amount, "%.3g", volume);
      throw InputError(in.source + ": " + pair + " overlap (a common volume of " + amount + " around " + point_name(Vec3(c.X(), c.Y(), c.Z())) +
                       "): meshed apart they would fill that space twice; fuse them, or make them BooleanFragments so that "
                       "they share their faces");
    }
}

BrepFace face_of(const TopoDS_Face& f, Index index, bool reversed, const OccShape& m) {
  // wires and pcurves are read on the forward face: the edges' orientations are then the ones of
  // the face's own parametrisation (the outer wire counter-clockwise in (u, v))
  const TopoDS_Face fwd = TopoDS::Face(f.Oriented(TopAbs_FORWARD));
  auto surface = std::make_shared<OccSurface>(fwd, index);
  BrepFace out;
  out.reversed = reversed;
  out.planar = surface->is_plane();
  out.tolerance = BRep_Tool::Tolerance(fwd);
  out.surface = std::move(surface);
  const TopoDS_Wire outer = BRepTools::OuterWire(fwd);
  if (outer.IsNull()) throw InputError(face_name(index) + ": the face has no boundary wire");
  out.wires.push_back(wire_of(outer, fwd, index, m));
  // inner wires; INTERNAL and EXTERNAL ones (edges embedded in the face) bound nothing
  for (TopoDS_Iterator it(fwd); it.More(); it.Next())
    if (it.Value().ShapeType() == TopAbs_WIRE && !it.Value().IsSame(outer) && is_boundary(it.Value()))
      out.wires.push_back(wire_of(TopoDS::Wire(it.Value()), fwd, index, m));
  return out;
}

}  // namespace

BrepInput brep_input_from_shape(const TopoDS_Shape& shape, const std::string& source) {
  if (shape.IsNull()) throw InputError(source + ": the shape is empty");
  auto model = std::make_shared<OccShape>();
  model->shape = shape;
  model->source = source;
  OccShape& m = *model;
  guard([&] { return source; }, "OpenCASCADE could not list the shape's parts", [&] {
    TopExp::MapShapes(shape, TopAbs_VERTEX, m.vertices);
    TopExp::MapShapes(shape, TopAbs_EDGE, m.edges);
    TopExp::MapShapes(shape, TopAbs_FACE, m.faces);
    m.solids = solids_of(shape);
  });
  if (m.solids.empty()) {
    const std::string open = m.faces.Extent() > 0 ? guard([&] { return source; }, "OpenCASCADE could not list the shape's edges",
                                                          [&] { return open_edges(shape, m); })
                                                  : std::string();
    throw InputError(source + ": the shape has no solid to mesh (it holds " + count_of(m.faces.Extent(), "face") +
                     " and no closed shell" + (open.empty() ? "" : ": " + open) + ")");
  }

  BrepInput in;
  in.source = source;
  for (int i = 1; i <= m.vertices.Extent(); ++i)
    in.vertices.push_back(guard([&] { return source + ": " + vertex_name(i - 1); }, "OpenCASCADE could not read it",
                                [&] { return vertex_of(TopoDS::Vertex(m.vertices(i))); }));
  for (int i = 1; i <= m.edges.Extent(); ++i)
    in.edges.push_back(guard([&] { return source + ": " + edge_name(i - 1); }, "OpenCASCADE could not read it",
                             [&] { return edge_of(TopoDS::Edge(m.edges(i)), i - 1, m); }));

  // A face's orientation is the one it has where the solids first meet it (in the second solid
  // of an interface it is the opposite); a face of no solid keeps the one it has in the shape.
  std::vector<signed char> reversed(m.faces.Extent(), -1);
  in.solids.resize(m.solids.size());
  guard([&] { return source; }, "OpenCASCADE could not list the solids' faces", [&] {
    for (size_t s = 0; s < m.solids.size(); ++s) {
      std::unordered_set<Index> seen;
      for (TopExp_Explorer ex(m.solids[s], TopAbs_FACE); ex.More(); ex.Next()) {
        const Index f = m.faces.FindIndex(ex.Current()) - 1;
        if (f < 0 || !seen.insert(f).second) continue;
        in.solids[s].faces.push_back(f);
        if (reversed[f] < 0) reversed[f] = ex.Current().Orientation() == TopAbs_REVERSED;
      }
    }
  });
  // Several solids: each one's box and volume, by which the pipeline meshes groups of solids
  // that share no face apart and shares the count among them (brep_generate.cpp).
  if (m.solids.size() > 1)
    for (size_t s = 0; s < m.solids.size(); ++s)
      guard([&] { return source + ": " + solid_name(static_cast<Index>(s)); }, "OpenCASCADE could not measure it", [&] {
        Bnd_Box box;
        BRepBndLib::Add(m.solids[s], box, Standard_False);
        if (!box.IsVoid()) {
          double x0, y0, z0, x1, y1, z1;
          box.Get(x0, y0, z0, x1, y1, z1);
          in.solids[s].bbox_min = Vec3(x0, y0, z0), in.solids[s].bbox_max = Vec3(x1, y1, z1);
        }
        GProp_GProps props;
        BRepGProp::VolumeProperties(m.solids[s], props);
        in.solids[s].volume = std::abs(props.Mass());
      });
  for (int i = 1; i <= m.faces.Extent(); ++i) {
    const TopoDS_Face& f = TopoDS::Face(m.faces(i));
    const bool rev = reversed[i - 1] < 0 ? f.Orientation() == TopAbs_REVERSED : reversed[i - 1] > 0;
    in.faces.push_back(guard([&] { return source + ": " + face_name(i - 1); }, "OpenCASCADE could not read it",
                             [&] { return face_of(f, i - 1, rev, m); }));
  }

  // Real CAD understates some edges' tolerances (corpus/wrenchnut.brep: Edge17 declares 1.4e-3
  // and strays 0.09 from its pcurve near one end), and OpenCASCADE's checker, sampling 23 points,
  // lets it pass. An edge's tolerance here covers what its pcurves really deviate.
  for (size_t f = 0; f < in.faces.size(); ++f)
    for (const auto& wire : in.faces[f].wires)
      for (const BrepEdgeUse& use : wire) {
        BrepEdge& edge = in.edges[use.edge];
        if (edge.degenerate) continue;
        const double d = pcurve_deviation(*edge.curve, *use.pcurve, *in.faces[f].surface);
        edge.tolerance = std::max(edge.tolerance, 1.05 * d);
      }

  // BRepBndLib::Add, not AddOptimal: the optimal box costs Block.brep 0.2 s, more than reading
  // it; this one may exceed the shape by its tolerances and its B-splines' control points.
  guard([&] { return source; }, "OpenCASCADE could not take the bounding box", [&] {
    Bnd_Box box;
    BRepBndLib::Add(shape, box, Standard_False);
    if (box.IsVoid()) return;
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    in.bbox_min = Vec3(x0, y0, z0), in.bbox_max = Vec3(x1, y1, z1);
  });
  if (m.solids.size() > 1) refuse_overlaps(in, m);  // once the faces are read: the bodies are found by them
  std::shared_ptr<const OccShape> keep = model;
  in.tessellate = [keep](double linear, double angular) { return tessellate_shape(*keep, linear, angular); };
  in.shape = keep;
  return in;
}

const OccShape& occ_shape_of(const BrepInput& in) {
  if (!in.shape) throw InputError(in.source + ": the input holds no OpenCASCADE shape (it was not read by libbisect/occ)");
  return *static_cast<const OccShape*>(in.shape.get());
}

}  // namespace bisect::occ
