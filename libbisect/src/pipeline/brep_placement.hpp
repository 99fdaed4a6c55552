// Stage "Gen. Nodes" of the B-rep route at one size field: the surface grids (brep_grids.hpp),
// the morph of the proxy-made nodes onto the true geometry (brep_morph.hpp), the cells' interior
// nodes (3D shrinking at the base spacing, an octree where the field asks for less). Before any
// tetrahedron: the count calibration predicts the count from these nodes; the cells as the fill
// takes them (brep_cells.hpp) are made only for the placement that is filled.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "bisect/brep_input.hpp"
#include "bisect/polyhedral_model.hpp"
#include "pipeline/brep_cells.hpp"
#include "pipeline/brep_grids.hpp"
#include "pipeline/brep_proxy.hpp"
#include "pipeline/cell_filling.hpp"
#include "size/size_field.hpp"

namespace bisect::pipeline {

struct BrepPlacement {
  std::vector<Vec3> X;            // every node, true positions
  std::vector<Vec3> P;            // and where the decomposition made it, on or in the proxy
  std::vector<char> on_boundary;  // per node: on a face, edge or vertex (fixed from now on)
  BrepGrids grids;
  std::vector<BrepCell> cells;    // per convex cell: its interior nodes, centre and volume
  std::int64_t graded_nodes = 0;
  std::int64_t boundary_nodes() const;
  std::int64_t inside_nodes() const;
};

// progress(fraction) as mesh_brep_faces calls it (the grids are the placement's bulk); false
// throws Cancelled.
BrepPlacement place_brep_nodes(const BrepInput& in, const BrepProxy& proxy, const Decomposition& d, const size::SizeField& h,
                               int threads, const std::function<bool(double)>& progress = {});

}  // namespace bisect::pipeline
