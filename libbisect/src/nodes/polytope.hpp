// Convex polytopes: the convex cells of the decomposition as the node placement (7.4) and the
// cell fill see them, and the layers 3D shrinking makes of them by clipping.
#pragma once
#include <vector>

#include "bisect/types.hpp"

namespace bisect::nodes {

// A convex polytope: its corners and its faces, each a loop of corner ids counter-clockwise
// seen from outside, with the outward unit normal and offset (normal . x = offset).
struct Polytope {
  std::vector<Vec3> v;
  std::vector<std::vector<int>> faces;
  std::vector<Vec3> normal;
  std::vector<double> offset;
  double volume() const;
  double area() const;
  Vec3 centroid() const;  // of the solid
  double face_area(std::size_t f) const;
  Vec3 face_centre(std::size_t f) const;  // the mean of its corners
};

// The part of p with normal . x <= offset (scale: the size used for the on-plane tolerance).
Polytope clip(const Polytope& p, const Vec3& normal, double offset, double scale);

}  // namespace bisect::nodes
