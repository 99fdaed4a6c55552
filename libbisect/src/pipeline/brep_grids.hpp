// The surface grids of the B-rep route (thesis ch. 5 on the true surfaces, 5.2 for the cuts):
//
// - Face pieces: the part of one B-rep face inside one convex cell (and, for an interface, the
//   same cell on the other side) is meshed in the face's (u, v) parameters on the true surface
//   (surface/region_mesher.hpp), its boundary the edges discretised once (brep_boundary.hpp):
//   pieces of B-rep edges and the cut lines where the cells' cut faces meet the face. The proxy's
//   own facet edges inside a piece leave no trace. Every node lies on its face, edge or vertex.
// - Cut faces: each planar cut face of the decomposition, meshed in its plane in the proxy's
//   geometry; its nodes on the boundary are already where they belong, its inner nodes are moved
//   by the morph (brep_morph.hpp) with the cells' interior nodes.
//
// So the decomposition's cuts meet the true surfaces only along grid edges: the surface grid is
// made with the cut lines in it, never cut afterwards.
#pragma once
#include <array>
#include <functional>
#include <vector>

#include "bisect/polyhedral_model.hpp"
#include "pipeline/brep_boundary.hpp"

namespace bisect::pipeline {

// A piece of B-rep face `face` between cell `cell_out` (for which its triangles' normals point
// outward) and `cell_in` (-1 on the outer boundary).
struct FacePiece {
  Index face = -1;
  Index cell_out = -1, cell_in = -1;
  std::vector<std::array<Index, 3>> tris;    // node ids of BrepGrids
  std::vector<std::array<Vec2, 3>> tri_uv;   // each corner's (u, v) in this piece's chart (a node on
                                             // a seam has one per side; the tet10 mid-nodes use them)
};

struct BrepGrids {
  BoundaryNodes nodes;   // the edges' nodes (BrepBoundary::nodes), then the pieces' and cut faces' inner nodes
  std::vector<FacePiece> pieces;
  // per model face that is a cut face (source < 0): triangles counter-clockwise around its normal
  std::vector<std::vector<std::array<Index, 3>>> cut_tris;
  double min_angle_deg = 180;  // over the face pieces' triangles, in 3D
  std::int64_t facet_pieces = 0;  // pieces meshed on their proxy facets' planes (mesh_piece's last resort)
};

// Meshes every face piece and cut face of the decomposition at the sizes of h, on `threads`
// threads (the grids are the same for every count). Throws MeshingError naming the B-rep face
// (FreeCAD's Face<k>) when a piece cannot be meshed.
// progress(fraction of the faces done) is called on this thread, at least every 50 ms while a face
// is meshed; false throws Cancelled.
BrepGrids mesh_brep_faces(BrepBoundary& boundary, const Decomposition& d, const size::SizeField& h, int threads,
                          const std::function<bool(double)>& progress = {});

}  // namespace bisect::pipeline
