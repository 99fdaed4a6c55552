// Exact geometric predicates for double coordinates (thesis A5, made strict): a floating-point
// filter answers when its error bound allows, an exact evaluation in expansion arithmetic
// answers otherwise. Each returns the sign of the determinant: +1, 0 or -1, always exact for
// finite inputs.
#pragma once
#include "bisect/types.hpp"

namespace bisect::geom {

// +1 when a, b, c turn counterclockwise.
int orient2d(const Vec2& a, const Vec2& b, const Vec2& c);
// +1 when (b - a) . ((c - a) x (d - a)) > 0: d lies on the side of plane abc that abc's
// right-hand normal points to (the positive tetrahedron of tet_mesh.hpp). Note: the opposite
// sign of Shewchuk's orient3d.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
// +1 when d lies inside the circle through a, b, c, given orient2d(a, b, c) > 0 (the sign flips
// when abc turns clockwise).
int incircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);
// +1 when e lies inside the sphere through a, b, c, d, given orient3d(a, b, c, d) > 0 (the sign
// flips for a negatively oriented abcd).
int insphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e);

}  // namespace bisect::geom
