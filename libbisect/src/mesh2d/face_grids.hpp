// Face grids of a polyhedral model (thesis 5.2): every live planar face, holes included, is
// turned into its plane's (e1, e2) frame and meshed by the planar mesher's fill (convex pieces,
// shrinking nodes, recursive bisection, swaps and smoothing). Every model edge is discretised
// once, in 3D, and the same nodes serve every face that uses it, so the grids conform across
// edges and interfaces: on a decomposition's model, the grids of each convex cell's faces close
// up into one triangulated surface, which is what the 3D generator fills.
//
// Spacing: h from the required number of triangles over the total face area (4.6.2), or given;
// each model node wants no more than h nor than its shortest edge, and an edge's nodes grade
// between its ends' spacings (4.5.2, 4.6.5).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "bisect/polyhedral_model.hpp"

namespace bisect::mesh2d {

struct FaceGridOptions {
  std::int64_t elements = 0;  // triangles over all live faces (counted within ~15% by calibration)
  double size = 0;            // the spacing h itself; when > 0 it is used and `elements` ignored
  // per model face (empty: none): a spacing of its own where > 0 and below h (the faces of a
  // thin cell, size/cell_walls.hpp); an edge takes the smallest of its faces', a node of its
  // edges'. Not counted by the `elements` calibration, which is h's.
  std::vector<double> face_size;
  bool optimize = true;       // swaps and smoothing (4.4) on each face, boundary nodes fixed
  bool nodes_only = false;    // place the nodes only, no triangles (to count them cheaply)
  int threads = 1;             // faces meshed at once (0: one per core); the grids are the same for any
  std::function<bool(double)> progress;  // fraction of faces done; return false to cancel
};

struct FaceGrids {
  // model nodes first (the same ids), then edge nodes, then the faces' interior nodes
  std::vector<Vec3> nodes;
  std::vector<double> spacing;  // the spacing each node wants (interior nodes: h)
  std::vector<Index> face_of;   // the model face whose interior holds each node; -1 for model and edge nodes
  // per model face (empty for dead faces): triangles counter-clockwise around the face's normal
  std::vector<std::vector<std::array<Index, 3>>> face_tris;
  // model edge (lo, hi) -> its inner nodes in order from lo to hi
  std::map<std::pair<Index, Index>, std::vector<Index>> edge_nodes;
  double h = 0;
  std::int64_t triangles = 0;
  double min_angle_deg = 0, max_angle_deg = 0;
};

// Throws InputError when neither elements nor size is given, MeshingError naming the face when a
// face cannot be meshed, Cancelled when the progress callback says so.
FaceGrids mesh_faces(const PolyhedralModel& model, const FaceGridOptions& opt);

}  // namespace bisect::mesh2d
