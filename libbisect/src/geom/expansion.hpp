// Floating-point expansion arithmetic (Priest 1991; Shewchuk 1997, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates"): an exact real number is
// held as a sum of doubles ("components") that are nonoverlapping and sorted by increasing
// magnitude. Sums and products of such expansions are computed exactly with error-free
// transformations, so the sign of any polynomial in double inputs can be decided exactly.
//
// Internal to libbisect (the predicates, later the exact constructions). Preconditions, which
// the callers establish by scaling their inputs by a power of two:
//  - IEEE-754 binary64 with round-to-nearest-even and no extended precision (x86-64 SSE2);
//    the build passes -ffp-contract=off so that a*b+c is never fused behind our back;
//  - no overflow anywhere;
//  - no product underflows below the subnormal range: two_product is exact only when the
//    rounding error of a*b is representable, i.e. when every value involved is an integer
//    multiple of 2^-1074 after the multiplication (see predicates.cpp for how it is ensured).
// Zero components are dropped ("zero elimination"), so the zero expansion has length 0 and the
// sign of an expansion is the sign of its last (largest) component.
//
// Two layers: functions on raw component arrays (the caller provides room for the worst-case
// length), and Expansion<N>, a stack value with operators that compress their results and cap
// their capacity at kMaxCapacity, flagging results that might not fit.
#pragma once
#include <cmath>

namespace bisect::geom::expansion {

// x = fl(a + b) and y = a + b - x exactly, for any a, b (Knuth's branch-free two-sum).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

// As two_sum, but only valid when |a| >= |b| (or a == 0): three operations instead of six.
inline void fast_two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  y = b - (x - a);
}

// x = fl(a - b) and y = a - b - x exactly.
inline void two_diff(double a, double b, double& x, double& y) {
  x = a - b;
  const double bv = a - x;
  const double av = x + bv;
  y = (a - av) + (bv - b);
}

// x = fl(a * b) and y = a * b - x exactly (given the underflow precondition above). The fused
// multiply-add computes the rounding error of the product exactly and, unlike Dekker's
// splitting, cannot overflow for large |a|, |b|.
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

inline int sign(int n, const double* e) { return n == 0 ? 0 : (e[n - 1] > 0.0) - (e[n - 1] < 0.0); }

// An approximation of the value (the largest component dominates).
inline double estimate(int n, const double* e) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += e[i];
  return s;
}

// h = e + fsign * f (fsign is +1 or -1, which negates exactly); returns the length of h.
// h needs room for elen + flen components and must not alias e or f. This is Shewchuk's
// FAST-EXPANSION-SUM with zero elimination: merge by magnitude, then one pass of two-sums. It
// is exact, and its output strongly nonoverlapping, for strongly nonoverlapping inputs under
// round-to-even, which holds for everything built from the routines of this header.
inline int sum(int elen, const double* e, int flen, const double* f, double* h,
               double fsign = 1.0) {
  int i = 0, j = 0, n = 0;
  // Next component of the merge, in nondecreasing magnitude order.
  auto next = [&]() -> double {
    if (i < elen && (j >= flen || std::fabs(e[i]) < std::fabs(f[j]))) return e[i++];
    return fsign * f[j++];
  };
  const int m = elen + flen;
  if (m == 0) return 0;
  double q = next();
  if (m == 1) {
    if (q != 0.0) h[n++] = q;
    return n;
  }
  double x, y;
  fast_two_sum(next(), q, x, y);  // the second merged component is the larger one
  if (y != 0.0) h[n++] = y;
  q = x;
  for (int k = 2; k < m; ++k) {
    two_sum(q, next(), x, y);
    if (y != 0.0) h[n++] = y;
    q = x;
  }
  if (q != 0.0) h[n++] = q;
  return n;
}

// h = b * e; returns the length of h. h needs room for 2 * elen components and must not alias
// e. Shewchuk's SCALE-EXPANSION with zero elimination.
inline int scale(int elen, const double* e, double b, double* h) {
  if (elen == 0 || b == 0.0) return 0;
  int n = 0;
  double q, y;
  two_product(e[0], b, q, y);
  if (y != 0.0) h[n++] = y;
  for (int i = 1; i < elen; ++i) {
    double p, pt, s;
    two_product(e[i], b, p, pt);
    two_sum(q, pt, s, y);
    if (y != 0.0) h[n++] = y;
    fast_two_sum(p, s, q, y);  // |p| >= |s| is part of the theorem
    if (y != 0.0) h[n++] = y;
  }
  if (q != 0.0) h[n++] = q;
  return n;
}

// Rewrites e[0..n) in place as an equal expansion that is as short as Shewchuk's COMPRESS makes
// it (nonadjacent, its largest component within an ulp of the value); returns the new length.
// The exact operations above never merge components, so without this an expansion keeps
// every rounding error it ever had: a product of two expansions of a few hundred components
// each costs their product in two-products, while the value itself, spanning a few hundred
// bits, fits in a handful of components.
inline int compress(int n, double* e) {
  if (n <= 1) return n;
  // Top-down: sums from the largest component, keeping the parts that no longer fit.
  int bottom = n - 1;
  double q = e[n - 1];
  for (int i = n - 2; i >= 0; --i) {
    double x, y;
    fast_two_sum(q, e[i], x, y);
    if (y != 0.0) {
      e[bottom--] = x;
      q = y;
    } else {
      q = x;
    }
  }
  // Bottom-up over what the first pass kept (e[bottom] holds q).
  int top = 0;
  for (int i = bottom + 1; i < n; ++i) {
    double x, y;
    fast_two_sum(e[i], q, x, y);
    if (y != 0.0) e[top++] = y;
    q = x;
  }
  if (q != 0.0) e[top++] = q;
  return top;
}

// The largest capacity of an Expansion. Worst-case lengths grow fast (2 m n for a product), but
// compressed expansions stay short: a value spanning b bits needs at most about b / 53
// components when its bits are dense, b / 2 in the worst case. So capacities are capped, an
// operation whose inputs might not fit the cap flags its result as overflowed (checked
// exactly, from the actual lengths), and callers fall back to something else (the predicates:
// big integers). The cap keeps stack frames to tens of kilobytes.
inline constexpr int kMaxCapacity = 1024;
constexpr int capped(int n) { return n < kMaxCapacity ? n : kMaxCapacity; }

// An expansion with a fixed capacity, so that it lives on the stack (no allocation on the
// exact path). Components are left uninitialised. Arithmetic results are compressed.
template <int N>
struct Expansion {
  static_assert(N >= 1 && N <= kMaxCapacity, "capacity out of range");
  static constexpr int capacity = N;
  double c[N];
  int n = 0;
  bool overflow = false;  // the value was lost: a result did not fit its capacity

  // Valid only when !overflow.
  int sign() const { return expansion::sign(n, c); }
  double estimate() const { return expansion::estimate(n, c); }
  void compress() { n = expansion::compress(n, c); }
};

inline Expansion<1> from_double(double a) {
  Expansion<1> r;
  if (a != 0.0) r.c[r.n++] = a;
  return r;
}

// The exact a - b as an expansion of at most two components.
inline Expansion<2> diff(double a, double b) {
  Expansion<2> r;
  double x, y;
  two_diff(a, b, x, y);
  if (y != 0.0) r.c[r.n++] = y;
  if (x != 0.0) r.c[r.n++] = x;
  return r;
}

// The exact a * b as an expansion of at most two components.
inline Expansion<2> product(double a, double b) {
  Expansion<2> r;
  double x, y;
  two_product(a, b, x, y);
  if (y != 0.0) r.c[r.n++] = y;
  if (x != 0.0) r.c[r.n++] = x;
  return r;
}

template <int A, int B>
Expansion<capped(A + B)> operator+(const Expansion<A>& e, const Expansion<B>& f) {
  Expansion<capped(A + B)> h;
  if (e.overflow || f.overflow || e.n + f.n > h.capacity) {
    h.overflow = true;
    return h;
  }
  h.n = sum(e.n, e.c, f.n, f.c, h.c);
  if (h.n > 2) h.compress();
  return h;
}

template <int A, int B>
Expansion<capped(A + B)> operator-(const Expansion<A>& e, const Expansion<B>& f) {
  Expansion<capped(A + B)> h;
  if (e.overflow || f.overflow || e.n + f.n > h.capacity) {
    h.overflow = true;
    return h;
  }
  h.n = sum(e.n, e.c, f.n, f.c, h.c, -1.0);
  if (h.n > 2) h.compress();
  return h;
}

template <int A>
Expansion<capped(2 * A)> operator*(const Expansion<A>& e, double b) {
  Expansion<capped(2 * A)> h;
  if (e.overflow || 2 * e.n > h.capacity) {
    h.overflow = true;
    return h;
  }
  h.n = scale(e.n, e.c, b, h.c);
  if (h.n > 2) h.compress();
  return h;
}

// e * f as the sum over the components of f of the scaled expansions e * f_k (the shorter
// expansion is the one iterated over). The sum is accumulated alternately in h and a scratch
// buffer, which avoids copying on every step.
template <int A, int B>
Expansion<capped(2 * A * B)> operator*(const Expansion<A>& e, const Expansion<B>& f) {
  constexpr int kCap = capped(2 * A * B);
  Expansion<kCap> h;
  if (e.overflow || f.overflow || 2 * e.n * f.n > kCap) {
    h.overflow = true;
    return h;
  }
  // Iterate over the shorter one: fewer, longer partial products sum faster.
  const bool swap = f.n > e.n;
  const int ln = swap ? f.n : e.n, sn = swap ? e.n : f.n;
  const double* lc = swap ? f.c : e.c;
  const double* sc = swap ? e.c : f.c;
  double scratch[kCap];
  double part[capped(2 * (A > B ? A : B))];
  double* acc = h.c;
  double* other = scratch;
  int n = 0;
  for (int k = 0; k < sn; ++k) {
    const int pn = scale(ln, lc, sc[k], part);
    n = sum(n, acc, pn, part, other);
    double* t = acc;
    acc = other;
    other = t;
  }
  if (acc != h.c)
    for (int i = 0; i < n; ++i) h.c[i] = acc[i];
  h.n = n;
  if (h.n > 2) h.compress();
  return h;
}

}  // namespace bisect::geom::expansion
