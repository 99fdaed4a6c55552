// Measures the tests read off a finished mesh that the library's quality report does not give.
#pragma once
#include <algorithm>
#include <cstddef>

#include "bisect/quality.hpp"
#include "bisect/tet_mesh.hpp"

namespace bisect::test {

// The smallest corner angle (degrees) of the mesh's boundary triangles, at their corner nodes
// (order 1 or 2).
inline double surface_min_angle(const TetMesh& m) {
  double worst = 180;
  for (std::size_t t = 0; t < m.num_tris(); ++t) {
    const Index* v = &m.tris[m.nodes_per_tri() * t];
    worst = std::min(worst, triangle_min_angle_deg(m.nodes[v[0]], m.nodes[v[1]], m.nodes[v[2]]));
  }
  return worst;
}

}  // namespace bisect::test
