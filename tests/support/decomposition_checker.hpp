// An independent check of a convex decomposition, as the user sees it: the cells file that
// `bisect-mesh --cells-only` wrote, read back, against the input it came from. It shares no code
// with the decomposition (only the readers and the input summary of the foundation), so a bug
// there cannot hide itself here.
#pragma once
#include <string>
#include <vector>

#include "bisect/poly_input.hpp"

namespace bisect::testing {

struct CellCheck {
  std::vector<std::string> problems;  // empty: the decomposition is valid
  std::size_t cells = 0, shared_faces = 0, boundary_faces = 0;
  double max_volume_rel_error = 0;    // over the input's regions
  double max_coverage_rel_error = 0;  // over the input's faces
};

// The input region of each cell, from the "-- cell K of input region R" comments of a cells file.
std::vector<Index> cell_regions_of_file(const std::string& cells_path);

// Checks that (a) every cell is closed, its faces planar and consistently oriented, (b) every
// cell is convex with a positive volume, (c) the cells of each input region add up to its net
// volume (cavities get none), (d) every cell face is shared by exactly two cells or lies on an
// input face (a face two regions share lies on an input face), and (e) the cell faces on each
// input face cover it exactly (areas add up to its net area). Tolerances are relative to the
// bounding box (geometry) and to the region or face (volumes, areas).
CellCheck check_decomposition(const PolyInput& input, const PolyInput& cells, const std::vector<Index>& cell_region,
                              double geom_tol = 1e-9, double measure_tol = 1e-9);

}  // namespace bisect::testing
