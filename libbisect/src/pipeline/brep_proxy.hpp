// The proxy of the B-rep route: a coarse polyhedral stand-in for a CAD shape, which the convex
// decomposition (thesis 6.5-6.7) works on. A planar B-rep face is one polygon with its holes (its
// nodes put exactly on the face's plane); a curved face is its tessellation's triangles, each a
// planar face of its own; every solid is a region, a face of two solids an interface, an inner
// shell a cavity. The proxy is coarse on purpose (an angular deflection of tens of degrees): the
// surface grids are made afterwards on the true surfaces (brep_grids.hpp), and only the cuts'
// planes come from the proxy.
#pragma once
#include <array>
#include <vector>

#include "bisect/brep_input.hpp"
#include "bisect/poly_input.hpp"

namespace bisect::pipeline {

struct BrepProxy {
  PolyInput input;                 // nodes: the tessellation's, in its order
  BrepTessellation tess;
  std::vector<Index> face_brep;    // per proxy face: the B-rep face it lies on
  std::vector<Index> face_tri;     // per proxy face of a curved B-rep face: its triangle in
                                   // tess.faces[face_brep].tris; -1 for a planar face's polygons
  std::vector<std::array<double, 4>> plane;  // per B-rep face: n, d (n . x = d) for planar faces
  // Per node: the chords it ends, as (B-rep edge, segment i from tess.edges[e].nodes[i] to [i+1]).
  std::vector<std::vector<std::array<Index, 2>>> node_chords;
  double linear = 0, angular = 0;  // the deflections used
  std::size_t flat_facets = 0;     // curved faces' triangles with three nodes on one line
};

// Tessellates `in` at the given deflections and builds the proxy. Throws InputError naming the
// B-rep face when a face has no triangles. mend_flat: no triangle of a curved face is left flat
// in space where a flip of it takes it away (flat_facets counts any left), else the flips
// towards the surface may make them (see follow_surface in brep_proxy.cpp).
BrepProxy make_proxy(const BrepInput& in, double linear, double angular, bool mend_flat = false);

// The linear deflection at which px's curved faces would keep to its angular deflection: BRepMesh
// keeps to the angle on elementary surfaces, but on a B-spline face the linear deflection can
// govern, and a proxy made at a fraction of the shape's diagonal then stands far off a face
// curved tighter than that (a spring's wire, 3 mm round, at 4.9 mm: the proxy held 62% of its
// volume, and cells moved onto the true surface folded). Over every triangle of a curved face
// whose centroid lies further from the surface than the angle's chord height there,
// (1 - cos(angle / 2)) / curvature, the smallest such height; px.linear when none does.
double angle_keeping_deflection(const BrepInput& in, const BrepProxy& px);

}  // namespace bisect::pipeline
