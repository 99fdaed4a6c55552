// Candidate bisection planes through a reflex edge (thesis 6.4.1): planes in the inner wedge,
// between the extensions of the two faces at the edge, at most seven and at least ten degrees
// apart, in a fixed order: the face extensions first (they add no new angle to the cells), then
// the wedge's bisector, then the quarter and eighth planes.
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

std::vector<CutPlane> candidate_planes(const PolyhedralModel& m, const ReflexEdge& e, int max_planes);

}  // namespace bisect
