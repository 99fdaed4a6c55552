// Reference determinants for the predicates' tests (test_predicates.cpp), in GMP's exact
// rationals (a double converts to mpq_class exactly), written independently of the library's:
// other pivots, generic Laplace expansions. Their sign conventions are checked against the
// geometric meaning in PredicatesReference.MatchesGeometry.
#pragma once
#include <gmpxx.h>

#include "bisect/types.hpp"

namespace bisect::geom::reference {

using Q = mpq_class;

inline Q det3(const Q m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// Laplace expansion along the first row.
inline Q det4(const Q m[4][4]) {
  Q total = 0;
  for (int j = 0; j < 4; ++j) {
    Q minor[3][3];
    for (int r = 1; r < 4; ++r)
      for (int c = 0, k = 0; c < 4; ++c)
        if (c != j) minor[r - 1][k++] = m[r][c];
    const Q term = m[0][j] * det3(minor);
    if (j % 2 == 0)
      total += term;
    else
      total -= term;
  }
  return total;
}

inline int ref_orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  // The definition: the z component of (b - a) x (c - a).
  const Q bx = Q(b.x()) - a.x(), by = Q(b.y()) - a.y();
  const Q cx = Q(c.x()) - a.x(), cy = Q(c.y()) - a.y();
  return sgn(Q(bx * cy - by * cx));
}

inline int ref_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // The definition of predicates.hpp: (b - a) . ((c - a) x (d - a)).
  Q u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = Q(b[k]) - a[k];
    v[k] = Q(c[k]) - a[k];
    w[k] = Q(d[k]) - a[k];
  }
  const Q x = v[1] * w[2] - v[2] * w[1], y = v[2] * w[0] - v[0] * w[2],
          z = v[0] * w[1] - v[1] * w[0];
  return sgn(Q(u[0] * x + u[1] * y + u[2] * z));
}

// The lifted determinant with rows (p - a, |p - a|^2) for p = b, c, d; the 4x4 determinant
// with rows (x, y, x^2 + y^2, 1), positive for d inside a counterclockwise abc, is its negative.
inline int ref_incircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const Vec2* p[3] = {&b, &c, &d};
  Q m[3][3];
  for (int i = 0; i < 3; ++i) {
    m[i][0] = Q((*p[i]).x()) - a.x();
    m[i][1] = Q((*p[i]).y()) - a.y();
    m[i][2] = m[i][0] * m[i][0] + m[i][1] * m[i][1];
  }
  return -sgn(det3(m));
}

// Likewise rows (p - a, |p - a|^2) for p = b, c, d, e; the sign convention of predicates.hpp
// is its negative (checked by ReferenceMatchesGeometry).
inline int ref_insphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) {
  const Vec3* p[4] = {&b, &c, &d, &e};
  Q m[4][4];
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) m[i][k] = Q((*p[i])[k]) - a[k];
    m[i][3] = m[i][0] * m[i][0] + m[i][1] * m[i][1] + m[i][2] * m[i][2];
  }
  return -sgn(det4(m));
}

}  // namespace bisect::geom::reference
