// Stage "Gen. Nodes" of the thesis's tables for polyhedral inputs: face grids on every face of
// every convex cell (5.2, shared across cells and interfaces) and interior nodes by 3D convex
// shrinking (7.4), optionally graded from the boundary's fine spacing. The nodes, not yet the
// tetrahedra.
#pragma once
#include <cstdint>
#include <vector>

#include "bisect/polyhedral_model.hpp"
#include "mesh2d/face_grids.hpp"
#include "nodes/polytope.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::pipeline {

// The nodes of one placement, then the tetrahedra the cell fill makes of them.
struct Built {
  std::int64_t helper_nodes = 0, helpers_removed = 0, skipped_nodes = 0, flips = 0, graded_nodes = 0;
  std::int64_t refilled_cells = 0;
  std::vector<Vec3> X;
  std::vector<tet::Tet> tets;
  std::vector<Index> region;
  std::size_t boundary_nodes = 0;  // face-grid nodes: fixed
  mesh2d::FaceGrids grids;
  std::vector<nodes::Polytope> polys;        // per cell
  std::vector<std::vector<Index>> interior;  // per cell: its interior nodes
};

// The cell as a polytope: its faces' outer loops, turned to run counter-clockwise seen from
// outside, with outward planes.
nodes::Polytope cell_polytope(const PolyhedralModel& m, const ConvexCell& c);

// Face grids and interior nodes at spacing np; a cell whose cap (per cell, 0 for none: the
// walls', size/cell_walls.hpp) is below np at its cap, its faces' grids too. `count_only`: the
// faces' nodes without their triangles, enough to count them. Adds its time to *gen_nodes.
Built place_nodes(const Decomposition& d, double np, const std::vector<double>& cap, int threads, double grading, double* gen_nodes,
                  bool count_only = false);

// The nodes that tetrahedra will use, on the mesh's boundary and interfaces (the input faces)
// and elsewhere (inside the cells and on the cut faces, which the mesh does not keep as faces).
// Model nodes off every live face (left by the cuts) do not count.
enum NodeKind : char { kUnused = 0, kInside = 1, kOnInputFace = 2 };
std::vector<char> node_kinds(const PolyhedralModel& m, const Built& b);

}  // namespace bisect::pipeline
