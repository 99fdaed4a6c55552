// The stages of the exact predicates of predicates.hpp, exposed for the tests (each stage is
// checked on its own against rational arithmetic, including on inputs the filter would decide)
// and for the benchmark (the cost of each stage). Not for other callers: use the
// predicates of predicates.hpp, which run the floating-point filter first.
#pragma once
#include "bisect/types.hpp"

namespace bisect::geom::detail {

// Filter alone: the sign when the floating-point evaluation certifies it, 0 when it cannot
// (in particular whenever the determinant is exactly zero).
int orient2d_filter(const Vec2& a, const Vec2& b, const Vec2& c);
int orient3d_filter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
int incircle_filter(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);
int insphere_filter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e);

// Exact stage: expansion arithmetic on the coordinates, scaled by a power of two when their
// magnitudes need it, or big integers when no scaling can keep the expansions exact. Same
// results and sign conventions as the public predicates.
int orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c);
int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
int incircle_exact(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);
int insphere_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e);

// The big-integer evaluation alone (the last resort of the exact stage).
int orient2d_bigint(const Vec2& a, const Vec2& b, const Vec2& c);
int orient3d_bigint(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
int incircle_bigint(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);
int insphere_bigint(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e);

}  // namespace bisect::geom::detail
