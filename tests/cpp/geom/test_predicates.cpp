// The exact predicates against exact rational arithmetic (GMP's mpq_class: a double converts
// to it exactly). The reference determinants (predicates_reference.hpp) are written
// independently of the library's, and their sign conventions are themselves checked here
// against the geometric meaning (circumcentres computed in rationals). The expansion arithmetic
// underneath: test_expansion.cpp.
//
// Every configuration is checked twice: through the public predicate (filter, then exact
// stage) and through the exact stage alone (detail::*_exact), so that the exact stage is also
// tested on the inputs the filter would have decided.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "geom/predicates.hpp"
#include "geom/predicates_detail.hpp"
#include "predicates_reference.hpp"
#include "sanitizer.hpp"

namespace bisect::geom {
namespace {

using reference::det3;
using reference::Q;
using reference::ref_incircle;
using reference::ref_insphere;
using reference::ref_orient2d;
using reference::ref_orient3d;
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- The four predicates behind one interface ----------------------------------------------

struct Orient2d {
  static constexpr const char* kName = "orient2d";
  static constexpr int kPoints = 3, kDim = 2;
  using P = Vec2;
  static int fast(const P* p) { return orient2d(p[0], p[1], p[2]); }
  static int filter(const P* p) { return detail::orient2d_filter(p[0], p[1], p[2]); }
  static int exact(const P* p) { return detail::orient2d_exact(p[0], p[1], p[2]); }
  static int big(const P* p) { return detail::orient2d_bigint(p[0], p[1], p[2]); }
  static int ref(const P* p) { return ref_orient2d(p[0], p[1], p[2]); }
};
struct Orient3d {
  static constexpr const char* kName = "orient3d";
  static constexpr int kPoints = 4, kDim = 3;
  using P = Vec3;
  static int fast(const P* p) { return orient3d(p[0], p[1], p[2], p[3]); }
  static int filter(const P* p) { return detail::orient3d_filter(p[0], p[1], p[2], p[3]); }
  static int exact(const P* p) { return detail::orient3d_exact(p[0], p[1], p[2], p[3]); }
  static int big(const P* p) { return detail::orient3d_bigint(p[0], p[1], p[2], p[3]); }
  static int ref(const P* p) { return ref_orient3d(p[0], p[1], p[2], p[3]); }
};
struct Incircle {
  static constexpr const char* kName = "incircle";
  static constexpr int kPoints = 4, kDim = 2;
  using P = Vec2;
  static int fast(const P* p) { return incircle(p[0], p[1], p[2], p[3]); }
  static int filter(const P* p) { return detail::incircle_filter(p[0], p[1], p[2], p[3]); }
  static int exact(const P* p) { return detail::incircle_exact(p[0], p[1], p[2], p[3]); }
  static int big(const P* p) { return detail::incircle_bigint(p[0], p[1], p[2], p[3]); }
  static int ref(const P* p) { return ref_incircle(p[0], p[1], p[2], p[3]); }
};
struct Insphere {
  static constexpr const char* kName = "insphere";
  static constexpr int kPoints = 5, kDim = 3;
  using P = Vec3;
  static int fast(const P* p) { return insphere(p[0], p[1], p[2], p[3], p[4]); }
  static int filter(const P* p) { return detail::insphere_filter(p[0], p[1], p[2], p[3], p[4]); }
  static int exact(const P* p) { return detail::insphere_exact(p[0], p[1], p[2], p[3], p[4]); }
  static int big(const P* p) { return detail::insphere_bigint(p[0], p[1], p[2], p[3], p[4]); }
  static int ref(const P* p) { return ref_insphere(p[0], p[1], p[2], p[3], p[4]); }
};

template <class Pred>
using Config = std::array<typename Pred::P, Pred::kPoints>;

// Counts cases and disagreements; prints the first few disagreements in hexadecimal so that
// they can be reproduced.
struct Tally {
  long cases = 0, zeros = 0, undecided = 0, wrong = 0;

  template <class Pred>
  void check(const Config<Pred>& c, bool with_bigint = false) {
    for (const auto& p : c) EXPECT_TRUE(p.allFinite()) << "generator bug";
    const int want = Pred::ref(c.data());
    const int got = Pred::fast(c.data()), got_exact = Pred::exact(c.data());
    const int got_filter = Pred::filter(c.data());
    const int got_big = with_bigint ? Pred::big(c.data()) : want;
    ++cases;
    zeros += want == 0;
    undecided += got_filter == 0;
    const bool filter_ok = got_filter == 0 || got_filter == want;
    if (got == want && got_exact == want && got_big == want && filter_ok) return;
    if (++wrong <= 5) {
      std::printf(
          "%s: reference %d, predicate %d, filter %d, exact stage %d, big integers %d"
          " for\n",
          Pred::kName, want, got, got_filter, got_exact, got_big);
      for (const auto& p : c) {
        for (int k = 0; k < Pred::kDim; ++k) std::printf(" %a", p[k]);
        std::printf("\n");
      }
    }
  }
};

// ---- Input generators ----------------------------------------------------------------------

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
int uniform_int(Rng& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

// x moved by k steps of one ulp.
double nudge(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, kInf);
  for (; k < 0; ++k) x = std::nextafter(x, -kInf);
  return x;
}

template <class P>
P random_point(Rng& rng, double lo = -1.0, double hi = 1.0) {
  P p;
  for (int k = 0; k < p.size(); ++k) p[k] = uniform(rng, lo, hi);
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

// Moves every coordinate of point i by -3..3 ulps, then shuffles the points (the moved point
// takes any role, and both orientations occur).
template <class Pred>
void nudge_and_shuffle(Config<Pred>& c, int i, Rng& rng) {
  for (int k = 0; k < Pred::kDim; ++k) c[i][k] = nudge(c[i][k], uniform_int(rng, -3, 3));
  std::shuffle(c.begin(), c.end(), rng);
}

// A random similarity-like change of scale and position, so the families cover many exponents.
template <class Pred>
void random_frame(Config<Pred>& c, Rng& rng) {
  const double s = std::ldexp(1.0, uniform_int(rng, -30, 30));
  const auto offset = random_point<typename Pred::P>(rng, -100.0, 100.0);
  const bool shift = uniform_int(rng, 0, 1) == 1;
  for (auto& p : c) p = shift ? typename Pred::P(p * s + offset) : typename Pred::P(p * s);
}

// Uniform random points in the unit box.
template <class Pred>
Config<Pred> uniform_config(Rng& rng) {
  Config<Pred> c;
  for (auto& p : c) p = random_point<typename Pred::P>(rng);
  return c;
}

// Points on a random line (2D), plane (3D), circle or sphere, rounded to doubles, one of them
// then moved by a few ulps.
template <class Pred>
Config<Pred> near_degenerate_config(Rng& rng) {
  using P = typename Pred::P;
  Config<Pred> c;
  const int last = Pred::kPoints - 1;
  if constexpr (std::is_same_v<Pred, Orient2d> || std::is_same_v<Pred, Orient3d>) {
    for (int i = 0; i < last; ++i) c[i] = random_point<P>(rng);
    P q = c[0];
    for (int i = 1; i < last; ++i) q += uniform(rng, -1.5, 2.5) * (c[i] - c[0]);
    c[last] = q;
  } else {
    const P centre = random_point<P>(rng);
    const double r = uniform(rng, 0.05, 2.0);
    for (auto& p : c) p = centre + r * random_unit<P>(rng);
  }
  random_frame<Pred>(c, rng);
  nudge_and_shuffle<Pred>(c, uniform_int(rng, 0, last), rng);
  return c;
}

// Integer points on x^2 + y^2 = 25 or 65, or on x^2 + y^2 + z^2 = 9 or 3.
template <class P>
std::vector<std::vector<P>> integer_spheres() {
  std::vector<std::vector<P>> sets;
  if constexpr (P::RowsAtCompileTime == 2) {
    for (int r2 : {25, 65}) {
      std::vector<P> s;
      for (int x = -8; x <= 8; ++x)
        for (int y = -8; y <= 8; ++y)
          if (x * x + y * y == r2) s.emplace_back(x, y);
      sets.push_back(s);
    }
  } else {
    for (int r2 : {9, 3}) {
      std::vector<P> s;
      for (int x = -3; x <= 3; ++x)
        for (int y = -3; y <= 3; ++y)
          for (int z = -3; z <= 3; ++z)
            if (x * x + y * y + z * z == r2) s.emplace_back(x, y, z);
      sets.push_back(s);
    }
  }
  return sets;
}

// Exactly degenerate configurations: distinct integer points of one circle or sphere, or (for
// the orientations) points of an integer line or plane; moved to an exactly representable
// position and scale; sometimes one point is then moved by an ulp or replaced by a point off
// the circle.
template <class Pred>
Config<Pred> exact_config(Rng& rng) {
  using P = typename Pred::P;
  Config<Pred> c;
  if constexpr (std::is_same_v<Pred, Orient2d> || std::is_same_v<Pred, Orient3d>) {
    // Integer combinations of integer vectors: exactly on a line or plane.
    P dirs[2] = {P::Zero(), P::Zero()};
    for (auto& d : dirs)
      for (int k = 0; k < d.size(); ++k) d[k] = uniform_int(rng, -50, 50);
    for (auto& p : c) {
      p = P::Zero();
      for (int i = 0; i < Pred::kDim - 1; ++i) p += double(uniform_int(rng, -20, 20)) * dirs[i];
    }
  } else {
    static const auto sets = integer_spheres<P>();
    const auto& s = sets[uniform_int(rng, 0, 1)];
    std::vector<int> idx(s.size());
    for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = int(i);
    std::shuffle(idx.begin(), idx.end(), rng);
    for (int i = 0; i < Pred::kPoints; ++i) c[i] = s[idx[i]];
    if (uniform_int(rng, 0, 7) == 0) c[0] = sets[1 - (&s - &sets[0])][0] * 1.5;
  }
  const double scale = std::ldexp(1.0, uniform_int(rng, -40, 40));
  P offset;
  for (int k = 0; k < offset.size(); ++k) offset[k] = uniform_int(rng, -(1 << 20), 1 << 20);
  for (auto& p : c) p = (p + offset) * scale;
  const int mode = uniform_int(rng, 0, 2);
  if (mode == 1) {
    auto& x = c[uniform_int(rng, 0, Pred::kPoints - 1)][uniform_int(rng, 0, Pred::kDim - 1)];
    x = nudge(x, uniform_int(rng, 0, 1) ? 1 : -1);
  }
  std::shuffle(c.begin(), c.end(), rng);
  return c;
}

// Points of a small grid, repeated points allowed: many exact zeros of every kind.
template <class Pred>
Config<Pred> grid_config(Rng& rng) {
  Config<Pred> c;
  const int n = Pred::kDim == 2 ? 5 : 2;
  for (auto& p : c)
    for (int k = 0; k < Pred::kDim; ++k) p[k] = uniform_int(rng, 0, n);
  const double scale = std::ldexp(1.0, uniform_int(rng, -40, 40));
  for (auto& p : c) p *= scale;
  return c;
}

// A near-degenerate or exact configuration at an extreme magnitude: multiplied by 2^+-498
// (about 1e150) or 1e150, 1e-150, 1e300, 1e-300, 2^-1000 (products underflow, the filter's
// determinant overflows or underflows).
template <class Pred>
Config<Pred> extreme_config(Rng& rng) {
  Config<Pred> c =
      uniform_int(rng, 0, 1) ? near_degenerate_config<Pred>(rng) : exact_config<Pred>(rng);
  static const double scales[] = {0x1p498, 0x1p-498, 1e150,     1e-150,
                                  1e300,   1e-300,   0x1p-1000, 0x1p900};
  // First bring the largest coordinate to [1, 2) (exactly: a power of two), then scale.
  double largest = 0.0;
  for (const auto& p : c) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  if (largest > 0.0) {
    const double unit = std::ldexp(1.0, -std::ilogb(largest));
    for (auto& p : c) p *= unit;
  }
  const double s = scales[uniform_int(rng, 0, 7)];
  for (auto& p : c) p *= s;
  return c;
}

template <class Pred, class Gen>
long run_family(const char* family, long n, Gen gen, Rng& rng, Tally& total) {
  Tally t;
  for (long i = 0; i < n; ++i) t.check<Pred>(gen(rng));
  std::printf(
      "  %-8s %-16s %7ld cases, %6ld exact zeros, %6ld past the filter, %ld disagreements\n",
      Pred::kName, family, t.cases, t.zeros, t.undecided, t.wrong);
  total.cases += t.cases;
  total.undecided += t.undecided;
  total.zeros += t.zeros;
  total.wrong += t.wrong;
  return t.wrong;
}

// Under AddressSanitizer a fifth of the cases (PredicatesVsGmp took 65 s there): every family and
// the exact stages behind its thousands of zeros still run, which is what ASan checks (the
// expansions' bounds); the ordinary build runs them all.
constexpr long kCaseShare = bisect::test::kUnderSanitizer ? 5 : 1;

// All families for one predicate: at least 250000 configurations (a fifth under ASan).
template <class Pred>
Tally run_all(std::uint64_t seed) {
  Rng rng(seed);
  Tally total;
  run_family<Pred>("uniform", 60000 / kCaseShare, uniform_config<Pred>, rng, total);
  run_family<Pred>("near-degenerate", 100000 / kCaseShare, near_degenerate_config<Pred>, rng, total);
  run_family<Pred>("exact/integer", 50000 / kCaseShare, exact_config<Pred>, rng, total);
  run_family<Pred>("grid", 30000 / kCaseShare, grid_config<Pred>, rng, total);
  run_family<Pred>("huge/tiny", 30000 / kCaseShare, extreme_config<Pred>, rng, total);
  std::printf("  %-8s total %ld cases, %ld disagreements\n", Pred::kName, total.cases, total.wrong);
  return total;
}

// ---- Tests ---------------------------------------------------------------------------------

TEST(PredicatesConventions, Orient2d) {
  const Vec2 a(0, 0), b(1, 0), c(0, 1);
  EXPECT_EQ(orient2d(a, b, c), 1);
  EXPECT_EQ(orient2d(b, a, c), -1);
  EXPECT_EQ(orient2d(a, c, b), -1);
  EXPECT_EQ(orient2d(b, c, a), 1);  // cyclic shifts keep the sign
  EXPECT_EQ(orient2d(a, b, Vec2(2, 0)), 0);
  EXPECT_EQ(orient2d(a, a, c), 0);
  // Collinear after rounding? 0.1, 0.2, 0.3 are not on one line in doubles.
  EXPECT_EQ(orient2d(Vec2(0.1, 0.1), Vec2(0.2, 0.2), Vec2(0.3, 0.3)),
            ref_orient2d(Vec2(0.1, 0.1), Vec2(0.2, 0.2), Vec2(0.3, 0.3)));
}

TEST(PredicatesConventions, Orient3d) {
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  EXPECT_EQ(orient3d(o, x, y, z), 1);  // the positive tetrahedron
  EXPECT_EQ(orient3d(x, o, y, z), -1);
  EXPECT_EQ(orient3d(o, x, z, y), -1);
  EXPECT_EQ(orient3d(o, x, y, -z), -1);  // below the plane oxy
  EXPECT_EQ(orient3d(x, y, z, o), -1);   // an odd permutation of (o, x, y, z)
  EXPECT_EQ(orient3d(o, x, y, Vec3(5, -7, 0)), 0);
  EXPECT_EQ(orient3d(o, x, x, z), 0);
}

TEST(PredicatesConventions, Incircle) {
  const Vec2 a(1, 0), b(0, 1), c(-1, 0);  // counterclockwise on the unit circle
  ASSERT_EQ(orient2d(a, b, c), 1);
  EXPECT_EQ(incircle(a, b, c, Vec2(0, 0)), 1);
  EXPECT_EQ(incircle(a, b, c, Vec2(2, 0)), -1);
  EXPECT_EQ(incircle(a, b, c, Vec2(0, -1)), 0);
  EXPECT_EQ(incircle(b, a, c, Vec2(0, 0)), -1);  // clockwise: the sign flips
  // On the circle of radius 5 through (3, 4), then an ulp outside and inside.
  const Vec2 p(5, 0), q(0, 5), r(-4, -3);
  EXPECT_EQ(incircle(p, q, r, Vec2(3, 4)), 0);
  EXPECT_EQ(incircle(p, q, r, Vec2(3, nudge(4, 1))), -1);
  EXPECT_EQ(incircle(p, q, r, Vec2(3, nudge(4, -1))), 1);
}

TEST(PredicatesConventions, Insphere) {
  // A regular tetrahedron inscribed in the sphere of radius sqrt(3) about the origin.
  Vec3 a(1, 1, 1), b(1, -1, -1), c(-1, 1, -1), d(-1, -1, 1);
  if (orient3d(a, b, c, d) < 0) std::swap(a, b);
  ASSERT_EQ(orient3d(a, b, c, d), 1);
  EXPECT_EQ(insphere(a, b, c, d, Vec3(0, 0, 0)), 1);  // the centre
  EXPECT_EQ(insphere(a, b, c, d, Vec3(3, 3, 3)), -1);
  EXPECT_EQ(insphere(a, b, c, d, Vec3(1, 1, -1)), 0);  // another cube corner: on the sphere
  EXPECT_EQ(insphere(b, a, c, d, Vec3(0, 0, 0)), -1);  // swapped: the sign flips
  EXPECT_EQ(insphere(a, b, d, c, Vec3(3, 3, 3)), 1);
}

// The references' sign conventions follow from the geometry: circumcentres in rationals.
TEST(PredicatesReference, MatchesGeometry) {
  Rng rng(7);
  for (int n = 0; n < 2000; ++n) {
    const Vec2 a = random_point<Vec2>(rng), b = random_point<Vec2>(rng),
               c = random_point<Vec2>(rng), d = random_point<Vec2>(rng);
    // Circumcentre o: 2 (p - a) . o = |p|^2 - |a|^2 for p = b, c (Cramer's rule).
    const Q m00 = 2 * (Q(b.x()) - a.x()), m01 = 2 * (Q(b.y()) - a.y());
    const Q m10 = 2 * (Q(c.x()) - a.x()), m11 = 2 * (Q(c.y()) - a.y());
    auto sq = [](const Vec2& p) -> Q { return Q(p.x()) * p.x() + Q(p.y()) * p.y(); };
    const Q r0 = sq(b) - sq(a), r1 = sq(c) - sq(a);
    const Q det = m00 * m11 - m01 * m10;
    const Q ox = (r0 * m11 - m01 * r1) / det, oy = (m00 * r1 - r0 * m10) / det;
    auto dist2 = [&](const Vec2& p) -> Q {
      const Q dx = Q(p.x()) - ox, dy = Q(p.y()) - oy;
      return Q(dx * dx + dy * dy);
    };
    const int inside = sgn(Q(dist2(a) - dist2(d)));
    ASSERT_EQ(ref_incircle(a, b, c, d), ref_orient2d(a, b, c) * inside);
    ASSERT_EQ(incircle(a, b, c, d), ref_orient2d(a, b, c) * inside);
  }
  for (int n = 0; n < 1000; ++n) {
    Vec3 p[5];
    for (auto& q : p) q = random_point<Vec3>(rng);
    Q m[3][3], r[3];
    auto sq = [](const Vec3& q) -> Q {
      return Q(q.x()) * q.x() + Q(q.y()) * q.y() + Q(q.z()) * q.z();
    };
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) m[i][k] = 2 * (Q(p[i + 1][k]) - p[0][k]);
      r[i] = sq(p[i + 1]) - sq(p[0]);
    }
    const Q det = det3(m);
    Q o[3];
    for (int k = 0; k < 3; ++k) {
      Q mk[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) mk[i][j] = j == k ? r[i] : m[i][j];
      o[k] = det3(mk) / det;
    }
    auto dist2 = [&](const Vec3& q) -> Q {
      Q s = 0;
      for (int k = 0; k < 3; ++k) s += (Q(q[k]) - o[k]) * (Q(q[k]) - o[k]);
      return s;
    };
    const int inside = sgn(Q(dist2(p[0]) - dist2(p[4])));
    const int orient = ref_orient3d(p[0], p[1], p[2], p[3]);
    ASSERT_EQ(ref_insphere(p[0], p[1], p[2], p[3], p[4]), orient * inside);
    ASSERT_EQ(insphere(p[0], p[1], p[2], p[3], p[4]), orient * inside);
  }
}

TEST(PredicatesVsGmp, Orient2d) {
  const Tally t = run_all<Orient2d>(101);
  EXPECT_GE(t.cases, 250000 / kCaseShare);
  EXPECT_GT(t.zeros, 10000 / kCaseShare);
  EXPECT_EQ(t.wrong, 0);
}

TEST(PredicatesVsGmp, Orient3d) {
  const Tally t = run_all<Orient3d>(202);
  EXPECT_GE(t.cases, 250000 / kCaseShare);
  EXPECT_GT(t.zeros, 10000 / kCaseShare);
  EXPECT_EQ(t.wrong, 0);
}

TEST(PredicatesVsGmp, Incircle) {
  const Tally t = run_all<Incircle>(303);
  EXPECT_GE(t.cases, 250000 / kCaseShare);
  EXPECT_GT(t.zeros, 10000 / kCaseShare);
  EXPECT_EQ(t.wrong, 0);
}

TEST(PredicatesVsGmp, Insphere) {
  const Tally t = run_all<Insphere>(404);
  EXPECT_GE(t.cases, 250000 / kCaseShare);
  EXPECT_GT(t.zeros, 10000 / kCaseShare);
  EXPECT_EQ(t.wrong, 0);
}

// Coordinates whose magnitudes span more than the double exponent range can express in one
// product (1e-240 next to 1e240): the exact stage must switch to big integers. Each family is
// exactly degenerate before the nudge, so the tiny terms decide the sign.
TEST(PredicatesVsGmp, MixedMagnitudes) {
  Rng rng(505);
  Tally t2, t3, tc, ts;
  auto maybe_nudge = [&rng](double& x) { x = nudge(x, uniform_int(rng, -2, 2)); };
  auto mantissa = [&rng]() { return uniform(rng, 1.0, 2.0); };
  for (int n = 0; n < 4000; ++n) {
    // b_x c_y == b_y c_x with wildly different exponents: m1 2^e1 * m2 2^e2 == m1 2^e3 * m2 2^e4.
    const int e1 = uniform_int(rng, 300, 1000), e2 = uniform_int(rng, -1020, -300);
    const int e3 = uniform_int(rng, -1000, 1000), e4 = e1 + e2 - e3;
    if (e4 < -1020 || e4 > 1000) continue;
    const double m1 = mantissa(), m2 = mantissa();
    Vec2 b(std::ldexp(m1, e1), std::ldexp(m1, e3)), c(std::ldexp(m2, e4), std::ldexp(m2, e2));
    maybe_nudge(b[uniform_int(rng, 0, 1)]);
    Config<Orient2d> c2 = {Vec2(0, 0), b, c};
    std::shuffle(c2.begin(), c2.end(), rng);
    t2.check<Orient2d>(c2, true);
    Config<Orient3d> c3 = {Vec3(0, 0, 0), Vec3(b.x(), b.y(), 0), Vec3(c.x(), c.y(), 0),
                           Vec3(0, 0, std::ldexp(mantissa(), uniform_int(rng, -1000, 1000)))};
    std::shuffle(c3.begin(), c3.end(), rng);
    t3.check<Orient3d>(c3, true);
  }
  for (int n = 0; n < 4000; ++n) {
    // The circle x^2 + y^2 = (2^2k + 2^-2k) x through the origin holds (2^+-2k, +-1), and the
    // sphere x^2 + y^2 + z^2 = (2^2k + 2^-2k) x also (2^+-2k, 0, +-1); then scaled by 2^j.
    const int k = uniform_int(rng, 150, 250), j = uniform_int(rng, -100, 100);
    const double lo = std::ldexp(1.0, -2 * k + j), hi = std::ldexp(1.0, 2 * k + j),
                 one = std::ldexp(1.0, j);
    std::vector<Vec2> circle = {{0, 0}, {lo, one}, {lo, -one}, {hi, one}, {hi, -one}};
    std::shuffle(circle.begin(), circle.end(), rng);
    Config<Incircle> cc = {circle[0], circle[1], circle[2], circle[3]};
    maybe_nudge(cc[uniform_int(rng, 0, 3)][uniform_int(rng, 0, 1)]);
    tc.check<Incircle>(cc, true);
    std::vector<Vec3> sphere = {{0, 0, 0},     {lo, one, 0},  {lo, -one, 0},
                                {hi, one, 0},  {hi, -one, 0}, {lo, 0, one},
                                {lo, 0, -one}, {hi, 0, one},  {hi, 0, -one}};
    std::shuffle(sphere.begin(), sphere.end(), rng);
    Config<Insphere> cs = {sphere[0], sphere[1], sphere[2], sphere[3], sphere[4]};
    maybe_nudge(cs[uniform_int(rng, 0, 4)][uniform_int(rng, 0, 2)]);
    const int axis = uniform_int(rng, 0, 2);  // the circle's axis need not be x
    for (auto& p : cs) std::swap(p[0], p[axis]);
    ts.check<Insphere>(cs, true);
  }
  for (const Tally* t : {&t2, &t3, &tc, &ts}) {
    EXPECT_GT(t->cases, 1000);
    EXPECT_GT(t->zeros, 100);
    EXPECT_EQ(t->wrong, 0);
  }
  std::printf("  mixed magnitudes: %ld + %ld + %ld + %ld cases, %ld disagreements\n", t2.cases,
              t3.cases, tc.cases, ts.cases, t2.wrong + t3.wrong + tc.wrong + ts.wrong);
}

// Coordinates with independent random exponents over the whole double range (subnormals
// included): products underflow and overflow in the filter, and the exact stage scales or
// switches to big integers.
TEST(PredicatesVsGmp, WildExponents) {
  Rng rng(707);
  auto wild = [&rng]() {
    const int e = uniform_int(rng, -1080, 1000);
    const double x = std::ldexp(uniform(rng, 1.0, 2.0), e);
    return uniform_int(rng, 0, 9) == 0 ? 0.0 : (uniform_int(rng, 0, 1) ? x : -x);
  };
  Tally t;
  for (int n = 0; n < 3000; ++n) {
    Config<Orient2d> c2;
    Config<Incircle> cc;
    Config<Orient3d> c3;
    Config<Insphere> cs;
    for (auto& p : c2) p = Vec2(wild(), wild());
    for (auto& p : cc) p = Vec2(wild(), wild());
    for (auto& p : c3) p = Vec3(wild(), wild(), wild());
    for (auto& p : cs) p = Vec3(wild(), wild(), wild());
    t.check<Orient2d>(c2, true);
    t.check<Orient3d>(c3, true);
    t.check<Incircle>(cc, true);
    t.check<Insphere>(cs, true);
  }
  EXPECT_EQ(t.wrong, 0);
}

// A configuration where products underflow: Shewchuk's bound alone (relative to the
// permanent) would accept the wrong sign, because the underflowed minor is multiplied by 2^900.
TEST(PredicatesFilter, UnderflowDoesNotFoolTheFilter) {
  const double u = 0x1p-537;
  const Vec3 d(0, 0, 0), a(1, 0, 0x1p900);
  // b_x c_y = 1.6875 * 2^-1074 and b_y c_x = 1.5625 * 2^-1074 both round to 2^-1073, so the
  // minor evaluates to 0 instead of 2^-1077, which times 2^900 outweighs the other term.
  const Vec3 b(1.125 * u, 1.25 * u, 0), c(1.25 * u, 1.5 * u, -0x1p358);
  const double adz = a.z() - d.z(), cdz = c.z() - d.z();
  const double naive =
      adz * (b.x() * c.y() - b.y() * c.x()) + cdz * (a.x() * b.y() - b.x() * a.y());
  const int want = ref_orient3d(a, b, c, d);
  ASSERT_EQ(want, -1);
  EXPECT_EQ(naive < 0 ? 1 : -1, -want) << "the case no longer tests underflow";
  EXPECT_EQ(orient3d(a, b, c, d), want);
  EXPECT_EQ(orient3d(b, a, c, d), -want);
}

// The big-integer evaluation on its own, on ordinary inputs (it is otherwise reached only by
// the mixed-magnitude cases above).
TEST(PredicatesStages, BigIntegersAlone) {
  Rng rng(606);
  Tally t;
  for (int n = 0; n < 3000; ++n) {
    t.check<Orient2d>(n % 2 ? uniform_config<Orient2d>(rng) : exact_config<Orient2d>(rng), true);
    t.check<Orient3d>(n % 2 ? uniform_config<Orient3d>(rng) : exact_config<Orient3d>(rng), true);
    t.check<Incircle>(n % 2 ? near_degenerate_config<Incircle>(rng) : exact_config<Incircle>(rng),
                      true);
    t.check<Insphere>(n % 2 ? near_degenerate_config<Insphere>(rng) : exact_config<Insphere>(rng),
                      true);
  }
  EXPECT_EQ(t.wrong, 0);
}

// Inputs with no meaningful sign still return, without crashing or looping.
TEST(PredicatesStages, NonFiniteInputsReturn) {
  const Vec2 a(0, 0), b(1, 0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const int s = orient2d(a, b, Vec2(nan, 1));
  EXPECT_TRUE(s >= -1 && s <= 1);
  const int t =
      insphere(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(kInf, 0, 0));
  EXPECT_TRUE(t >= -1 && t <= 1);
}

}  // namespace
}  // namespace bisect::geom
