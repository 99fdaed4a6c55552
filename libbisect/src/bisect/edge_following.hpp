// Edge-following bisection (thesis 7.3.3) and contour polyhedral splitting (7.3.4).
//
// The section polygon of the plane is walked along the region's own edges: every point where the
// plane crosses an edge moves to the end of that edge nearer the plane, or to the edge's middle
// (an optional mid-node, Fig. 7.3.16) when the end would tilt the walk more than 45 degrees out
// of the plane and the middle tilts it less. The walked loop is projected onto the plane,
// triangulated there, and the triangles become the interface. Before anything changes, the
// bandwidth test rejects the walk when a node not joined to the loop lies inside the projected
// loop between the planes P_l and P_u (the loop's distances from the plane widened by psi = the
// relative distance times the mean edge length), and a triangle meeting the boundary at an acute
// angle rejects it too. Contour splitting walks every loop of the section (all polygons, with
// their holes) and triangulates them as a group.
#pragma once
#include "bisect/plane_cut.hpp"

namespace bisect {

CutOutcome edge_following_cut(PolyhedralModel& m, Index r, const CutPlane& plane, Index ea, Index eb, bool contour,
                              const DecomposeOptions& opt, const RegionSnapshot* snap = nullptr);

}  // namespace bisect
