// A planar triangle (or mixed triangle/quadrilateral) mesh as flat arrays: what the planar mesher
// (thesis ch. 4) builds and what the optimisation passes (swaps 4.4.1, smoothing 4.4.2, quads
// 4.7.2) change in place. Triangles are counter-clockwise (positive orient2d).
#pragma once
#include <array>
#include <vector>

#include "bisect/types.hpp"

namespace bisect::mesh2d {

struct TriMesh2 {
  std::vector<Vec2> nodes;
  // true for nodes that must not move or disappear: boundary, interface and hole nodes
  std::vector<char> fixed;
  std::vector<std::array<Index, 3>> tris;  // counter-clockwise
  std::vector<Index> tri_region;           // region (outer polygon of the input) per triangle
  // quadrilaterals made by the walking method (4.7.2), counter-clockwise; empty unless asked for
  std::vector<std::array<Index, 4>> quads;
  std::vector<Index> quad_region;
};

}  // namespace bisect::mesh2d
