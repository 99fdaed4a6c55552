// Where the decomposition's model lies on the B-rep (the proxy's cut-up boundary mapped back onto
// the true geometry), and its edges discretised once by the size field.
//
// Every model node and edge of the proxy's decomposition lies on a proxy face (a piece of a
// B-rep face), on a chord of a B-rep edge, or inside the solid (where cut faces meet). A point
// of a proxy face maps to its B-rep face through the face's parameters (barycentric in the
// tessellation triangle's corner parameters; the plane itself for a planar face); a point of a
// chord maps to its edge's curve at the interpolated parameter; a proxy node that is a B-rep
// vertex maps to the vertex. That image is where the node goes in the mesh: on its face, edge
// or vertex exactly (ARCHITECTURE.md §1: every surface node lies on its face).
#pragma once
#include <array>
#include <functional>
#include <map>
#include <vector>

#include "bisect/brep_input.hpp"
#include "bisect/polyhedral_model.hpp"
#include "pipeline/brep_proxy.hpp"
#include "size/size_field.hpp"

namespace bisect::pipeline {

// What a point lies on. kFace: inside B-rep face `id` (its proxy face `proxy` gives the
// parameters); kEdge: on B-rep edge `id` at parameter t (on the chord `chord` of it); kVertex:
// B-rep vertex `id`; kInterior: inside a solid.
struct PointOn {
  enum Kind : char { kInterior = 0, kFace = 1, kEdge = 2, kVertex = 3 } kind = kInterior;
  Index id = -1;
  Index proxy = -1;  // kFace: a proxy face holding it
  Index chord = -1;  // kEdge: the segment index along tess.edges[id]
  double t = 0;      // kEdge: the edge parameter
};

// Per B-rep vertex, 1 at a pole: the vertex of a degenerate edge (one point in 3D, a segment in
// (u, v)).
std::vector<char> pole_vertices(const BrepInput& in);

// The B-rep edges that a point lying on `a` and one lying on `b` both lie on, in the order of
// their indices: a point on an edge lies on it, a vertex on every edge it bounds, a point inside
// a face or a solid on none (so: the edges a mesh edge between them may run along).
std::vector<Index> common_brep_edges(const BrepInput& in, const PointOn& a, const PointOn& b);

// The mesh's boundary nodes as they come from the model's edges: the proxy position (where the
// decomposition put it), the true position (its image, or for interior nodes the proxy position
// until the morph moves it), and what it lies on.
struct BoundaryNodes {
  std::vector<Vec3> x;      // true positions
  std::vector<Vec3> p;      // proxy positions
  std::vector<PointOn> on;
};

class BrepBoundary {
 public:
  BrepBoundary(const BrepInput& in, const BrepProxy& px, const PolyhedralModel& model);

  const PointOn& node_on(Index v) const { return node_on_[v]; }
  // The parameters on B-rep face k of the point p lying on proxy face s (s on face k).
  Vec2 uv_on_proxy(Index s, const Vec3& p) const;
  // The true point of a proxy point p described by `on` (kInterior: p itself).
  Vec3 image(const PointOn& on, const Vec3& p) const;
  // How far a point p on a proxy facet of B-rep face k moves with the face's own boundary: the
  // proxy's chords of the face's curved edges against the true curves, blended over the chords
  // within a chord's length of p (0 where there are none). See cut_node_image.
  Vec3 boundary_shift(Index k, const Vec3& p) const;
  // The true point of a node the cuts made inside a proxy face: the surface point nearest p moved
  // with the face's boundary. Beside a hole the proxy's chords cut across the hole's arc, and the
  // face's proxy facet holds a sliver the true face does not: a cut line leaving a vertex of
  // the arc at a grazing angle runs through it (corpus/Kurbelwelle.brep: a node 0.002 inside a
  // 3.5 mm bore, on the plane Face11, whose grid triangles then folded against the bore's). Moved
  // as the chords move, it stays on the face's side of the arc.
  Vec3 cut_node_image(const PointOn& on, const Vec3& p) const;
  // What the model edge (a, b) lies on: kEdge (along a chord of `id`), kFace (inside face `id`,
  // through proxy face `proxy`), or kInterior (a cut-cut edge).
  PointOn edge_on(Index a, Index b) const;

  // Every live model edge discretised once by h (ARCHITECTURE.md §1: edges discretised once, by
  // one size field): model nodes first (ids = model node ids), then each edge's inner nodes.
  // edge_nodes[(lo, hi)]: the inner nodes from lo to hi. cancelled (optional): asked once per
  // model edge, on any of the threads (util::ParallelPoll's hook), a true answer throws Cancelled
  // (up to 4096 curve points and size queries each). The same nodes for every thread count.
  void discretise_edges(const size::SizeField& h, const std::function<bool()>& cancelled = {}, int threads = 1);
  // Model edge (a, b)'s inner nodes from a to b: proxy points, true points, what each lies on.
  void discretise_edge(Index a, Index b, const size::SizeField& h, std::vector<Vec3>* p, std::vector<Vec3>* x,
                       std::vector<PointOn>* on) const;
  BoundaryNodes nodes;
  std::map<std::pair<Index, Index>, std::vector<Index>> edge_nodes;
  // Edges to cut into this many times the segments the size asks for: a face piece whose
  // boundary chords cross in its chart (two cut lines meeting at a small angle) is meshed again
  // with its boundary finer.
  std::map<std::pair<Index, Index>, int> finer;

  const BrepInput& in;
  const BrepProxy& px;
  const PolyhedralModel& model;

 private:
  std::vector<PointOn> node_on_;
  std::vector<char> pole_;  // per B-rep vertex: the vertex of a degenerate edge (a pole)
  // per B-rep face: the proxy chords of its edges whose true curve leaves them (edge, chord)
  std::vector<std::vector<std::array<Index, 2>>> bent_chords_;
  PointOn classify(Index v) const;
  bool on_chord(Index v, Index e, Index i, double* t) const;
  // the point of edge e's curve at the parameter a fraction f along chord i's (as on_chord maps)
  Vec3 curve_along_chord(Index e, Index i, double f) const;
};

}  // namespace bisect::pipeline
