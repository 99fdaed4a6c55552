// Geometry preparation of a planar input (thesis 4.6.1): the regions to mesh, each an outer
// polygon counter-clockwise with its holes clockwise (hole polygons and sub-domains lying
// directly inside it), so that the region is always on the left of its loops; an edge that two
// regions share is an interface and is discretised once for both.
#pragma once
#include <cstdint>
#include <vector>

#include "bisect/poly_input.hpp"

namespace bisect::mesh2d {

struct PlanarRegion {
  Index polygon = -1;                     // the input polygon that bounds it
  std::vector<std::vector<Index>> loops;  // loops[0] outer (counter-clockwise), then holes
  double area = 0;                        // net
  std::vector<Index> loop_polygon = {};   // per loop, the input polygon it comes from (messages)
};

struct PlanarDomain {
  std::vector<Vec2> nodes;
  std::vector<PlanarRegion> regions;
  double area = 0;
  std::int64_t required_elements = 0;
};

PlanarDomain prepare_planar(const Poly2Input& in);

}  // namespace bisect::mesh2d
