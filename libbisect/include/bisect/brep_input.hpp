// The B-rep route's input without OpenCASCADE types (ARCHITECTURE.md §1): what libbisect/occ
// makes of a shape (a .brep, .step or .iges file, or FreeCAD's Part.Shape handed over as a BREP
// string), and what the pipeline consumes. Tests build it from analytic geometry as well.
//
// Numbering is FreeCAD's: vertex, edge, face and solid k here is FreeCAD's Vertex<k+1>,
// Edge<k+1>, Face<k+1> and Solid<k+1> (the order of TopExp::MapShapes on the whole shape), so a
// message or a FEM group names what the user sees.
#pragma once
#include <array>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bisect/parametric_surface.hpp"

namespace bisect {

struct BrepVertex {
  Vec3 point = Vec3::Zero();
  double tolerance = 0;  // BRep_Tool::Tolerance: the vertex is anywhere within this of `point`
};

struct BrepEdge {
  // The edge's 3D curve over exactly the edge's range [t_min, t_max]; null for a degenerate
  // edge (a sphere's pole, a cone's apex), whose points are all vertex v0.
  std::shared_ptr<const ParametricCurve> curve;
  Index v0 = -1, v1 = -1;  // the vertices at t_min and t_max (one and the same for a closed edge)
  bool degenerate = false;
  double tolerance = 0;
};

// One use of an edge in a face's boundary, with its pcurve (the edge in the face's parameter
// plane, over the edge's parameters). A seam edge (a full cylinder's) is used twice by its face,
// once on each side of the parameter box; a degenerate edge has a pcurve and no 3D curve.
struct BrepEdgeUse {
  Index edge = -1;
  bool reversed = false;  // the wire runs from the edge's t_max to its t_min here
  std::shared_ptr<const ParameterCurve> pcurve;
};

struct BrepFace {
  std::shared_ptr<const ParametricSurface> surface;  // in the shape's placement
  // The face's orientation in the shape: when true, the face's own normal is -(du x dv).
  bool reversed = false;
  bool planar = false;
  double tolerance = 0;
  // Boundary wires, the outer one first, each as its edge uses in order along the wire.
  std::vector<std::vector<BrepEdgeUse>> wires;
};

struct BrepSolid {
  // Every face of every shell of the solid, outer and inner (an inner shell bounds a cavity).
  // A face listed by two solids is an interface between them and is meshed once.
  std::vector<Index> faces;
  // FreeCAD's number of this solid in the whole shape (0-based) when the input is a part of a
  // larger one (one connected group of a compound's solids); -1: its place in `solids`
  Index number = -1;
  // its bounding box and volume, when the reader knows them (volume 0: unknown)
  Vec3 bbox_min = Vec3::Zero(), bbox_max = Vec3::Zero();
  double volume = 0;
};

// A tessellation of the whole shape (OpenCASCADE's BRepMesh): each edge is discretised once, so
// the faces' triangles share their nodes along edges and the surface is closed.
struct BrepTessellation {
  std::vector<Vec3> nodes;
  std::vector<Index> node_vertex;  // per node: the B-rep vertex it is, or -1
  std::vector<Index> node_edge;    // per node that is no vertex: the edge it lies on, or -1
  std::vector<double> node_t;      // per node on an edge: its parameter there
  struct Face {
    std::vector<std::array<Index, 3>> tris;   // node ids; counter-clockwise in the face's (u, v)
    std::vector<std::array<Vec2, 3>> uv;      // each corner's (u, v) on this face (a node on a
                                              // seam has one (u, v) per side)
  };
  std::vector<Face> faces;  // one per B-rep face
  struct Edge {
    std::vector<Index> nodes;  // from v0 to v1; a degenerate edge: its vertex's node alone
  };
  std::vector<Edge> edges;  // one per B-rep edge
};

struct BrepInput {
  std::vector<BrepVertex> vertices;
  std::vector<BrepEdge> edges;
  std::vector<BrepFace> faces;
  std::vector<BrepSolid> solids;
  std::string source;  // the file or object, for messages
  Vec3 bbox_min = Vec3::Zero(), bbox_max = Vec3::Zero();
  // Tessellates the shape with a linear deflection (model units) and an angular deflection
  // (radians). Throws InputError naming the face when a face cannot be tessellated.
  std::function<BrepTessellation(double linear, double angular)> tessellate;
  // The source geometry, kept alive for as long as this input (libbisect/occ: the OpenCASCADE
  // shape and its FreeCAD numbering, which BrepChecker reads); opaque to the core, and null for an
  // input built from analytic geometry.
  std::shared_ptr<const void> shape;
};

// The groups of solids that share faces (one conforming body each: BooleanFragments, a
// CompSolid), each in the order of `in.solids`, the groups in the order of their first solid.
// Solids of different groups share no face: separate bodies, meshed apart.
std::vector<std::vector<Index>> connected_solids(const BrepInput& in);

// Names as FreeCAD shows them: "Face12" for face 11 (0-based), and so on.
inline std::string face_name(Index f) { return "Face" + std::to_string(f + 1); }
inline std::string edge_name(Index e) { return "Edge" + std::to_string(e + 1); }
inline std::string vertex_name(Index v) { return "Vertex" + std::to_string(v + 1); }
inline std::string solid_name(Index s) { return "Solid" + std::to_string(s + 1); }
// A place for messages: "(x, y, z)" to 4 significant digits, enough to find it in FreeCAD.
inline std::string point_name(const Vec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", p.x(), p.y(), p.z());
  return text;
}
// " beside Face3, Face7, Face9 and 4 more" for B-rep faces (0-based ids, increasing, at most
// `shown` named); empty for none: where a message says what the user can look at in FreeCAD.
template <typename Faces>
std::string beside_faces(const Faces& faces, std::size_t shown = 3) {
  std::string out;
  std::size_t listed = 0;
  for (Index f : faces) {
    if (listed == shown) return out + " and " + std::to_string(faces.size() - shown) + " more";
    out += (listed++ ? ", " : " beside ") + face_name(f);
  }
  return out;
}
// Solid s of this input as FreeCAD names it in the whole shape.
inline std::string solid_name(const BrepInput& in, Index s) {
  return solid_name(s >= 0 && s < static_cast<Index>(in.solids.size()) && in.solids[s].number >= 0 ? in.solids[s].number : s);
}

}  // namespace bisect
