// One piece of the B-rep route's surface grids at a time (brep_grids.hpp gathers them): a piece of
// a B-rep face inside one convex cell meshed in the face's (u, v) on the true surface, with the
// facets' planes as the last resort, and a cut face of the decomposition meshed in its plane.
// Each runs on a thread of its own; the result is in local node ids, joined by mesh_brep_faces.
#pragma once
#include <array>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/brep_boundary.hpp"
#include "size/size_field.hpp"

namespace bisect::pipeline {

using CutFacesAt = std::map<std::pair<Index, Index>, std::vector<Index>>;  // model edge (lo, hi) -> the cut faces on it

// A piece to mesh: its B-rep face, its cells, and its model faces, each with the direction to
// take its loops in (so that they run counter-clockwise around the outward normal of cell_out);
// cuts: the decomposition's cut faces by model edge, to tell which grid triangles lie in a cut
// plane (piece_against_proxy.hpp).
struct PieceJob {
  Index face = -1, cell_out = -1, cell_in = -1;
  std::vector<std::pair<Index, bool>> faces;  // model face, reversed
  const CutFacesAt* cuts = nullptr;
};

// One mesh made on a thread: local nodes -> global ones (-1: a new inner node), the new nodes,
// the triangles in local ids.
struct Made {
  std::vector<Index> global;
  std::vector<Vec3> x, p;
  std::vector<PointOn> on;
  std::vector<Vec2> uv;  // per local node
  std::vector<std::array<Index, 3>> tris;
  std::string error;  // the mesher's failure, when it failed
  bool on_facets = false;  // a face piece meshed on its proxy facets' planes (the last resort)
};

// The piece on its B-rep face's true surface (thesis ch. 5): its loops chained from the model
// faces' edges, meshed in the face's parameters at the size field's sizes; where the boundary is
// no simple polygon in any chart, each model face on its proxy facet's plane. Throws
// MeshingError when the piece cannot be meshed (mesh_brep_faces retries such pieces and names
// the face), Cancelled when `cancelled` says so.
Made mesh_piece(const BrepBoundary& bd, const PieceJob& job, const size::SizeField& h, const std::function<bool()>& cancelled);

// Model face fi, a cut face of the decomposition, meshed in its plane with the proxy's positions,
// counter-clockwise around its normal; its inner nodes are moved by the morph later.
Made mesh_cut_face(const BrepBoundary& bd, Index fi, const size::SizeField& h, const std::function<bool()>& cancelled);

}  // namespace bisect::pipeline
