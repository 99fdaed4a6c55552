// Exact predicates in two stages.
//
// 1. Filter: the determinant is evaluated in doubles together with its permanent (the same
//    expression with every product replaced by its absolute value). Shewchuk (1997) bounds the
//    rounding error of exactly these expression shapes by c * permanent; when |det| exceeds the
//    bound its sign is certain. His bounds assume no underflow. A product that underflows has an
//    absolute error of up to 2^-1075 instead of a relative one, and later multiplications
//    scale that error by the magnitude of the other factors, which can be large while the
//    permanent is small (1e-200 * 1e-200 next to 1e300). So the bound gets an absolute term,
//    2^-1000 times a bound (at least 1) on the factors that can multiply such an error; the at
//    most a few hundred underflow errors need less than 2^-1060 times it. 2^-1000 rather than
//    anything smaller keeps the term a normal double: on x86, arithmetic on subnormals takes a
//    microcode assist that made the filter ten times slower. Determinants below 2^-1000 (about
//    1e-301) thus always go to the exact stage. Overflow needs no special care: an infinite or NaN
//    determinant or bound fails both strict comparisons.
//
// 2. Exact: the determinant is evaluated exactly in expansion arithmetic (expansion.hpp),
//    starting from the coordinates themselves: each difference is an exact two-component
//    expansion, and every result is compressed, so that expansions stay a few components long
//    whatever their worst case. Expansions are exact only if no product underflows or
//    overflows, so the coordinates are first scaled by a power of two, which multiplies the
//    determinant by a positive factor and keeps its sign (all four determinants are
//    homogeneous in the coordinates). If their magnitudes are spread too widely for any scaling
//    to work (more than about 2^400 apart), or an expansion outgrows its capped capacity, the
//    determinant is evaluated with big integers (bigint.hpp) instead.
//
// No adaptive middle stage: an evaluation from the rounded differences with an error bound
// (Shewchuk's stage B) was tried and decided almost none of the near-degenerate inputs that
// get past the filter (points rounded onto a sphere: 14 of 2946), so it only added its cost.
//
// Every determinant is written once as a template over the number type, so the expansion and
// the big-integer evaluations share the formula.
#include "geom/predicates.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "geom/bigint.hpp"
#include "geom/expansion.hpp"
#include "geom/predicates_detail.hpp"

namespace bisect::geom {

namespace {

using bigint::BigInt;
using expansion::Expansion;

constexpr double kEps = 0x1p-53;  // half an ulp of 1: the unit roundoff of round-to-nearest
// Shewchuk's ccwerrboundA = (3 + 16 eps) eps, o3derrboundA = (7 + 56 eps) eps, iccerrboundA =
// (10 + 96 eps) eps and isperrboundA = (16 + 224 eps) eps, each raised by at least 8 eps^2 to
// pay for the one more rounding that adding the underflow term costs (and chosen to be exact
// doubles).
constexpr double kOrient2dBound = (3.0 + 24.0 * kEps) * kEps;
constexpr double kOrient3dBound = (7.0 + 64.0 * kEps) * kEps;
constexpr double kIncircleBound = (10.0 + 112.0 * kEps) * kEps;
constexpr double kInsphereBound = (16.0 + 256.0 * kEps) * kEps;
// The absolute term for underflowing products (see the top of the file); a normal double.
constexpr double kUnderflow = 0x1p-1000;

// ---- The determinants, generic in the number type -----------------------------------------
//
// Each takes the coordinate differences to the last point, d[i * dim + k] = p_i[k] - p_last[k],
// as Expansion<N> or BigInt, and returns the determinant in that type. kSign converts the
// determinant's sign to the predicate's convention.

// det [a - c; b - c].
struct Orient2dDet {
  static constexpr int kDim = 2, kPoints = 3, kDegree = 2, kSign = 1;
  template <class T>
  auto operator()(const T* d) const {
    return d[0] * d[3] - d[1] * d[2];
  }
};

// det [a - d; b - d; c - d], expanded along z: Shewchuk's orientation, the opposite of ours.
struct Orient3dDet {
  static constexpr int kDim = 3, kPoints = 4, kDegree = 3, kSign = -1;
  template <class T>
  auto operator()(const T* d) const {
    const T *a = d, *b = d + 3, *c = d + 6;
    const auto mbc = b[0] * c[1] - b[1] * c[0];
    const auto mac = a[0] * c[1] - a[1] * c[0];
    const auto mab = a[0] * b[1] - a[1] * b[0];
    return (mbc * a[2] - mac * b[2]) + mab * c[2];
  }
};

// det [a - d, |a - d|^2; b - d, ...; c - d, ...], expanded along the lifted column.
struct IncircleDet {
  static constexpr int kDim = 2, kPoints = 4, kDegree = 4, kSign = 1;
  template <class T>
  auto operator()(const T* d) const {
    const T *a = d, *b = d + 2, *c = d + 4;
    const auto mbc = b[0] * c[1] - b[1] * c[0];
    const auto mac = a[0] * c[1] - a[1] * c[0];
    const auto mab = a[0] * b[1] - a[1] * b[0];
    const auto alift = a[0] * a[0] + a[1] * a[1];
    const auto blift = b[0] * b[0] + b[1] * b[1];
    const auto clift = c[0] * c[0] + c[1] * c[1];
    return (alift * mbc - blift * mac) + clift * mab;
  }
};

// det [p - e, |p - e|^2] over the rows p = a, b, c, d, expanded along the lifted column
// (Shewchuk's insphere, the opposite of ours); t_pqr are the 3x3 minors of the xyz columns.
struct InsphereDet {
  static constexpr int kDim = 3, kPoints = 5, kDegree = 5, kSign = -1;
  template <class T>
  auto operator()(const T* d) const {
    const T *a = d, *b = d + 3, *c = d + 6, *e = d + 9;  // e is the fourth point, d
    auto minor = [](const T* p, const T* q) { return p[0] * q[1] - p[1] * q[0]; };
    const auto mab = minor(a, b), mac = minor(a, c), mad = minor(a, e);
    const auto mbc = minor(b, c), mbd = minor(b, e), mcd = minor(c, e);
    const auto tabc = (mbc * a[2] - mac * b[2]) + mab * c[2];
    const auto tabd = (mbd * a[2] - mad * b[2]) + mab * e[2];
    const auto tacd = (mcd * a[2] - mad * c[2]) + mac * e[2];
    const auto tbcd = (mcd * b[2] - mbd * c[2]) + mbc * e[2];
    auto lift = [](const T* p) { return (p[0] * p[0] + p[1] * p[1]) + p[2] * p[2]; };
    return (lift(e) * tabc - lift(c) * tabd) + (lift(b) * tacd - lift(a) * tbcd);
  }
};

// ---- Preparing the coordinates for the exact stage ---------------------------------------

// The exponent of the lowest set bit of a finite nonzero double: x is an integer multiple of
// 2^result.
int lowest_bit_exponent(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  const std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
  if (biased == 0) return -1074 + __builtin_ctzll(mant);  // subnormal, mant != 0
  return biased - 1075 + (mant != 0 ? __builtin_ctzll(mant) : 52);
}

enum class Route { kExpansion, kBigInt, kZero };

// Decides how the exact stage evaluates a determinant that is a homogeneous polynomial of the
// given degree in the n coordinates v, and scales v in place by a power of two if needed.
//
// Expansions are exact when no product underflows and nothing overflows. Every intermediate
// value is a polynomial of degree <= `degree` in the coordinates, hence an integer multiple of
// 2^(degree * low) when all coordinates are multiples of 2^low (low < 0); the rounding error of
// a product is then a representable double as long as degree * low >= -1074. And with all
// |coordinates| < 2^(top + 1), every value stays below 2^(degree * (top + 2) + 10) (at most 72
// monomials of differences below 2^(top + 2)), which is finite when top <= 1000 / degree - 12.
// When the coordinates violate either condition they are scaled to top = 1000 / degree - 12,
// which gives the lowest bit the most room; if that is still not enough, only big integers
// are exact.
Route prepare(double* v, int n, int degree) {
  double largest = 0.0;
  int low = INT_MAX;
  for (int i = 0; i < n; ++i) {
    if (v[i] == 0.0) continue;
    largest = std::max(largest, std::fabs(v[i]));
    low = std::min(low, lowest_bit_exponent(v[i]));
  }
  if (largest == 0.0) return Route::kZero;  // every point at the origin
  const int top = std::ilogb(largest);
  const int top_limit = 1000 / degree - 12;
  auto fits = [degree](int lowest) { return lowest >= 0 || degree * lowest >= -1074; };
  if (top <= top_limit && fits(low)) return Route::kExpansion;
  const int k = top_limit - top;
  if (!fits(low + k)) return Route::kBigInt;
  for (int i = 0; i < n; ++i) v[i] = std::ldexp(v[i], k);  // exact: no bit falls off
  return Route::kExpansion;
}

bool all_finite(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

// ---- Exact evaluation ------------------------------------------------------------------------

// With expansions, on prepared coordinates: each difference is its exact two-component
// expansion (a single component when the difference is exact, as for nearby points by
// Sterbenz's lemma, and then everything is shorter). Returns the determinant's sign, or 2 when
// an expansion outgrew its capacity (expansion.hpp), which takes coordinates whose bits are
// spread over many hundreds of binary orders. Insphere's frame is the largest, about 80 KB of
// stack (-fstack-usage), all of it fixed-size arrays: no allocation.
template <class Det>
int expansion_stage(const double* v) {
  constexpr int n = Det::kDim * (Det::kPoints - 1);
  const double* last = v + n;
  Expansion<2> d[n];
  for (int i = 0; i < n; ++i) d[i] = expansion::diff(v[i], last[i % Det::kDim]);
  const auto det = Det{}(d);
  return det.overflow ? 2 : det.sign();
}

// The exact stage with big integers: each coordinate is an integer multiple of 2^low, the
// lowest set bit over all of them, so dividing by 2^low (a positive factor) leaves integers.
template <class Det>
int bigint_stage(const double* v) {
  constexpr int n = Det::kDim * Det::kPoints, m = n - Det::kDim;
  int low = INT_MAX;
  for (int i = 0; i < n; ++i)
    if (v[i] != 0.0) low = std::min(low, lowest_bit_exponent(v[i]));
  BigInt x[n], d[m];
  for (int i = 0; i < n; ++i) x[i] = BigInt::from_double(v[i], low);
  for (int i = 0; i < m; ++i) d[i] = x[i] - x[m + i % Det::kDim];
  return Det{}(d).sign();
}

// The exact stage on the coordinates of the points, packed.
template <class Det>
int exact_stage(const double* coords) {
  constexpr int n = Det::kDim * Det::kPoints;
  if (!all_finite(coords, n)) return 0;  // no meaningful sign; documented inputs are finite
  double v[n];
  std::copy(coords, coords + n, v);
  switch (prepare(v, n, Det::kDegree)) {
    case Route::kZero:
      return 0;
    case Route::kBigInt:
      break;
    case Route::kExpansion: {
      const int sign = expansion_stage<Det>(v);
      if (sign != 2) return Det::kSign * sign;
      break;
    }
  }
  return Det::kSign * bigint_stage<Det>(coords);
}

template <class Det>
int bigint_only(const double* coords) {
  return all_finite(coords, Det::kDim * Det::kPoints) ? Det::kSign * bigint_stage<Det>(coords) : 0;
}

}  // namespace

// ---- The exact stage and its big-integer fallback, by name ---------------------------------

namespace detail {

int orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double v[] = {a.x(), a.y(), b.x(), b.y(), c.x(), c.y()};
  return exact_stage<Orient2dDet>(v);
}

int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double v[] = {a.x(), a.y(), a.z(), b.x(), b.y(), b.z(),
                      c.x(), c.y(), c.z(), d.x(), d.y(), d.z()};
  return exact_stage<Orient3dDet>(v);
}

int incircle_exact(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double v[] = {a.x(), a.y(), b.x(), b.y(), c.x(), c.y(), d.x(), d.y()};
  return exact_stage<IncircleDet>(v);
}

int insphere_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) {
  const double v[] = {a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(),
                      c.z(), d.x(), d.y(), d.z(), e.x(), e.y(), e.z()};
  return exact_stage<InsphereDet>(v);
}

int orient2d_bigint(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double v[] = {a.x(), a.y(), b.x(), b.y(), c.x(), c.y()};
  return bigint_only<Orient2dDet>(v);
}

int orient3d_bigint(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double v[] = {a.x(), a.y(), a.z(), b.x(), b.y(), b.z(),
                      c.x(), c.y(), c.z(), d.x(), d.y(), d.z()};
  return bigint_only<Orient3dDet>(v);
}

int incircle_bigint(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double v[] = {a.x(), a.y(), b.x(), b.y(), c.x(), c.y(), d.x(), d.y()};
  return bigint_only<IncircleDet>(v);
}

int insphere_bigint(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) {
  const double v[] = {a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(),
                      c.z(), d.x(), d.y(), d.z(), e.x(), e.y(), e.z()};
  return bigint_only<InsphereDet>(v);
}

}  // namespace detail

// ---- The filters ---------------------------------------------------------------------------
//
// Each returns the certified sign, or 0 when the error bound does not allow a decision (never
// for a determinant that is exactly zero).

namespace {

inline int orient2d_filter(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double acx = a.x() - c.x(), acy = a.y() - c.y();
  const double bcx = b.x() - c.x(), bcy = b.y() - c.y();
  const double left = acx * bcy, right = acy * bcx;
  const double det = left - right;
  // Two products, no later multiplication: the underflow term is a constant.
  const double bound = kOrient2dBound * (std::fabs(left) + std::fabs(right)) + kUnderflow;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return 0;
}

inline int orient3d_filter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double adx = a.x() - d.x(), ady = a.y() - d.y(), adz = a.z() - d.z();
  const double bdx = b.x() - d.x(), bdy = b.y() - d.y(), bdz = b.z() - d.z();
  const double cdx = c.x() - d.x(), cdy = c.y() - d.y(), cdz = c.z() - d.z();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  // Shewchuk's determinant det [a - d; b - d; c - d], the negative of ours.
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double az = std::fabs(adz), bz = std::fabs(bdz), cz = std::fabs(cdz);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * az +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * bz +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * cz;
  // An underflow in an xy product is multiplied by a z difference.
  const double bound = kOrient3dBound * permanent + kUnderflow * std::max({1.0, az, bz, cz});
  if (det > bound) return -1;
  if (-det > bound) return 1;
  return 0;
}

inline int incircle_filter(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double adx = a.x() - d.x(), ady = a.y() - d.y();
  const double bdx = b.x() - d.x(), bdy = b.y() - d.y();
  const double cdx = c.x() - d.x(), cdy = c.y() - d.y();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det =
      alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  // Underflows in the minors are multiplied by a lift, those in a lift by a minor; both are
  // bounded by twice the largest lift.
  const double bound =
      kIncircleBound * permanent + kUnderflow * std::max({1.0, alift, blift, clift});
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return 0;
}

inline int insphere_filter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                           const Vec3& e) {
  const double aex = a.x() - e.x(), aey = a.y() - e.y(), aez = a.z() - e.z();
  const double bex = b.x() - e.x(), bey = b.y() - e.y(), bez = b.z() - e.z();
  const double cex = c.x() - e.x(), cey = c.y() - e.y(), cez = c.z() - e.z();
  const double dex = d.x() - e.x(), dey = d.y() - e.y(), dez = d.z() - e.z();
  // xy minors m_pq = p_x q_y - p_y q_x, keeping both products for the permanent.
  const double abx = aex * bey, aby = aey * bex, mab = abx - aby;
  const double acx = aex * cey, acy = aey * cex, mac = acx - acy;
  const double adx = aex * dey, ady = aey * dex, mad = adx - ady;
  const double bcx = bex * cey, bcy = bey * cex, mbc = bcx - bcy;
  const double bdx = bex * dey, bdy = bey * dex, mbd = bdx - bdy;
  const double cdx = cex * dey, cdy = cey * dex, mcd = cdx - cdy;
  // xyz minors t_pqr and their permanents.
  const double tabc = (mbc * aez - mac * bez) + mab * cez;
  const double tabd = (mbd * aez - mad * bez) + mab * dez;
  const double tacd = (mcd * aez - mad * cez) + mac * dez;
  const double tbcd = (mcd * bez - mbd * cez) + mbc * dez;
  const double pab = std::fabs(abx) + std::fabs(aby), pac = std::fabs(acx) + std::fabs(acy);
  const double pad = std::fabs(adx) + std::fabs(ady), pbc = std::fabs(bcx) + std::fabs(bcy);
  const double pbd = std::fabs(bdx) + std::fabs(bdy), pcd = std::fabs(cdx) + std::fabs(cdy);
  const double az = std::fabs(aez), bz = std::fabs(bez), cz = std::fabs(cez), dz = std::fabs(dez);
  const double pabc = (pbc * az + pac * bz) + pab * cz;
  const double pabd = (pbd * az + pad * bz) + pab * dz;
  const double pacd = (pcd * az + pad * cz) + pac * dz;
  const double pbcd = (pcd * bz + pbd * cz) + pbc * dz;
  const double alift = (aex * aex + aey * aey) + aez * aez;
  const double blift = (bex * bex + bey * bey) + bez * bez;
  const double clift = (cex * cex + cey * cey) + cez * cez;
  const double dlift = (dex * dex + dey * dey) + dez * dez;
  // Shewchuk's determinant, the negative of ours.
  const double det = (dlift * tabc - clift * tabd) + (blift * tacd - alift * tbcd);
  const double permanent = (dlift * pabc + clift * pabd) + (blift * pacd + alift * pbcd);
  // Underflows are multiplied by at most a difference times a lift, or by a 3x3 minor: both
  // below a small multiple of (largest lift)^2 once that is at least 1.
  const double lift = std::max({1.0, alift, blift, clift, dlift});
  const double bound = kInsphereBound * permanent + kUnderflow * (lift * lift);
  if (det > bound) return -1;
  if (-det > bound) return 1;
  return 0;
}

}  // namespace

int detail::orient2d_filter(const Vec2& a, const Vec2& b, const Vec2& c) {
  return geom::orient2d_filter(a, b, c);
}
int detail::orient3d_filter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return geom::orient3d_filter(a, b, c, d);
}
int detail::incircle_filter(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  return geom::incircle_filter(a, b, c, d);
}
int detail::insphere_filter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                            const Vec3& e) {
  return geom::insphere_filter(a, b, c, d, e);
}

// ---- The predicates ------------------------------------------------------------------------

int orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  const int s = orient2d_filter(a, b, c);
  return s != 0 ? s : detail::orient2d_exact(a, b, c);
}

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const int s = orient3d_filter(a, b, c, d);
  return s != 0 ? s : detail::orient3d_exact(a, b, c, d);
}

int incircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int s = incircle_filter(a, b, c, d);
  return s != 0 ? s : detail::incircle_exact(a, b, c, d);
}

int insphere(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e) {
  const int s = insphere_filter(a, b, c, d, e);
  return s != 0 ? s : detail::insphere_exact(a, b, c, d, e);
}

}  // namespace bisect::geom
