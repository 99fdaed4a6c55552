// The check that a 2D input's polygons do not overlap in part (thesis 4.6.1 has polygons that
// share edges, holes and sub-domains inside a polygon; two regions covering the same area would
// be meshed twice, with overlapping triangles).
#pragma once
#include "bisect/poly_input.hpp"

namespace bisect {

// Throws InputError naming both polygons by the file's 1-based numbers, and a point of the
// overlap, when two polygons' edges cross, when one runs both inside and outside the other, or
// when two have the same outline.
void reject_overlapping_polygons(const Poly2Input& in);

}  // namespace bisect
