// Makes a cached B-spline evaluation independent of what the cache held before.
//
// OCCT's B-spline caches (BSplCLib_CacheParams) keep the polynomial of one knot span. A
// parameter a few ulps below a knot is still "in" the cached lower span (IsCacheValid tests
// u - start < length), while a fresh lookup (BSplCLib::LocateParameter) rounds it up into the
// next span: the two polynomials agree only to round-off, so the value would depend on which
// evaluation came before, and a mesh made on several threads would differ in the last bits from
// one made on one. Moving such a parameter onto the knot makes both choose the upper span. The
// parameter moves by a few ulps; the surface point by as little.
#pragma once
#include <Precision.hxx>
#include <Standard_Real.hxx>
#include <TColStd_Array1OfReal.hxx>

#include <algorithm>
#include <cmath>
#include <vector>

namespace bisect::occ {

class KnotSnap {
 public:
  KnotSnap() = default;  // snaps nothing (no knots, or one span)
  // The flat knot sequence and degree the cache is built from (GeomAdaptor_* pass
  // UKnotSequence() / KnotSequence()).
  KnotSnap(const TColStd_Array1OfReal& flat, int degree, bool periodic) : periodic_(periodic) {
    first_ = flat.Value(flat.Lower() + degree);
    last_ = flat.Value(flat.Upper() - degree);
    for (int i = flat.Lower(); i <= flat.Upper(); ++i)
      if (knots_.empty() || flat.Value(i) > knots_.back()) knots_.push_back(flat.Value(i));
  }

  double operator()(double u) const {
    if (knots_.size() < 3) return u;  // one span: always the same polynomial
    if (periodic_) u = normalised(u);
    const auto k = std::lower_bound(knots_.begin(), knots_.end(), u);
    // wider than LocateParameter's window (Epsilon(min(|last knot|, |u|))) so as to cover it
    if (k != knots_.end() && *k > u && *k - u <= 4 * Epsilon(std::max(std::abs(*k), std::abs(u)))) return *k;
    return u;
  }

 private:
  // BSplCLib_CacheParams::PeriodicNormalization, operation for operation: the cache normalises
  // the parameter it is given the same way, so a snapped value stays put.
  double normalised(double u) const {
    const double period = last_ - first_;
    if (u < first_) return u + period * (std::trunc((first_ - u) / period) + 1.0);
    if (u > last_) return u - period * (std::trunc((u - last_) / period) + 1.0);
    return u;
  }

  std::vector<double> knots_;  // distinct, rising
  double first_ = 0, last_ = 0;
  bool periodic_ = false;
};

}  // namespace bisect::occ
