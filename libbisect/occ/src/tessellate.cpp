// BRepMesh's tessellation of the whole shape as a BrepTessellation: one node per vertex, the
// nodes of each edge made once from its polygon on triangulation, and the faces' triangles
// welded onto them, so that the surface is closed.
//
// How BRepMesh leaves its results (OCCT 7.6): per face a Poly_Triangulation with nodes, (u, v)
// nodes and triangles; per edge and face a Poly_PolygonOnTriangulation listing the
// triangulation's nodes along the edge with the edge's parameters (a seam edge has two, one per
// side, picked by the edge's orientation); every face of an edge gets the same parameters, since
// BRepMesh discretises each edge once. Its triangles run counter-clockwise in (u, v) whatever the
// face's orientation (du x dv is their normal; the face's own normal is the opposite on a
// reversed face); the test TessellationTrianglesAreCounterClockwiseInUV checks this on every
// model.
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <Poly_Triangulation.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <limits>

#include "occ_guard.hpp"
#include "occ_shape.hpp"

namespace bisect::occ {
namespace {

struct FaceMesh {
  TopoDS_Face face;  // the copy's, forward
  Handle(Poly_Triangulation) tri;
  TopLoc_Location loc;  // the triangulation's location (polygons are found by it: keep the object)
  gp_Trsf place;        // its transformation
};

Vec3 node_of(const FaceMesh& fm, int i) {
  const gp_Pnt p = fm.tri->Node(i).Transformed(fm.place);
  return Vec3(p.X(), p.Y(), p.Z());
}

// The polygon's nodes run from v0 to v1 unless its parameters fall.
bool runs_backwards(const Poly_PolygonOnTriangulation& poly) {
  const int n = poly.NbNodes();
  return poly.HasParameters() && n > 1 && poly.Parameter(1) > poly.Parameter(n);
}

class Welder {
 public:
  Welder(const OccShape& m, const BRepBuilderAPI_Copy& copier) : m_(m), copier_(copier) {}

  BrepTessellation run() {
    const int nv = m_.vertices.Extent(), ne = m_.edges.Extent(), nf = m_.faces.Extent();
    for (int v = 1; v <= nv; ++v) {
      const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(m_.vertices(v)));
      add_node(Vec3(p.X(), p.Y(), p.Z()), v - 1, -1, 0);
    }
    faces_.resize(nf);
    std::vector<Index> first_face(ne, -1);
    for (int f = 0; f < nf; ++f) {
      FaceMesh& fm = faces_[f];
      fm.face = TopoDS::Face(copier_.ModifiedShape(m_.faces(f + 1)).Oriented(TopAbs_FORWARD));
      fm.tri = BRep_Tool::Triangulation(fm.face, fm.loc);
      fm.place = fm.loc.Transformation();
      if (fm.tri.IsNull() || fm.tri->NbTriangles() == 0)
        throw InputError(face_name(f) + ": OpenCASCADE could not tessellate it (BRepMesh left it without triangles)");
      for (TopExp_Explorer ex(m_.faces(f + 1), TopAbs_EDGE); ex.More(); ex.Next()) {
        const Index e = m_.edges.FindIndex(ex.Current()) - 1;
        if (first_face[e] < 0) first_face[e] = f;
      }
    }
    out_.edges.resize(ne);
    for (int e = 0; e < ne; ++e) make_edge_nodes(e, first_face[e]);
    out_.faces.resize(nf);
    for (int f = 0; f < nf; ++f) weld_face(f);
    return std::move(out_);
  }

 private:
  Index add_node(const Vec3& p, Index vertex, Index edge, double t) {
    out_.nodes.push_back(p);
    out_.node_vertex.push_back(vertex);
    out_.node_edge.push_back(edge);
    out_.node_t.push_back(t);
    return static_cast<Index>(out_.nodes.size() - 1);
  }

  TopoDS_Edge copied_edge(int e, TopAbs_Orientation o) const {
    return TopoDS::Edge(copier_.ModifiedShape(m_.edges(e + 1)).Oriented(o));
  }

  // The edge's nodes, v0 to v1, from its polygon on the first face that has it.
  void make_edge_nodes(int e, Index f) {
    const TopoDS_Edge& edge = TopoDS::Edge(m_.edges(e + 1));
    TopoDS_Vertex a, b;
    TopExp::Vertices(TopoDS::Edge(edge.Oriented(TopAbs_FORWARD)), a, b);
    const Index v0 = m_.vertices.FindIndex(a) - 1, v1 = m_.vertices.FindIndex(b) - 1;
    std::vector<Index>& nodes = out_.edges[e].nodes;
    if (BRep_Tool::Degenerated(edge)) {
      nodes = {v0};
      return;
    }
    if (f < 0) {  // an edge of no face: its ends alone
      nodes = v0 == v1 ? std::vector<Index>{v0} : std::vector<Index>{v0, v1};
      return;
    }
    const FaceMesh& fm = faces_[f];
    const Handle(Poly_PolygonOnTriangulation)& poly =
        BRep_Tool::PolygonOnTriangulation(copied_edge(e, TopAbs_FORWARD), fm.tri, fm.loc);
    if (poly.IsNull() || poly->NbNodes() < 2)
      throw InputError(face_name(f) + ": OpenCASCADE could not tessellate it (BRepMesh left " + edge_name(e) +
                       " without nodes on it)");
    const int n = poly->NbNodes();
    const bool back = runs_backwards(*poly);
    nodes.resize(n);
    nodes[0] = v0, nodes[n - 1] = v1;
    for (int k = 1; k < n - 1; ++k) {
      const int i = back ? n - k : k + 1;  // 1-based position in the polygon
      const double t = poly->HasParameters() ? poly->Parameter(i) : std::numeric_limits<double>::quiet_NaN();
      nodes[k] = add_node(node_of(fm, poly->Node(i)), -1, e, t);
    }
  }

  void weld_face(int f) {
    const FaceMesh& fm = faces_[f];
    std::vector<Index> global(fm.tri->NbNodes() + 1, -1);
    auto bind = [&](int local, Index g) {
      if (global[local] >= 0 && global[local] != g)
        throw MeshingError(face_name(f) + ": OpenCASCADE's tessellation puts one node on two places of the boundary");
      global[local] = g;
    };
    std::vector<char> done(m_.edges.Extent(), 0);
    for (TopExp_Explorer ex(m_.faces(f + 1), TopAbs_EDGE); ex.More(); ex.Next()) {
      const Index e = m_.edges.FindIndex(ex.Current()) - 1;
      if (done[e]) continue;
      done[e] = 1;
      const std::vector<Index>& nodes = out_.edges[e].nodes;
      const TopLoc_Location& loc = fm.loc;
      const Handle(Poly_PolygonOnTriangulation)& p1 =
          BRep_Tool::PolygonOnTriangulation(copied_edge(e, TopAbs_FORWARD), fm.tri, loc);
      const Handle(Poly_PolygonOnTriangulation)& p2 =
          BRep_Tool::PolygonOnTriangulation(copied_edge(e, TopAbs_REVERSED), fm.tri, loc);
      if (p1.IsNull() && p2.IsNull())
        throw InputError(face_name(f) + ": OpenCASCADE could not tessellate it (BRepMesh left " + edge_name(e) +
                         " without nodes on it)");
      for (const Handle(Poly_PolygonOnTriangulation)& p : {p1, p2}) {
        if (p.IsNull()) continue;
        const int n = p->NbNodes();
        if (nodes.size() == 1) {  // a degenerate edge (a pole): all its nodes are its vertex
          for (int i = 1; i <= n; ++i) bind(p->Node(i), nodes[0]);
          continue;
        }
        if (n != static_cast<int>(nodes.size()))
          throw MeshingError(face_name(f) + ": OpenCASCADE's tessellation has " + std::to_string(n) + " nodes on " +
                             edge_name(e) + " here and " + std::to_string(nodes.size()) + " on another face");
        const bool back = runs_backwards(*p);
        for (int k = 0; k < n; ++k) bind(p->Node(back ? n - k : k + 1), nodes[k]);
      }
    }
    for (int i = 1; i <= fm.tri->NbNodes(); ++i)
      if (global[i] < 0) global[i] = add_node(node_of(fm, i), -1, -1, 0);

    // BRepMesh always gives the (u, v) of its nodes (BRepMesh_BaseMeshAlgo::collectTriangles)
    if (!fm.tri->HasUVNodes())
      throw MeshingError(face_name(f) + ": OpenCASCADE's tessellation has no (u, v) for its nodes");
    BrepTessellation::Face& out = out_.faces[f];
    for (int k = 1; k <= fm.tri->NbTriangles(); ++k) {
      int n[3];
      fm.tri->Triangle(k).Get(n[0], n[1], n[2]);
      const std::array<Index, 3> tri = {global[n[0]], global[n[1]], global[n[2]]};
      // a triangle with a side on a degenerate edge (two corners at one pole) has no area
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) continue;
      std::array<Vec2, 3> uv;
      for (int c = 0; c < 3; ++c) {
        const gp_Pnt2d q = fm.tri->UVNode(n[c]);
        uv[c] = Vec2(q.X(), q.Y());
      }
      out.tris.push_back(tri);
      out.uv.push_back(uv);
    }
  }

  const OccShape& m_;
  const BRepBuilderAPI_Copy& copier_;
  std::vector<FaceMesh> faces_;
  BrepTessellation out_;
};

}  // namespace

BrepTessellation tessellate_shape(const OccShape& m, double linear, double angular) {
  if (!(linear > 0) || !(angular > 0))
    throw InputError(m.source + ": the tessellation needs a positive linear and angular deflection");
  auto where = [&] { return m.source; };
  // on a copy that shares the geometry: the shape as read stays without triangulations (a second
  // call with other deflections must not find, and keep, the first one's)
  BRepBuilderAPI_Copy copier;
  TopoDS_Shape copy;
  guard(where, "OpenCASCADE could not copy the shape", [&] {
    copier.Perform(m.shape, Standard_False, Standard_False);
    copy = copier.Shape();
  });
  guard(where, "OpenCASCADE could not tessellate the shape", [&] {
    IMeshTools_Parameters p;
    p.Deflection = linear;
    p.Angle = angular;
    p.InParallel = Standard_True;  // faces are meshed independently: the result is the same
    BRepMesh_IncrementalMesh mesh(copy, p);
  });
  try {
    return guard(where, "OpenCASCADE failed while reading its tessellation", [&] { return Welder(m, copier).run(); });
  } catch (const InputError& e) {
    const std::string msg = e.what();
    if (msg.rfind(m.source + ":", 0) == 0) throw;
    throw InputError(m.source + ": " + msg);
  }
}

}  // namespace bisect::occ
