// Laplace smoothing (thesis 4.4.2): each free node moves to the average of the nodes joined to
// it. A move is made only if every element around the node stays strictly convex (triangles do
// not turn over, quadrilaterals do not fold) and the smallest angle around it does not get
// smaller (the safeguard the plain method lacks on concave regions). Fixed nodes, and nodes on
// boundary or interface edges, stay. Works on mixed triangle and quadrilateral meshes.
#pragma once
#include <cstdint>

#include "mesh2d/tri_mesh2.hpp"

namespace bisect::mesh2d {

struct SmoothOptions {
  int passes = 5;
};
struct SmoothStats {
  int passes = 0;
  std::int64_t moves = 0, rejected = 0;
};

SmoothStats smooth_laplace(TriMesh2& m, const SmoothOptions& opt = {});

}  // namespace bisect::mesh2d
