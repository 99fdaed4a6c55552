// Self-intersection of a polyhedral input (thesis 6.12: inputs that self-intersect are rejected).
// Faces are triangulated in their planes; triangles of different faces whose boxes meet (found
// through a uniform grid) are tested with the exact orient3d / orient2d predicates, so touching
// and crossing are told apart exactly on the input coordinates. Faces that share nodes may meet
// there and only there.
#pragma once
#include <string>
#include <vector>

#include "bisect/poly_input.hpp"

namespace bisect {

struct FaceIntersection {
  Index face_a = -1, face_b = -1;  // input face numbers, 0-based (holes count as their face)
  Vec3 point = Vec3::Zero();       // where they meet (approximately)
  std::string kind;                // "crossing", "touching" or "coplanar_overlap"
};

std::vector<FaceIntersection> find_surface_intersections(const PolyInput& in, std::size_t max_reports = 10);

// InputError "<source>: faces 3 and 17 intersect at (x, y, z) (crossing)", with the count of
// further pairs, when the input intersects itself.
void reject_surface_intersections(const PolyInput& in);

}  // namespace bisect
