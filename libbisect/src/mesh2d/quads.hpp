// Quadrilaterals by the walking method of thesis 4.7.2: pairs of triangles across an edge become
// a quadrilateral when it is convex with no angle under the limit; from each quadrilateral made,
// the walk goes on to the triangles beyond its sides (always taking the best partner), and when
// it stops, the remaining triangles are searched for a new start. Triangles of two regions are
// never paired. Afterwards the mixed mesh is smoothed.
#pragma once
#include <cstdint>

#include "mesh2d/tri_mesh2.hpp"

namespace bisect::mesh2d {

struct QuadOptions {
  double min_angle_deg = 20;
  int smooth_passes = 5;
};
struct QuadStats {
  std::int64_t quads = 0, triangles_left = 0;
  double min_angle_deg = 0;  // over the whole mixed mesh afterwards
};

QuadStats make_quads(TriMesh2& m, const QuadOptions& opt = {});

}  // namespace bisect::mesh2d
