// The expansion arithmetic under the exact predicates (geom/expansion.hpp): sums and products
// exact against GMP's rationals, expansions well formed (non-overlapping, increasing), and
// overflow flagged. The predicates themselves: test_predicates.cpp.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geom/expansion.hpp"

namespace bisect::geom {
namespace {

using Q = mpq_class;
using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
int uniform_int(Rng& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

template <int N>
Q value_of(const expansion::Expansion<N>& e) {
  Q s = 0;
  for (int i = 0; i < e.n; ++i) s += Q(e.c[i]);
  return s;
}

// Exponent of the lowest set bit of a nonzero double.
int lowest_bit(double x) {
  int e;
  double m = std::frexp(std::fabs(x), &e);  // x = m 2^e, m in [0.5, 1)
  int low = e;
  while (m != std::floor(m)) {
    m *= 2;
    --low;
  }
  return low;
}

// Components nonzero, increasing in magnitude and nonoverlapping: the highest bit of each lies
// below the lowest bit of the next.
template <int N>
bool well_formed(const expansion::Expansion<N>& e) {
  for (int i = 0; i < e.n; ++i) {
    if (e.c[i] == 0.0) return false;
    if (i + 1 < e.n && std::ilogb(e.c[i]) >= lowest_bit(e.c[i + 1])) return false;
  }
  return true;
}

TEST(PredicatesExpansion, ExactAgainstGmp) {
  using namespace expansion;
  Rng rng(808);
  auto x = [&rng]() { return std::ldexp(uniform(rng, -1.0, 1.0), uniform_int(rng, -60, 60)); };
  int checked = 0;
  for (int n = 0; n < 20000; ++n) {
    const double a = x(), b = x(), c = x(), d = x(), e = x();
    const auto p = diff(a, b) * diff(c, d);         // 2 x 2
    const auto q = product(a, e) - diff(d, b) * c;  // 2 - 2 * 1
    const auto r = (p + q) * (p - q * e);           // longer operands
    const Q qa(a), qb(b), qc(c), qd(d), qe(e);
    const Q wp = (qa - qb) * (qc - qd), wq = qa * qe - (qd - qb) * qc;
    ASSERT_EQ(value_of(p), wp);
    ASSERT_EQ(value_of(q), wq);
    ASSERT_EQ(value_of(r), Q((wp + wq) * (wp - wq * qe)));
    ASSERT_TRUE(well_formed(p) && well_formed(q) && well_formed(r));
    ASSERT_EQ(r.sign(), sgn(Q((wp + wq) * (wp - wq * qe))));
    ++checked;
  }
  EXPECT_EQ(checked, 20000);
}

// An operation whose result might not fit the capped capacity flags it, and the flag spreads.
TEST(PredicatesExpansion, OverflowIsFlagged) {
  using namespace expansion;
  Expansion<40> sparse;  // 2^0 + 2^-2 + ... + 2^-78: 40 nonadjacent components
  sparse.n = 0;
  for (int i = 39; i >= 0; --i) sparse.c[sparse.n++] = std::ldexp(1.0, -2 * i);
  ASSERT_TRUE(well_formed(sparse));
  const auto square = sparse * sparse;  // 2 * 40 * 40 > kMaxCapacity
  EXPECT_TRUE(square.overflow);
  EXPECT_TRUE((square + sparse).overflow);
  EXPECT_FALSE((sparse + sparse).overflow);
  EXPECT_EQ(value_of(sparse + sparse), 2 * value_of(sparse));
}

}  // namespace
}  // namespace bisect::geom
