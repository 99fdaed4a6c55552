// How a face piece's grid (brep_grids.hpp) sits against its convex proxy cell, which the cell
// fill may work in (proxy_fill.hpp):
//
// - A grid triangle whose three corners lie on one cut face lies in that cut face's plane (three
//   points of a plane curve span its plane). The cell then holds a pocket with no volume between
//   the triangle and the cut face: a full cylinder cut across at a coarse size (three nodes of the
//   cut circle joined by one triangle: corpus/x_rod.brep), or a cut through a sphere's pole
//   (corpus/x_problemSphere.brep). No point sees such a cell whole, in either geometry. The
//   triangle is flipped with a neighbour, or split at its centre.
// - An inner node's proxy position is the point of the piece's proxy facets at its parameters.
//   Where its parameters lie in none of the facets' triangles (a cone's apex, whose triangle in
//   (u, v) is a quadrilateral with a collapsed side; a B-spline face whose parameters are far
//   from proportional to length over a coarse facet), that point is an extrapolation and may lie
//   outside the cell: then it is the point of the piece's proxy faces nearest the node.
// - A grid edge inside the piece with both ends on one cut face (a "chord") lies in that cut
//   face's plane, since both ends do: the piece touches the cut face along it and the cell is
//   pinched to no thickness there (corpus/wrenchnut.brep's B-spline faces; corpus/x_rod.brep's
//   cylinder at a coarse size). The edge is flipped, or its two triangles are split at a node
//   between them, whichever leaves the larger smallest angle; each change is checked in both the
//   true and the proxy positions, since the cell is filled in either (a flip that keeps its
//   triangles turned on the surface can turn them over on the proxy facet), and none leaves a
//   triangle with under half the smallest angle the two had (a needle on the surface is worse for
//   the user than a chord the cell fill copes with by joining the cell to a neighbour:
//   corpus/x_ring.brep came out with a 0.03 degree surface triangle without that bound).
#pragma once
#include <functional>
#include <utility>
#include <vector>

#include "bisect/parametric_surface.hpp"
#include "bisect/polyhedral_model.hpp"
#include "surface/region_mesher.hpp"

namespace bisect::pipeline {

// rm: a piece's grid; its first `boundary` nodes are the loops' nodes, node_cuts[v] the cut faces
// boundary node v lies on. Mends every triangle with its three corners on one cut face: by the
// flip of one of its edges with the neighbouring triangle (both new triangles turning as the two
// old ones did, neither on one cut face; of those, the flip leaving the larger smallest angle),
// else by a node at its centre in (u, v). Returns the number mended; one that neither mends is
// left for the cell fill to report.
int mend_cut_ears(const ParametricSurface& surf, surface::RegionMesh& rm, const std::vector<std::vector<Index>>& node_cuts,
                  std::size_t boundary);

// The chords' mend (above), after mend_cut_ears. p: every node's proxy position (it grows with
// the nodes the mend adds); proxy_at(uv, x): the proxy position of a new node at those parameters
// and that surface point; off_cut(f, q): the distance of proxy point q from cut face f's plane.
// Returns the number mended; a chord neither mends without a needle is left to the cell fill
// (which joins the cell to a neighbour, or reports it).
int mend_cut_chords(const ParametricSurface& surf, surface::RegionMesh& rm, const std::vector<std::vector<Index>>& node_cuts,
                    std::size_t boundary, std::vector<Vec3>& p, const std::function<Vec3(const Vec2& uv, const Vec3& x)>& proxy_at,
                    const std::function<double(Index f, const Vec3& q)>& off_cut);

// The point of the model faces `faces` (first: model face id) nearest x; *source: the proxy face
// (the model face's source) it lies on.
Vec3 nearest_on_faces(const PolyhedralModel& m, const std::vector<std::pair<Index, bool>>& faces, const Vec3& x, Index* source);

}  // namespace bisect::pipeline
