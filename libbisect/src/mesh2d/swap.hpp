// Vertex swapping (thesis 4.4.1): of the two triangulations of a convex quadrilateral keep the
// one whose smallest angle is larger. Each triangle looks at all its neighbours first and swaps
// with the one giving the largest smallest angle (the thesis's neighbour-first variant); later
// passes look only at triangles a swap touched; the passes stop when the grid's smallest angle
// no longer changes (the oscillation stop for round-off). Boundary and interface edges (a
// triangle of another region, or none, on one side) are never swapped.
#pragma once
#include <cstdint>

#include "mesh2d/tri_mesh2.hpp"

namespace bisect::mesh2d {

struct SwapOptions {
  int max_passes = 50;
  bool neighbour_first = true;
};
struct SwapStats {
  int passes = 0;
  std::int64_t swaps = 0;
  bool oscillation_stopped = false;
};

SwapStats swap_edges(TriMesh2& m, const SwapOptions& opt = {});

}  // namespace bisect::mesh2d
