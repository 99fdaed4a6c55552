// Where a line meets a triangle, by exact predicates: the one test behind the polyhedral input's
// self-intersection check, a cell boundary's self-crossing check and the boundary recovery's
// pierced tetrahedra, each of which reads the answer its own way.
#pragma once
#include "bisect/types.hpp"
#include "geom/predicates.hpp"

namespace bisect::geom {

// The line through p and q, with p and q not both in the plane of triangle abc, against the
// closed triangle abc: -1 when it passes outside, else how many of the triangle's edge lines it
// passes through where it meets the plane (0 inside, 1 across an edge, 2 through a corner). Says
// nothing of whether the segment pq reaches the plane: the caller's orient3d of p and q does.
inline int line_through_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
  const bool nonneg = s1 >= 0 && s2 >= 0 && s3 >= 0, nonpos = s1 <= 0 && s2 <= 0 && s3 <= 0;
  if (!nonneg && !nonpos) return -1;
  return (s1 == 0) + (s2 == 0) + (s3 == 0);
}

// The segment pq, its ends strictly on either side of abc's plane, against the closed triangle
// abc: -1 when it misses, else as line_through_triangle.
inline int segment_through_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
  if (sp == 0 || sq == 0 || sp == sq) return -1;
  return line_through_triangle(p, q, a, b, c);
}

// Where the segment pq meets abc's plane (approximately; p when pq lies parallel to it).
inline Vec3 plane_meeting(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double dp = n.dot(p - a), dq = n.dot(q - a);
  return dp == dq ? p : Vec3(p + dp / (dp - dq) * (q - p));
}

}  // namespace bisect::geom
