// Cost per call of the exact predicates, against a plain double determinant measured in the
// same run (absolute times vary with the machine and its load; the ratios are what to compare).
//
//   bench_predicates [calls]      (default 2000000 calls per measurement)
//
// Columns, in ns per call:
//   naive        the determinant in doubles, no error bound (not robust): the baseline
//   filtered     the predicate on uniform random points (the filter decides almost always)
//   exact stage  the exact stage alone (detail::*_exact) on the same random points
//   near-degen.  the predicate on points rounded onto a line, plane, circle or sphere, kept
//                only when the filter cannot decide them: every call reaches the exact stage
//   past filter  the share of the random inputs that the filter could not decide
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "geom/predicates.hpp"
#include "geom/predicates_detail.hpp"

namespace {

using bisect::Vec2;
using bisect::Vec3;
namespace geom = bisect::geom;

constexpr int kPool = 4096;  // configurations cycled through: they stay in cache

// Non-robust determinants with the predicates' sign conventions: the peer to compare with.
// noinline, as the predicates are calls into the library too.
__attribute__((noinline)) int naive_orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double det = (a.x() - c.x()) * (b.y() - c.y()) - (a.y() - c.y()) * (b.x() - c.x());
  return (det > 0) - (det < 0);
}

__attribute__((noinline)) int naive_orient3d(const Vec3& a, const Vec3& b, const Vec3& c,
                                             const Vec3& d) {
  const double det = (b - a).dot((c - a).cross(d - a));
  return (det > 0) - (det < 0);
}

__attribute__((noinline)) int naive_incircle(const Vec2& a, const Vec2& b, const Vec2& c,
                                             const Vec2& d) {
  const Vec2 p = a - d, q = b - d, r = c - d;
  const double det = p.squaredNorm() * (q.x() * r.y() - q.y() * r.x()) -
                     q.squaredNorm() * (p.x() * r.y() - p.y() * r.x()) +
                     r.squaredNorm() * (p.x() * q.y() - p.y() * q.x());
  return (det > 0) - (det < 0);
}

__attribute__((noinline)) int naive_insphere(const Vec3& a, const Vec3& b, const Vec3& c,
                                             const Vec3& d, const Vec3& e) {
  const Vec3 p = a - e, q = b - e, r = c - e, s = d - e;
  auto t = [](const Vec3& u, const Vec3& v, const Vec3& w) { return u.dot(v.cross(w)); };
  const double det = -p.squaredNorm() * t(q, r, s) + q.squaredNorm() * t(p, r, s) -
                     r.squaredNorm() * t(p, q, s) + s.squaredNorm() * t(p, q, r);
  return (det < 0) - (det > 0);  // the predicates' convention is the negative
}

using Rng = std::mt19937_64;

template <class P>
P random_point(Rng& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  P p;
  for (int k = 0; k < p.size(); ++k) p[k] = u(rng);
  return p;
}

template <class P>
P random_unit(Rng& rng) {
  std::normal_distribution<double> normal;
  P p;
  do {
    for (int k = 0; k < p.size(); ++k) p[k] = normal(rng);
  } while (p.norm() < 1e-3);
  return p / p.norm();
}

// Nanoseconds per call of f over the pool, best of three runs of `calls` calls (the minimum
// is the least disturbed by other processes).
template <class Pool, class F>
double ns_per_call(const Pool& pool, long calls, F f) {
  double best = 1e300;
  long sink = 0;
  for (int rep = 0; rep < 3; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    for (long i = 0; i < calls; ++i) sink += f(pool[i % pool.size()]);
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() / calls);
  }
  if (sink == 42) std::printf(" ");  // keeps the calls from being optimised away
  return best;
}

struct Row {
  const char* name;
  double naive, filtered, exact, degenerate, past_filter;
};

void print(const std::vector<Row>& rows, long calls) {
  std::printf("bench_predicates: %ld calls per measurement, ns per call (best of 3)\n\n", calls);
  std::printf("%-9s %8s %9s %8s %12s %12s %12s\n", "predicate", "naive", "filtered", "ratio",
              "exact stage", "near-degen.", "past filter");
  for (const Row& r : rows)
    std::printf("%-9s %8.2f %9.2f %7.2fx %12.1f %12.1f %11.3f%%\n", r.name, r.naive, r.filtered,
                r.filtered / r.naive, r.exact, r.degenerate, 100.0 * r.past_filter);
  std::printf("\nratio = filtered / naive. near-degen.: every input reaches the exact stage.\n");
}

// Runs all measurements for one predicate. Gen makes a random configuration, Near a
// near-degenerate one; Naive, Fast, Filter and Exact evaluate a configuration.
template <class Config, class Gen, class Near, class Naive, class Fast, class Filter, class Exact>
Row measure(const char* name, long calls, Gen gen, Near near, Naive naive, Fast fast, Filter filter,
            Exact exact) {
  Rng rng(12345);
  std::vector<Config> random(kPool), degenerate;
  for (auto& c : random) c = gen(rng);
  long undecided = 0;
  for (const auto& c : random) undecided += filter(c) == 0;
  while (degenerate.size() < kPool) {
    const Config c = near(rng);
    if (filter(c) == 0) degenerate.push_back(c);
  }
  Row r{name, 0, 0, 0, 0, double(undecided) / kPool};
  r.naive = ns_per_call(random, calls, naive);
  r.filtered = ns_per_call(random, calls, fast);
  // The exact stage costs far more per call: fewer calls keep the run short.
  r.exact = ns_per_call(random, std::max(calls / 20, 1L), exact);
  r.degenerate = ns_per_call(degenerate, std::max(calls / 20, 1L), fast);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  long calls = 2000000;
  if (argc > 1) calls = std::atol(argv[1]);
  if (calls <= 0) {
    std::fprintf(stderr, "usage: %s [calls > 0]\n", argv[0]);
    return 2;
  }
  std::vector<Row> rows;

  using C2 = std::array<Vec2, 3>;
  rows.push_back(measure<C2>(
      "orient2d", calls,
      [](Rng& g) {
        return C2{random_point<Vec2>(g), random_point<Vec2>(g), random_point<Vec2>(g)};
      },
      [](Rng& g) {  // c on the line ab, rounded
        const Vec2 a = random_point<Vec2>(g), b = random_point<Vec2>(g);
        const double t = std::uniform_real_distribution<double>(-1.0, 2.0)(g);
        return C2{a, b, Vec2(a + t * (b - a))};
      },
      [](const C2& c) { return naive_orient2d(c[0], c[1], c[2]); },
      [](const C2& c) { return geom::orient2d(c[0], c[1], c[2]); },
      [](const C2& c) { return geom::detail::orient2d_filter(c[0], c[1], c[2]); },
      [](const C2& c) { return geom::detail::orient2d_exact(c[0], c[1], c[2]); }));

  using C3 = std::array<Vec3, 4>;
  rows.push_back(measure<C3>(
      "orient3d", calls,
      [](Rng& g) {
        return C3{random_point<Vec3>(g), random_point<Vec3>(g), random_point<Vec3>(g),
                  random_point<Vec3>(g)};
      },
      [](Rng& g) {  // d on the plane abc, rounded
        const Vec3 a = random_point<Vec3>(g), b = random_point<Vec3>(g), c = random_point<Vec3>(g);
        std::uniform_real_distribution<double> u(-1.0, 2.0);
        const double s = u(g), t = u(g);
        return C3{a, b, c, Vec3(a + s * (b - a) + t * (c - a))};
      },
      [](const C3& c) { return naive_orient3d(c[0], c[1], c[2], c[3]); },
      [](const C3& c) { return geom::orient3d(c[0], c[1], c[2], c[3]); },
      [](const C3& c) { return geom::detail::orient3d_filter(c[0], c[1], c[2], c[3]); },
      [](const C3& c) { return geom::detail::orient3d_exact(c[0], c[1], c[2], c[3]); }));

  using C4 = std::array<Vec2, 4>;
  rows.push_back(measure<C4>(
      "incircle", calls,
      [](Rng& g) {
        return C4{random_point<Vec2>(g), random_point<Vec2>(g), random_point<Vec2>(g),
                  random_point<Vec2>(g)};
      },
      [](Rng& g) {  // four points of a circle, rounded
        const Vec2 o = random_point<Vec2>(g);
        const double r = std::uniform_real_distribution<double>(0.1, 1.0)(g);
        C4 c;
        for (auto& p : c) p = o + r * random_unit<Vec2>(g);
        return c;
      },
      [](const C4& c) { return naive_incircle(c[0], c[1], c[2], c[3]); },
      [](const C4& c) { return geom::incircle(c[0], c[1], c[2], c[3]); },
      [](const C4& c) { return geom::detail::incircle_filter(c[0], c[1], c[2], c[3]); },
      [](const C4& c) { return geom::detail::incircle_exact(c[0], c[1], c[2], c[3]); }));

  using C5 = std::array<Vec3, 5>;
  rows.push_back(measure<C5>(
      "insphere", calls,
      [](Rng& g) {
        C5 c;
        for (auto& p : c) p = random_point<Vec3>(g);
        return c;
      },
      [](Rng& g) {  // five points of a sphere, rounded
        const Vec3 o = random_point<Vec3>(g);
        const double r = std::uniform_real_distribution<double>(0.1, 1.0)(g);
        C5 c;
        for (auto& p : c) p = o + r * random_unit<Vec3>(g);
        return c;
      },
      [](const C5& c) { return naive_insphere(c[0], c[1], c[2], c[3], c[4]); },
      [](const C5& c) { return geom::insphere(c[0], c[1], c[2], c[3], c[4]); },
      [](const C5& c) { return geom::detail::insphere_filter(c[0], c[1], c[2], c[3], c[4]); },
      [](const C5& c) { return geom::detail::insphere_exact(c[0], c[1], c[2], c[3], c[4]); }));

  print(rows, calls);
  return 0;
}
