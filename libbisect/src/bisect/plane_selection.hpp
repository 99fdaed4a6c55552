// Candidate bisection planes through a reflex edge (thesis 6.4.1): planes in the inner wedge,
// between the extensions of the two faces at the edge, at most seven and at least ten degrees
// apart (and, at a nearly flat edge beside a curved face, up to two more through a vertex).
// Their order follows the thesis's aim, "avoiding the creation of small angles between
// polyhedral faces and bisection planes":
// - in a polyhedral input, at an edge with no facet of a curved surface beside it, and at any
//   edge whose wedge exceeds 180 degrees by kFlatEdge or more: the face extensions first (they
//   add no new angle to the cells), then the wedge's bisector, then the quarter and eighth planes;
// - at a nearly flat edge beside a facet of a curved surface (the B-rep route's proxy: a hole
//   faceted every 22.5 degrees), the bisector first. There a face's extension meets the true
//   surface grazing, at half the facet angle: a cut line left the hole's edge at 11 degrees, with
//   a sliver of face between them that the face grid can only fill with thin triangles. The
//   bisector is normal to the true surface. Next come the planes through the edge and a vertex of
//   the region within an eighth of the wedge of the bisector, for when the bisector passes near
//   such a vertex and is rejected (it would leave a short edge; a hole faceted unevenly: the
//   bisector at one facet edge just misses the edge across the hole). Then the quarter planes,
//   the extensions and the eighth planes.
#pragma once
#include <vector>

#include "bisect/edge_wedges.hpp"
#include "bisect/plane_cut.hpp"

namespace bisect {

struct ReflexEdge {
  Index a, b;    // a < b
  Wedge wedge;   // the reflex interior wedge
  bool on_double_face = false;
};

// A reflex edge whose wedge exceeds 180 degrees by less than this is nearly flat (radians).
constexpr double kFlatEdge = 45.0 * 3.14159265358979323846 / 180.0;

// Whether the bisector leads at edge e: nearly flat, and beside a face that `curved_faces` (per
// input face) marks as a facet of a curved surface (empty: never).
bool bisector_first(const PolyhedralModel& m, const ReflexEdge& e, const std::vector<char>& curved_faces);

// region_nodes: the nodes of the edge's region (for the planes through a vertex; may be empty).
std::vector<CutPlane> candidate_planes(const PolyhedralModel& m, const ReflexEdge& e, int max_planes,
                                       const std::vector<Index>& region_nodes = {},
                                       const std::vector<char>& curved_faces = {});

}  // namespace bisect
